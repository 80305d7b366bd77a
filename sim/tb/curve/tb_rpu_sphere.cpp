// rpu_sphere against its twin rpu::ref::sphere_unit, on inputs from the real scene compiler and
// the model's ray generator: curve12 — every (pixel, segment) pair with pred1 at full resolution
// and as many pairs without it from the 2-pixel grid (RPU_VECTORS sets that count; a count of at
// least the grid's misses drives every pair of the 2-pixel grid); pairs of random compiled scenes
// (eye outside and inside the spheres); range-edge vectors that saturate A/B and alpha/beta
// (tests/test_model.cpp Overflow.RangeEdgesSaturateAndFlag and an eye-at-a-corner sweep); format
// corners (eye, c0, v̂ at their extremes: the internal width bounds) and random vectors over the
// whole port range (radicand saturation, any inv_s). ellipse6 has no curve segment (skipped).
// pred1, tc, half_chord and the overflow bit are compared always; A, B, AB, alpha and beta when
// pred1 holds (the model leaves them zero otherwise; the RTL's are don't-care).
#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

#include "Vrpu_sphere.h"
#include "tb_base.h"

namespace {

using fixed::i64;

const ref::HwParams kP = sim::tb_params();
const int CW = kP.coord_w, FV = kP.dir_frac, DirW = kP.dir_w(), DiffW = kP.diff_w();
const int R2W = kP.r2_w(), TcW = CW + 4, HcW = CW + 3, TW = kP.t_w();
const i64 kTopC = (i64{1} << (CW - 1)) - 1, kMinC = -(i64{1} << (CW - 1));  // CW's ends
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

struct Expected {
  ref::SearchInterval si;
  bool ovf = false;
};
struct Item {
  Source src;
  int i, j, seg;  // pixel and segment (scene sources), or vector index
  ref::IVec3 eye, vhat;
  const ref::SegmentDesc* s;
  Expected want = {};
};

Expected expected(const Item& it) {
  Expected e;
  fixed::Overflow ovf;
  e.si = ref::sphere_unit(kP, it.eye, it.vhat, *it.s, ovf);
  e.ovf = ovf.flag;
  return e;
}

// The item's inputs must be representable on the ports (every scene-derived value is).
bool fits_ports(const Item& it) {
  const ref::SegmentDesc& s = *it.s;
  using sim::fits_signed3;
  return fits_signed3(it.eye, CW) && fits_signed3(it.vhat, DirW) && fits_signed3(s.c0, CW) &&
         fits_signed3(s.p1, CW) && fits_signed3(s.d, DiffW) && sim::fits_unsigned(s.R2, R2W) &&
         sim::fits_unsigned(s.inv_m, kP.inv_w) && s.inv_s >= 0 && s.inv_s < (1 << kInvSW);
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
  sim::Testbench<Vrpu_sphere> tb("tb_rpu_sphere", argc, argv);
  auto& rng = tb.rng;
  const ref::HwParams& p = kP;
  const int rad_w = p.sphere_radicand_w();

  std::vector<Item> items;

  // ---- curve12: every pair with pred1 (every pixel), and as many pairs without it from the
  // 2-pixel grid (RPU_VECTORS sets that count; at least the grid's misses drives every pair) ----
  {
    const scene::CompiledScene sc = sim::compiled_demo_scene("curve12");
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
    const long n_miss = std::min<long>(static_cast<long>(grid_miss.size()), tb.vectors(hits));
    std::shuffle(grid_miss.begin(), grid_miss.end(), rng);
    std::printf("curve12: %zu segments; 2-pixel grid: %zu pairs, %zu with pred1; other pixels: %zu "
                "pairs with pred1; driving every pair with pred1 and %ld of the grid's %zu without\n",
                segs.size(), grid_hit.size() + grid_miss.size(), grid_hit.size(), off_hit.size(),
                n_miss, grid_miss.size());
    grid_miss.resize(static_cast<size_t>(n_miss));
    for (const auto* list : {&grid_hit, &off_hit, &grid_miss})
      for (const Pair& pr : *list) {
        const ref::RayGenOut ray = ref::ray_generator(p, m.camera, pr.i, pr.j);
        items.push_back(Item{kCurve12, pr.i, pr.j, pr.k, m.camera.eye, ray.vhat,
                             segs[static_cast<size_t>(pr.k)]});
      }
  }

  // ---- ellipse6 has no curve segments: nothing for this unit ----
  std::printf("ellipse6: %zu curve segments (skipped)\n",
              sim::compiled_demo_scene("ellipse6").curve_segments.size());

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
        const Item it{kRandomScene, i, j, k, m.camera.eye, ray.vhat, segs[k]};
        if (expected(it).si.pred1 ? hits++ < 1500 : misses++ < 500) items.push_back(it);
      }
    }
    std::printf("random scenes: %d compiled (%d drawn scenes refused by the compiler)\n", scenes,
                refused);
  }

  // ---- range edges: the model test's vector, and an eye-at-a-corner sweep ----
  {
    const i64 top_c = kTopC, min_c = kMinC, one = i64{1} << FV;
    ref::SegmentDesc s;  // tests/test_model.cpp Overflow.RangeEdgesSaturateAndFlag, CW-scaled
    s.c0 = {top_c - 10, top_c - 10, top_c - 10};
    s.R2 = i128{1} << (2 * CW - 2);
    s.d = {i64{1} << (CW - 4), 0, 0};
    set_inverse(s);
    items.push_back(
        Item{kEdge, 0, 0, 0, {top_c, top_c, top_c}, {one * 7 / 10, one * 7 / 10, 0}, keep(s)});
    int idx = 1;
    const i128 r2s[] = {static_cast<i128>(fixed::max_unsigned(R2W)), i128{1} << (2 * CW),
                        i128{1} << (2 * CW - 2), i128{1} << CW, 100};
    for (int c = 0; c < 8; ++c) {
      const ref::IVec3 eye = {c & 1 ? top_c : min_c, c & 2 ? top_c : min_c, c & 4 ? top_c : min_c};
      for (int dn = 0; dn < 30; ++dn) {
        Vec3 u;
        if (dn < 6) u = {dn / 2 == 0 ? (dn % 2 ? 1.0 : -1.0) : 0.0, dn / 2 == 1 ? (dn % 2 ? 1.0 : -1.0) : 0.0,
                         dn / 2 == 2 ? (dn % 2 ? 1.0 : -1.0) : 0.0};
        else if (dn < 14) u = normalize(Vec3{dn & 1 ? 1.0 : -1.0, dn & 2 ? 1.0 : -1.0, dn & 4 ? 1.0 : -1.0});
        else u = sim::random_unit(rng);
        const ref::IVec3 vhat = sim::quantise_dir(kP, u);
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
            items.push_back(Item{kEdge, idx++, 0, 0, eye, vhat, keep(t)});
          }
        }
      }
    }
  }

  // ---- format corners: eye, c0 and v̂ at their extremes (the width bounds of tc, disc, t) ----
  {
    const i64 top_c = kTopC, min_c = kMinC;
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
            items.push_back(Item{kCorner, idx++, 0, 0, eye, vhat, keep(s)});
          }
  }

  // ---- random vectors over the whole port range (magnitudes spread by a random bit length) ----
  {
    // A uniform value of a random bit length b <= w: [-2^(b-1), 2^(b-1) - 1].
    const auto rnd_signed = [&](int w) {
      const int b = 1 + static_cast<int>(rng() % w);
      return static_cast<i64>(rng() & ((u128{1} << b) - 1)) - (i64{1} << (b - 1));
    };
    const long n = std::max<long>(20000, tb.vectors(0) / 5);
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
      if (k % 3 == 0) vhat = sim::quantise_dir(kP, sim::random_unit(rng));  // as the ray generator
      const ref::IVec3 eye = {rnd_signed(CW), rnd_signed(CW), rnd_signed(CW)};
      items.push_back(Item{kRandom, static_cast<int>(k), 0, 0, eye, vhat, keep(s)});
    }
  }

  // ---- statistics of what is driven ----
  sim::Tally by_src(kSourceName, {"vectors", "with pred1", "with overflow"});
  long inside = 0, sat_rad = 0, sat_miss = 0, all_hits = 0;
  for (Item& it : items) {
    if (!fits_ports(it))
      return tb.fail("a %s vector does not fit the ports (eye %s, vhat %s, R2 %s)",
                     kSourceName[it.src], sim::str(it.eye).c_str(), sim::str(it.vhat).c_str(),
                     sim::str(it.s->R2).c_str());
    const Expected e = it.want = expected(it);
    const ref::SegmentDesc& sg = *it.s;
    by_src.add(it.src, 1, e.si.pred1, e.ovf);
    all_hits += e.si.pred1;
    inside += e.si.pred1 && e.si.tc < e.si.half_chord;
    const i128 disc = sg.R2 + e.si.tc * e.si.tc -
                      (i128{sg.c0.x - it.eye.x} * (sg.c0.x - it.eye.x) +
                       i128{sg.c0.y - it.eye.y} * (sg.c0.y - it.eye.y) +
                       i128{sg.c0.z - it.eye.z} * (sg.c0.z - it.eye.z));
    sat_rad += disc > static_cast<i128>(fixed::max_unsigned(rad_w));
    sat_miss += !e.si.pred1 && e.ovf;
  }
  by_src.print("per source");
  std::printf("  t1 clamped to the eye (eye inside the sphere): %ld; radicand saturated: %ld "
              "(%ld of them flagged without pred1)\n", inside, sat_rad, sat_miss);

  std::shuffle(items.begin(), items.end(), rng);  // mix the sources

  sim::Stream<Vrpu_sphere, Item> s{.latency = ref::sphere_latency(p)};
  s.inputs = [&](sim::Inputs& in, Vrpu_sphere& t, const Item& it) {
    const ref::SegmentDesc& sg = *it.s;
    in.vec("eye", t.eye_i, it.eye, CW).vec("vhat", t.vhat_i, it.vhat, DirW).vec("c0", t.c0_i, sg.c0, CW);
    in("R2", t.r2_i, sg.R2, R2W).vec("p1", t.p1_i, sg.p1, CW).vec("d", t.d_i, sg.d, DiffW);
    in("inv_m", t.inv_m_i, sg.inv_m, kP.inv_w)("inv_s", t.inv_s_i, sg.inv_s, kInvSW);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_sphere& t, const Item& it) {
    const ref::SearchInterval& w = it.want.si;
    o("pred1", t.pred1_o, w.pred1, 1).s("tc", t.tc_o, w.tc, TcW);
    o("half_chord", t.half_chord_o, w.half_chord, HcW)("overflow", t.ovf_o, it.want.ovf, 1);
    o.vec("A", t.a_o, w.A, CW, w.pred1).vec("B", t.b_o, w.B, CW, w.pred1);
    o.vec("AB", t.ab_o, w.AB, DiffW, w.pred1).s("alpha", t.alpha_o, w.alpha, TW, w.pred1);
    o.s("beta", t.beta_o, w.beta, TW, w.pred1);
  };
  s.what = [](const Item& it) {
    return std::string(kSourceName[it.src]) + ", pixel (" + std::to_string(it.i) + ", " +
           std::to_string(it.j) + "), segment " + std::to_string(it.seg);
  };
  return tb.check(items, s,
                  "CoordW=%d DirFrac=%d TFrac=%d InvW=%d SqrtW=%d, latency %ld, %ld with pred1", CW,
                  FV, kP.t_frac, kP.inv_w, kP.sqrt_w, s.latency, all_hits);
}
