// rpu_sphere against its twin rpu::ref::sphere_unit, on inputs from the real scene compiler and
// the model's ray generator: curve12 — every (pixel, segment) pair with pred1 at full resolution
// and as many pairs without it from the 2-pixel grid (RPU_VECTORS sets that count; a count of at
// least the grid's misses drives every pair of the 2-pixel grid); pairs of random compiled scenes
// (eye outside and inside the spheres); range-edge vectors that saturate A/B and alpha/beta
// (tests/test_model.cpp Overflow.RangeEdgesSaturateAndFlag and an eye-at-a-corner sweep); format
// corners (eye, c0, v̂ at their extremes: the internal width bounds) and random vectors over the
// whole port range (radicand saturation, any inv_s). ellipse6 has no curve segment (skipped).
// Random valid gaps, junk on the data inputs between operands; latency and tag checked too.
// pred1, tc, half_chord and the overflow bit are compared always; A, B, AB, alpha and beta when
// pred1 holds (the model leaves them zero otherwise; the RTL's are don't-care).
#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <vector>

#include "Vrpu_sphere.h"
#include "common/error.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef DIR_FRAC
#define DIR_FRAC 24
#endif
#ifndef T_FRAC
#define T_FRAC 24
#endif
#ifndef INV_W
#define INV_W 18
#endif
#ifndef SQRT_W
#define SQRT_W 0
#endif
#ifndef TAG_W
#define TAG_W 8
#endif

namespace {

using namespace rpu;
using fixed::i64;
using fixed::u128;
using sim::i128;

ref::HwParams make_params() {
  ref::HwParams p;
  p.coord_w = COORD_W;
  p.dir_frac = DIR_FRAC;
  p.t_frac = T_FRAC;
  p.inv_w = INV_W;
  p.sqrt_w = SQRT_W;
  p.validate();
  return p;
}

const ref::HwParams kP = make_params();
const int CW = kP.coord_w, FV = kP.dir_frac, DirW = kP.dir_w(), DiffW = kP.diff_w();
const int R2W = 2 * CW + 1, TcW = CW + 4, HcW = CW + 3, TW = kP.t_w();
constexpr int kInvSW = 7;

enum Source { kCurve12, kRandomScene, kEdge, kCorner, kRandom, kSources };
const char* const kSourceName[kSources] = {"curve12", "random scene", "range edge",
                                           "format corner", "random port"};

// Segments live here (stable addresses); an item points at one.
std::deque<ref::SegmentDesc> g_segments;
const ref::SegmentDesc* keep(const ref::SegmentDesc& s) {
  g_segments.push_back(s);
  return &g_segments.back();
}

struct Item {
  Source src;
  int i = 0, j = 0, seg = 0;  // pixel and segment (scene sources), or vector index
  ref::IVec3 eye, vhat;
  const ref::SegmentDesc* s = nullptr;
};

struct Expected {
  ref::SearchInterval si;
  bool ovf = false;
};
Expected expected(const Item& it) {
  Expected e;
  fixed::Overflow ovf;
  e.si = ref::sphere_unit(kP, it.eye, it.vhat, *it.s, ovf);
  e.ovf = ovf.flag;
  return e;
}

// Packing {z, y, x} of `w`-bit components into a port, and back.
template <class P>
void put_vec(P& port, i128 x, i128 y, i128 z, int w) {
  const u128 m = fixed::max_unsigned(w);
  const u128 u = (static_cast<u128>(x) & m) | ((static_cast<u128>(y) & m) << w) |
                 ((static_cast<u128>(z) & m) << (2 * w));
  sim::put(port, static_cast<i128>(u), 3 * w);
}
template <class P>
ref::WVec3 get_vec(const P& port, int w) {
  const u128 u = sim::get_unsigned(port, 3 * w);
  const auto comp = [&](int k) {
    const u128 c = (u >> (k * w)) & fixed::max_unsigned(w), sign = u128{1} << (w - 1);
    return static_cast<i128>((c ^ sign) - sign);
  };
  return {comp(0), comp(1), comp(2)};
}

std::string str(i128 v) { return sim::to_string(v); }
std::string str(const ref::WVec3& v) {
  std::string s("(");  // appended piecewise (GCC 12 warns falsely on "(" + std::string)
  s += str(v.x);
  s += ", ";
  s += str(v.y);
  s += ", ";
  s += str(v.z);
  s += ")";
  return s;
}
std::string str(const ref::IVec3& v) { return str(ref::WVec3{v.x, v.y, v.z}); }

bool fits3(const ref::IVec3& v, int w) {
  return fixed::fits_signed(v.x, w) && fixed::fits_signed(v.y, w) && fixed::fits_signed(v.z, w);
}
// The item's inputs must be representable on the ports (every scene-derived value is).
bool fits_ports(const Item& it) {
  const ref::SegmentDesc& s = *it.s;
  return fits3(it.eye, CW) && fits3(it.vhat, DirW) && fits3(s.c0, CW) && fits3(s.p1, CW) &&
         fits3(s.d, DiffW) && s.R2 >= 0 && fixed::fits_unsigned(static_cast<u128>(s.R2), R2W) &&
         s.inv_m >= 0 && fixed::fits_unsigned(static_cast<u128>(s.inv_m), kP.inv_w) &&
         s.inv_s >= 0 && s.inv_s < (1 << kInvSW);
}

Item make_item(Source src, int i, int j, int seg, const ref::IVec3& eye, const ref::IVec3& vhat,
               const ref::SegmentDesc* s) {
  Item it;
  it.src = src;
  it.i = i;
  it.j = j;
  it.seg = seg;
  it.eye = eye;
  it.vhat = vhat;
  it.s = s;
  return it;
}

// The descriptor formula for 1/L² (descriptors.cpp).
void set_inverse(ref::SegmentDesc& s) {
  s.L2 = i128{s.d.x} * s.d.x + i128{s.d.y} * s.d.y + i128{s.d.z} * s.d.z;
  s.inv_s = kP.inv_w - 2 + fixed::bit_length(static_cast<u128>(s.L2));
  s.inv_m = static_cast<fixed::i64>(
      fixed::udiv(u128{1} << s.inv_s, static_cast<u128>(s.L2), kP.inv_w));
}

// A random scene: 1–2 curves of 3–10 points in [-1, 1]³, the eye outside or inside them.
scene::Scene random_scene(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  scene::Scene s;
  s.source = "<random scene " + std::to_string(n) + ">";
  Vec3 dir;
  do dir = {u(rng), u(rng), u(rng)};
  while (length(dir) < 0.2 || std::fabs(normalize(dir).z) > 0.85);
  const double dist = n % 3 == 0 ? 0.2 + 1.0 * u01(rng) : 2.5 + 5.0 * u01(rng);
  s.camera.eye = normalize(dir) * dist;
  s.camera.target = s.camera.eye - normalize(dir) * 2.0 + Vec3{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
  s.camera.up = {0, 0, 1};
  s.camera.fov_deg = 25.0 + 60.0 * u01(rng);
  s.camera.width = 40 + static_cast<int>(rng() % 100);
  s.camera.height = 40 + static_cast<int>(rng() % 100);
  const int curves = 1 + static_cast<int>(rng() % 2);
  for (int c = 0; c < curves; ++c) {
    scene::Curve cv;
    const int pts = 3 + static_cast<int>(rng() % 8);
    for (int k = 0; k < pts; ++k) cv.points.push_back({u(rng), u(rng), u(rng)});
    cv.closed = rng() % 2;
    s.curves.push_back(cv);
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_sphere");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_sphere>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_sphere");
  std::mt19937_64 rng(seed);
  const ref::HwParams& p = kP;
  const int rad_w = p.sphere_radicand_w();
  const long latency = ref::sphere_latency(p);

  std::vector<Item> items;

  // ---- curve12: every pair with pred1 (every pixel), and as many pairs without it from the
  // 2-pixel grid (RPU_VECTORS sets that count; at least the grid's misses drives every pair) ----
  {
    const scene::CompiledScene sc = scene::compile_scene(
        scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/curve12.json"));
    const ref::ModelScene m = ref::quantize_scene(sc, p);
    std::vector<const ref::SegmentDesc*> segs;
    for (const ref::SegmentDesc& s : m.curve_segments) segs.push_back(keep(s));
    struct Pair {
      int i, j, k;
    };
    std::vector<Pair> grid_hit, grid_miss, off_hit;
    for (int j = 0; j < m.camera.height; ++j)
      for (int i = 0; i < m.camera.width; ++i) {
        const bool on_grid = i % 2 == 0 && j % 2 == 0;
        const ref::RayGenOut ray = ref::ray_generator(p, m.camera, i, j);
        for (size_t k = 0; k < segs.size(); ++k) {
          fixed::Overflow ovf;
          const bool pred1 = ref::sphere_unit(p, m.camera.eye, ray.vhat, *segs[k], ovf).pred1;
          if (pred1 || on_grid)
            (!on_grid ? off_hit : pred1 ? grid_hit : grid_miss).push_back({i, j, static_cast<int>(k)});
        }
      }
    const long hits = static_cast<long>(grid_hit.size() + off_hit.size());
    const long n_miss = std::min<long>(static_cast<long>(grid_miss.size()), sim::vector_count(hits));
    std::shuffle(grid_miss.begin(), grid_miss.end(), rng);
    std::printf("curve12: %zu segments; 2-pixel grid: %zu pairs, %zu with pred1; other pixels: %zu "
                "pairs with pred1; driving every pair with pred1 and %ld of the grid's %zu without\n",
                segs.size(), grid_hit.size() + grid_miss.size(), grid_hit.size(), off_hit.size(),
                n_miss, grid_miss.size());
    grid_miss.resize(static_cast<size_t>(n_miss));
    for (const auto* list : {&grid_hit, &off_hit, &grid_miss})
      for (const Pair& pr : *list) {
        const ref::RayGenOut ray = ref::ray_generator(p, m.camera, pr.i, pr.j);
        items.push_back(make_item(kCurve12, pr.i, pr.j, pr.k, m.camera.eye, ray.vhat,
                                  segs[static_cast<size_t>(pr.k)]));
      }
  }

  // ---- ellipse6 has no curve segments: nothing for this unit ----
  {
    const scene::CompiledScene sc = scene::compile_scene(
        scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/ellipse6.json"));
    std::printf("ellipse6: %zu curve segments (skipped)\n", sc.curve_segments.size());
  }

  // ---- random compiled scenes ----
  {
    int scenes = 0, refused = 0;
    for (int n = 0; scenes < 24; ++n) {
      ref::ModelScene m;
      try {
        m = ref::quantize_scene(scene::compile_scene(random_scene(rng, n)), p);
      } catch (const std::exception&) {
        ++refused;  // degenerate geometry or a field of view too wide: draw another
        continue;
      }
      ++scenes;
      std::vector<const ref::SegmentDesc*> segs;
      for (const ref::SegmentDesc& s : m.curve_segments) segs.push_back(keep(s));
      int hits = 0, misses = 0;
      for (int tries = 0; tries < 60000 && (hits < 1500 || misses < 500); ++tries) {
        const int i = static_cast<int>(rng() % m.camera.width);
        const int j = static_cast<int>(rng() % m.camera.height);
        const int k = static_cast<int>(rng() % segs.size());
        const ref::RayGenOut ray = ref::ray_generator(p, m.camera, i, j);
        const Item it = make_item(kRandomScene, i, j, k, m.camera.eye, ray.vhat, segs[k]);
        if (expected(it).si.pred1 ? hits++ < 1500 : misses++ < 500) items.push_back(it);
      }
    }
    std::printf("random scenes: %d compiled (%d drawn scenes refused by the compiler)\n", scenes,
                refused);
  }

  // ---- range edges: the model test's vector, and an eye-at-a-corner sweep ----
  {
    const i64 top_c = (i64{1} << (CW - 1)) - 1, min_c = -(i64{1} << (CW - 1));
    const i64 one = i64{1} << FV;
    ref::SegmentDesc s;  // tests/test_model.cpp Overflow.RangeEdgesSaturateAndFlag, CW-scaled
    s.c0 = {top_c - 10, top_c - 10, top_c - 10};
    s.R2 = i128{1} << (2 * CW - 2);
    s.d = {i64{1} << (CW - 4), 0, 0};
    set_inverse(s);
    items.push_back(
        make_item(kEdge, 0, 0, 0, {top_c, top_c, top_c}, {one * 7 / 10, one * 7 / 10, 0}, keep(s)));
    int idx = 1;
    std::normal_distribution<double> g(0.0, 1.0);
    const i128 r2s[] = {static_cast<i128>(fixed::max_unsigned(R2W)), i128{1} << (2 * CW),
                        i128{1} << (2 * CW - 2),
                        i128{1} << CW, 100};
    for (int c = 0; c < 8; ++c) {
      const ref::IVec3 eye = {c & 1 ? top_c : min_c, c & 2 ? top_c : min_c, c & 4 ? top_c : min_c};
      for (int dn = 0; dn < 30; ++dn) {
        Vec3 u;
        if (dn < 6) u = {dn / 2 == 0 ? (dn % 2 ? 1.0 : -1.0) : 0.0, dn / 2 == 1 ? (dn % 2 ? 1.0 : -1.0) : 0.0,
                         dn / 2 == 2 ? (dn % 2 ? 1.0 : -1.0) : 0.0};
        else if (dn < 14) u = normalize(Vec3{dn & 1 ? 1.0 : -1.0, dn & 2 ? 1.0 : -1.0, dn & 4 ? 1.0 : -1.0});
        else u = normalize(Vec3{g(rng), g(rng), g(rng)});
        const ref::IVec3 vhat = {std::llround(std::ldexp(u.x, FV)), std::llround(std::ldexp(u.y, FV)),
                                 std::llround(std::ldexp(u.z, FV))};
        for (int cc = 0; cc < 3; ++cc) {
          ref::SegmentDesc t;
          // Centre: the same corner, the opposite corner, a random point.
          const auto rnd = [&] { return static_cast<i64>(rng() % (u128{1} << CW)) + min_c; };
          t.c0 = cc == 0 ? eye : cc == 1 ? ref::IVec3{-eye.x - 1, -eye.y - 1, -eye.z - 1}
                                         : ref::IVec3{rnd(), rnd(), rnd()};
          const auto rd = [&] { return static_cast<i64>(rng() % (u128{1} << CW)) - (i64{1} << (CW - 1)); };
          do t.d = {rd(), rd(), rd()};
          while (i128{t.d.x} * t.d.x + i128{t.d.y} * t.d.y + i128{t.d.z} * t.d.z < 64);
          t.p1 = {rnd(), rnd(), rnd()};
          set_inverse(t);
          for (i128 r2 : r2s) {
            t.R2 = r2;
            items.push_back(make_item(kEdge, idx++, 0, 0, eye, vhat, keep(t)));
          }
        }
      }
    }
  }

  // ---- format corners: eye, c0 and v̂ at their extremes (the width bounds of tc, disc, t) ----
  {
    const i64 top_c = (i64{1} << (CW - 1)) - 1, min_c = -(i64{1} << (CW - 1));
    const i64 vmax = (i64{1} << (DirW - 1)) - 1, vmin = -(i64{1} << (DirW - 1));
    const i64 dmax = (i64{1} << (DiffW - 1)) - 1, dmin = -(i64{1} << (DiffW - 1));
    int idx = 0;
    for (int e = 0; e < 8; ++e)
      for (int c = 0; c < 8; ++c)
        for (int v = 0; v < 27; ++v)
          for (int r = 0; r < 2; ++r) {
            const auto pick = [](int bit, i64 hi, i64 lo) { return bit ? hi : lo; };
            const i64 vs[3] = {vmax, vmin, 0};
            ref::SegmentDesc s;
            s.c0 = {pick(c & 1, top_c, min_c), pick(c & 2, top_c, min_c), pick(c & 4, top_c, min_c)};
            s.R2 = r ? static_cast<i128>(fixed::max_unsigned(R2W)) : 0;
            s.p1 = {pick(e & 2, min_c, top_c), pick(e & 4, min_c, top_c), pick(e & 1, min_c, top_c)};
            s.d = {pick(v & 1, dmax, dmin), pick(v & 2, dmin, dmax), pick(c & 2, dmax, dmin)};
            s.inv_m = static_cast<fixed::i64>(rng() % 2 ? fixed::max_unsigned(kP.inv_w)
                                                          : u128{1} << (kP.inv_w - 1));
            s.inv_s = static_cast<int>(rng() % (1 << kInvSW));
            const ref::IVec3 eye = {pick(e & 1, top_c, min_c), pick(e & 2, top_c, min_c),
                                    pick(e & 4, top_c, min_c)};
            const ref::IVec3 vhat = {vs[v % 3], vs[(v / 3) % 3], vs[v / 9]};
            items.push_back(make_item(kCorner, idx++, 0, 0, eye, vhat, keep(s)));
          }
  }

  // ---- random vectors over the whole port range (magnitudes spread by a random bit length) ----
  {
    // A uniform value of a random bit length b <= w: [-2^(b-1), 2^(b-1) - 1].
    const auto rnd_signed = [&](int w) {
      const int b = 1 + static_cast<int>(rng() % w);
      return static_cast<i64>(rng() & ((u128{1} << b) - 1)) - (i64{1} << (b - 1));
    };
    const long n = std::max<long>(20000, sim::vector_count(0) / 5);
    for (long k = 0; k < n; ++k) {
      ref::SegmentDesc s;
      s.c0 = {rnd_signed(CW), rnd_signed(CW), rnd_signed(CW)};
      s.p1 = {rnd_signed(CW), rnd_signed(CW), rnd_signed(CW)};
      s.d = {rnd_signed(DiffW), rnd_signed(DiffW), rnd_signed(DiffW)};
      s.R2 = static_cast<i128>(((static_cast<u128>(rng()) << 64) | rng()) &
                               fixed::max_unsigned(1 + static_cast<int>(rng() % R2W)));
      if (k % 2) {
        s.inv_m = static_cast<fixed::i64>(rng() & fixed::max_unsigned(kP.inv_w));
        s.inv_s = static_cast<int>(rng() % (1 << kInvSW));
      } else if (s.d.x || s.d.y || s.d.z) {
        set_inverse(s);
      }
      ref::IVec3 vhat = {rnd_signed(DirW), rnd_signed(DirW), rnd_signed(DirW)};
      if (k % 3 == 0) {  // a unit direction, as the ray generator makes
        std::normal_distribution<double> g(0.0, 1.0);
        const Vec3 u = normalize(Vec3{g(rng), g(rng), g(rng)});
        vhat = {std::llround(std::ldexp(u.x, FV)), std::llround(std::ldexp(u.y, FV)),
                std::llround(std::ldexp(u.z, FV))};
      }
      const ref::IVec3 eye = {rnd_signed(CW), rnd_signed(CW), rnd_signed(CW)};
      items.push_back(make_item(kRandom, static_cast<int>(k), 0, 0, eye, vhat, keep(s)));
    }
  }

  // ---- statistics of what is driven ----
  long per_src[kSources] = {}, per_src_hit[kSources] = {}, per_src_ovf[kSources] = {};
  long inside = 0, sat_rad = 0, sat_miss = 0, all_hits = 0;
  for (const Item& it : items) {
    if (!fits_ports(it)) {
      std::printf("FAILURE: a %s vector does not fit the ports (eye %s, vhat %s, R2 %s)\n",
                  kSourceName[it.src], str(it.eye).c_str(), str(it.vhat).c_str(), str(it.s->R2).c_str());
      return 1;
    }
    const Expected e = expected(it);
    const ref::SegmentDesc& sg = *it.s;
    ++per_src[it.src];
    per_src_hit[it.src] += e.si.pred1;
    per_src_ovf[it.src] += e.ovf;
    all_hits += e.si.pred1;
    inside += e.si.pred1 && e.si.tc < e.si.half_chord;
    const i128 disc = sg.R2 + e.si.tc * e.si.tc -
                      (i128{sg.c0.x - it.eye.x} * (sg.c0.x - it.eye.x) +
                       i128{sg.c0.y - it.eye.y} * (sg.c0.y - it.eye.y) +
                       i128{sg.c0.z - it.eye.z} * (sg.c0.z - it.eye.z));
    sat_rad += disc > static_cast<i128>(fixed::max_unsigned(rad_w));
    sat_miss += !e.si.pred1 && e.ovf;
  }
  for (int k = 0; k < kSources; ++k)
    std::printf("  %-14s %7ld vectors, %7ld with pred1, %6ld with overflow\n", kSourceName[k],
                per_src[k], per_src_hit[k], per_src_ovf[k]);
  std::printf("  t1 clamped to the eye (eye inside the sphere): %ld; radicand saturated: %ld "
              "(%ld of them flagged without pred1)\n", inside, sat_rad, sat_miss);

  // ---- drive and check ----
  std::shuffle(items.begin(), items.end(), rng);  // mix the sources
  sim::reset(*top, *ctx);
  struct Pending {
    size_t index;
    long cycle;
    std::uint32_t tag;
    Expected want;
  };
  std::deque<Pending> pending;
  const u128 tag_mask = fixed::max_unsigned(TAG_W);
  long matched = 0, cycle = 0;
  size_t next = 0;
  const long total = static_cast<long>(items.size());
  const auto junk = [&] { return static_cast<i128>((static_cast<u128>(rng()) << 64) | rng()); };
  while (matched < total) {
    const bool issue = next < items.size() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Item& it = items[next];
      const ref::SegmentDesc& sg = *it.s;
      put_vec(top->eye_i, it.eye.x, it.eye.y, it.eye.z, CW);
      put_vec(top->vhat_i, it.vhat.x, it.vhat.y, it.vhat.z, DirW);
      put_vec(top->c0_i, sg.c0.x, sg.c0.y, sg.c0.z, CW);
      sim::put(top->r2_i, sg.R2, R2W);
      put_vec(top->p1_i, sg.p1.x, sg.p1.y, sg.p1.z, CW);
      put_vec(top->d_i, sg.d.x, sg.d.y, sg.d.z, DiffW);
      sim::put(top->inv_m_i, sg.inv_m, kP.inv_w);
      sim::put(top->inv_s_i, sg.inv_s, kInvSW);
      const std::uint32_t tag = static_cast<std::uint32_t>(next & tag_mask);
      sim::put(top->tag_i, tag, TAG_W);
      pending.push_back({next, cycle, tag, expected(it)});
      ++next;
    } else {  // junk on the data inputs: nothing may depend on them
      put_vec(top->eye_i, junk(), junk(), junk(), CW);
      put_vec(top->vhat_i, junk(), junk(), junk(), DirW);
      put_vec(top->c0_i, junk(), junk(), junk(), CW);
      sim::put(top->r2_i, junk() & static_cast<i128>(fixed::max_unsigned(R2W)), R2W);
      put_vec(top->p1_i, junk(), junk(), junk(), CW);
      put_vec(top->d_i, junk(), junk(), junk(), DiffW);
      sim::put(top->inv_m_i, junk() & static_cast<i128>(fixed::max_unsigned(kP.inv_w)), kP.inv_w);
      sim::put(top->inv_s_i, junk() & 0x7F, kInvSW);
      sim::put(top->tag_i, junk() & static_cast<i128>(tag_mask), TAG_W);
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (pending.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Pending pd = pending.front();
      pending.pop_front();
      const Item& it = items[pd.index];
      const ref::SearchInterval& w = pd.want.si;
      const bool want_ovf = pd.want.ovf;
      ref::SearchInterval got;
      got.pred1 = top->pred1_o;
      got.tc = sim::get_signed(top->tc_o, TcW);
      got.half_chord = static_cast<i128>(sim::get_unsigned(top->half_chord_o, HcW));
      got.A = get_vec(top->a_o, CW);
      got.B = get_vec(top->b_o, CW);
      got.AB = get_vec(top->ab_o, DiffW);
      got.alpha = sim::get_signed(top->alpha_o, TW);
      got.beta = sim::get_signed(top->beta_o, TW);
      const bool got_ovf = top->ovf_o;
      const std::uint32_t got_tag = static_cast<std::uint32_t>(sim::get_unsigned(top->tag_o, TAG_W));
      const char* field = nullptr;
      if (cycle - pd.cycle != latency) field = "latency";
      else if (got_tag != pd.tag) field = "tag";
      else if (got.pred1 != w.pred1) field = "pred1";
      else if (got.tc != w.tc) field = "tc";
      else if (got.half_chord != w.half_chord) field = "half_chord";
      else if (got_ovf != want_ovf) field = "overflow";
      else if (w.pred1 && !(got.A == w.A)) field = "A";
      else if (w.pred1 && !(got.B == w.B)) field = "B";
      else if (w.pred1 && !(got.AB == w.AB)) field = "AB";
      else if (w.pred1 && got.alpha != w.alpha) field = "alpha";
      else if (w.pred1 && got.beta != w.beta) field = "beta";
      if (field) {
        std::printf("FAILURE cycle %ld item %zu (%s, pixel (%d, %d), segment %d): %s differs "
                    "(issued at cycle %ld, latency %ld expected %ld; tag %u expected %u)\n",
                    cycle, pd.index, kSourceName[it.src], it.i, it.j, it.seg, field, pd.cycle,
                    cycle - pd.cycle, latency, got_tag, pd.tag);
        std::printf("  inputs:   eye %s vhat %s c0 %s R2 %s p1 %s d %s inv_m %lld inv_s %d\n",
                    str(it.eye).c_str(), str(it.vhat).c_str(), str(it.s->c0).c_str(),
                    str(it.s->R2).c_str(), str(it.s->p1).c_str(), str(it.s->d).c_str(),
                    static_cast<long long>(it.s->inv_m), it.s->inv_s);
        for (int k = 0; k < 2; ++k) {
          const ref::SearchInterval& v = k == 0 ? w : got;
          std::printf("  %s pred1 %d tc %s half_chord %s A %s B %s AB %s alpha %s beta %s "
                      "overflow %d\n",
                      k == 0 ? "expected:" : "actual:  ", v.pred1, str(v.tc).c_str(),
                      str(v.half_chord).c_str(), str(v.A).c_str(), str(v.B).c_str(),
                      str(v.AB).c_str(), str(v.alpha).c_str(), str(v.beta).c_str(),
                      k == 0 ? want_ovf : got_ovf);
        }
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_sphere CoordW=%d DirFrac=%d TFrac=%d InvW=%d SqrtW=%d: latency %ld, matched %ld "
              "items (%ld with pred1) in %ld cycles\n",
              CW, FV, kP.t_frac, kP.inv_w, kP.sqrt_w, latency, matched, all_hits, cycle);
  return 0;
}
