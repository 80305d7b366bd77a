// rpu_texture against its twin rpu::ref::texture_unit on (p0, segment) pairs of the real scene
// compiler: scenes/ellipse6.json, scenes/polyline9.json and scenes/airfield.json quantised with
// HwParams (COORD_W / T_FRAC / UNIT_FRAC / INV_W / SQRT_W, defaults otherwise). p0 is the model's
// ray/plane point (rpu::ref::ray_plane_unit) of a real pixel's ray (rpu::ref::ray_generator):
// mostly pixels at or beside the projection of a point within about two half widths of a texture
// curve (many covers = 1 and many pr1 ∧ ¬pr3 just outside the stroke), the rest random pixels.
// The segments of each p0: every one the classification grid lists there (the renderer's pairs,
// its grid grown by 2 LSB as in ref_renderer), one from a neighbouring grid cell and one random
// segment of the scene. A few percent of the pairs take p0 at random over the whole coordinate
// range (the clamp of (p0 − p1)·d at both ends, the widest products); 1 % also give p0 a non-zero
// z (the port takes it; the twin uses it); 2 % edit a descriptor field to its port limit with p0
// near the segment (an arc guide with the largest h: its radicand saturates and sets the overflow
// bit; inv_s too small: t̂ saturates; w0_2 = 0 and its maximum; a flat guide); 3 % put p0 exactly
// on (or one LSB off) an end plane and w0_2 exactly at (or one off) |p0 − p1|², |p0 − p2|² or
// |X − p0|²: the equality cases of every comparison (a quarter of them with p0 far along the
// plane and w0_2 at |X − p0|²; a third of them with the axes rotated so that z carries data).
// RPU_VECTORS sets the pair count (default 100,000). pr1, pr2, pr3, covers, t̂, X, the overflow
// bit, the tag and the latency compared for every pair.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "Vrpu_texture.h"
#include "scene/classification_grid.h"
#include "scene/segment.h"
#include "tb_base.h"
#include "tb_guide.h"

namespace {

constexpr int kCw = COORD_W, kFt = T_FRAC;
constexpr int kTw = kFt + 3, kDw = kCw + 1, kHw = kCw + 5;
constexpr int kL2w = 2 * kCw + 3, kXw = kCw + 3, kW02w = 2 * kCw + 1, kInvW = INV_W;

struct Scene {
  std::string name;
  scene::CompiledScene sc;
  ref::ModelScene m;
  scene::ClassificationGrid grid;
};

const char* const kScenes[] = {"ellipse6", "polyline9", "airfield"};
enum Source { kGrid, kNeighbour, kRandomSeg, kRandomP0, kRandomZ, kPortEdge, kExact };
const char* const kSourceName[] = {"grid",      "grid neighbour",   "random segment",
                                   "random p0", "random p0 with z", "descriptor edge",
                                   "exact boundary"};

struct Item {
  int scene;
  size_t seg;
  ref::SegmentDesc desc;  // the segment's descriptor (edited for the descriptor-edge vectors)
  int i, j;
  Source source;
  ref::WVec3 p0;
  ref::TextureOut want;
  bool ovf;
};

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_texture> tb("tb_rpu_texture", argc, argv);
  auto& rng = tb.rng;
  const ref::HwParams p = sim::tb_params();

  std::vector<Scene> scenes;
  for (const char* name : kScenes) {
    Scene s;
    s.name = name;
    s.sc = sim::compiled_demo_scene(name);
    s.m = ref::quantize_scene(s.sc, p);
    s.grid = scene::ClassificationGrid::build(s.sc.texture_segments, 2.0, 2.0 / s.m.norm.scale);
    for (const ref::SegmentDesc& d : s.m.texture_segments)
      if (d.w0_2 < 0 || d.w0_2 > static_cast<i128>(fixed::max_unsigned(kW02w)))
        return tb.fail("%s: w0_2 = %s does not fit %d bits", name, sim::str(d.w0_2).c_str(), kW02w);
    scenes.push_back(std::move(s));
  }

  const long count = tb.vectors(100000);
  std::vector<Item> items;
  const auto add_desc = [&](int k, size_t seg, const ref::SegmentDesc& s, int i, int j,
                            Source src, const ref::WVec3& p0) {
    fixed::Overflow ovf;
    // Every other pair with a round join (the same geometry, the other covering rule).
    ref::SegmentDesc joined = s;
    joined.round_join = items.size() % 2 == 1;
    Item it{k, seg, joined, i, j, src, p0, ref::texture_unit(p, joined, p0, ovf), false};
    it.ovf = ovf.flag;
    items.push_back(it);
  };
  const auto add = [&](int k, size_t seg, int i, int j, Source src, const ref::WVec3& p0) {
    add_desc(k, seg, scenes[static_cast<size_t>(k)].m.texture_segments[seg], i, j, src, p0);
  };
  while (static_cast<long>(items.size()) < count) {
    const int k = static_cast<int>(rng() % scenes.size());
    const Scene& S = scenes[static_cast<size_t>(k)];
    const size_t nseg = S.m.texture_segments.size();
    const unsigned kind = static_cast<unsigned>(rng() % 100);
    if (kind < 4) {  // p0 anywhere in the coordinate range (z = 0; 1 % with a z as well)
      const ref::WVec3 p0{sim::random_signed(rng, kCw), sim::random_signed(rng, kCw),
                          kind == 0 ? sim::random_signed(rng, kCw) : 0};
      add(k, rng() % nseg, -1, -1, kind == 0 ? kRandomZ : kRandomP0, p0);
      continue;
    }
    if (kind < 6) {
      // Descriptor fields at their port limits, p0 near the segment: an arc guide with the
      // largest h (its radicand saturates: the overflow bit), inv_s below the descriptor's
      // (t̂ saturates), w0_2 at 0 and at its maximum.
      const size_t seg = rng() % nseg;
      ref::SegmentDesc s = S.m.texture_segments[seg];
      const double u = sim::uniform(rng, -0.05, 1.05);
      const i128 reach = 2 * static_cast<i128>(std::sqrt(static_cast<double>(s.w0_2))) + 2;
      const auto near = [&](fixed::i64 p1, fixed::i64 d) {
        return static_cast<i128>(p1) + static_cast<i128>(std::floor(static_cast<double>(d) * u)) +
               static_cast<i128>(rng() % static_cast<u128>(2 * reach + 1)) - reach;
      };
      const ref::WVec3 p0{near(s.p1.x, s.d.x), near(s.p1.y, s.d.y), 0};
      switch (rng() % 6) {
        case 5: {
          // A flat guide as the descriptor compiler quantises one of height h beyond
          // kFlatRatio·L (a = L²/2h, b = L²/4h² in Q(0.FT)): h from the threshold to 2^6 times it.
          ref::GuideDesc& g = s.guide[rng() % 2];
          const double L = std::sqrt(static_cast<double>(s.L2));
          const double x = sim::uniform(rng, 0, 1);
          const double h = L * ref::HwParams::kFlatRatio *
                           (1.0 + 1e-6 + std::ldexp(x, static_cast<int>(rng() % 7)));
          sim::set_flat_guide(g, s.L2, h, kFt);
          break;
        }
        case 0:
        case 1: {
          ref::GuideDesc& g = s.guide[rng() % 2];
          g.mode = ref::GuideMode::kArc;
          g.h = (fixed::i64{1} << kHw) - 1;
          break;
        }
        case 2: s.inv_s = static_cast<int>(rng() % static_cast<unsigned>(s.inv_s)); break;
        case 3: s.w0_2 = 0; break;
        default: s.w0_2 = static_cast<i128>(fixed::max_unsigned(kW02w)); break;
      }
      const i128 lim = fixed::max_signed(kCw);
      if (std::abs(static_cast<double>(p0.x)) <= static_cast<double>(lim) &&
          std::abs(static_cast<double>(p0.y)) <= static_cast<double>(lim))
        add_desc(k, seg, s, -1, -1, kPortEdge, p0);
      continue;
    }
    if (kind < 9) {
      // Exact boundaries: p0 on (or one LSB off) the plane through p1 or p2 perpendicular to d
      // ((p0 − p1)·d = 0 or (p0 − p2)·d = 0: pr1's comparisons and the clamp's ends), and w0_2
      // equal to |p0 − p1|², |p0 − p2|² or |X − p0|², or one off (pr2's and pr3's ≤).
      const size_t seg = rng() % nseg;
      ref::SegmentDesc s = S.m.texture_segments[seg];
      const fixed::i64 g = std::gcd(std::abs(s.d.x), std::abs(s.d.y));
      const fixed::i64 sx = -s.d.y / g, sy = s.d.x / g;  // d rotated by 90°, made primitive
      const double step = std::hypot(static_cast<double>(sx), static_cast<double>(sy));
      // A quarter of them far along the plane (|p0 − X| up to 2^(CW−2)): w0_2 = |X − p0|² then
      // tests pr3's comparison and |e|²'s high bits.
      const bool far = rng() % 4 == 0;
      const auto m_max =
          far ? static_cast<fixed::i64>(std::ldexp(1.0, kCw) / step) + 1
              : static_cast<fixed::i64>(3.0 * std::sqrt(static_cast<double>(s.w0_2)) / step) + 1;
      const fixed::i64 m = static_cast<fixed::i64>(rng() % static_cast<std::uint64_t>(2 * m_max + 1)) - m_max;
      const bool at_p2 = rng() % 2;
      const int off = static_cast<int>(rng() % 5);  // 0..1: on the plane; else ±1 LSB in x or y
      ref::WVec3 p0{s.p1.x + (at_p2 ? s.d.x : 0) + m * sx, s.p1.y + (at_p2 ? s.d.y : 0) + m * sy, 0};
      if (off == 2) p0.x += 1;
      if (off == 3) p0.x -= 1;
      if (off == 4) p0.y += rng() % 2 ? 1 : -1;
      const i128 lim = fixed::max_signed(kCw);
      if (p0.x > lim || p0.x < -lim - 1 || p0.y > lim || p0.y < -lim - 1) continue;
      const ref::WVec3 r1{p0.x - s.p1.x, p0.y - s.p1.y, p0.z - s.p1.z};
      const ref::WVec3 r2{r1.x - s.d.x, r1.y - s.d.y, r1.z - s.d.z};
      fixed::Overflow unused;
      const ref::WVec3 X = ref::texture_unit(p, s, p0, unused).X;
      const ref::WVec3 e{X.x - p0.x, X.y - p0.y, X.z - p0.z};
      const i128 cand[] = {r1.x * r1.x + r1.y * r1.y + r1.z * r1.z,
                           r2.x * r2.x + r2.y * r2.y + r2.z * r2.z,
                           e.x * e.x + e.y * e.y + e.z * e.z};
      // 3: keep the scene's w0_2; far: always |X − p0|²
      const unsigned pick = far ? 2 : static_cast<unsigned>(rng() % 4);
      if (pick < 3) {
        const i128 w = cand[pick] + static_cast<i128>(rng() % 3) - 1;
        if (w >= 0 && w <= static_cast<i128>(fixed::max_unsigned(kW02w))) s.w0_2 = w;
      }
      if (rng() % 3 == 0) {
        // The axes rotated, (x, y, z) -> (z, x, y), for p0, p1, d and the guide units: every
        // dot product and |·|² (the boundaries above) is unchanged, but d_z, r1_z, r2_z, X_z and
        // (X − p0)_z become non-zero (the scenes are flat: z = 0 otherwise).
        const auto rot = [](auto& v) { v = {v.z, v.x, v.y}; };
        rot(p0);
        rot(s.p1);
        rot(s.d);
        rot(s.c0);
        rot(s.guide[0].u);
        rot(s.guide[1].u);
      }
      add_desc(k, seg, s, -1, -1, kExact, p0);
      continue;
    }
    const ref::CameraDesc& cam = S.m.camera;
    int i = static_cast<int>(rng() % static_cast<unsigned>(cam.width));
    int j = static_cast<int>(rng() % static_cast<unsigned>(cam.height));
    if (kind < 80) {
      // A point within about two half widths of a texture curve, its pixel or a neighbour.
      const scene::CompiledSegment& cs = S.sc.texture_segments[rng() % nseg];
      const double u = sim::uniform(rng, 0, 1);
      const Vec3 c = scene::curve_point(cs.geom, u);
      const Vec3 tan = scene::curve_point(cs.geom, std::min(1.0, u + 1e-3)) -
                       scene::curve_point(cs.geom, std::max(0.0, u - 1e-3));
      const Vec3 n = normalize(Vec3{-tan.y, tan.x, 0.0});
      const double off = sim::uniform(rng, -2.2, 2.2) * cs.half_width;
      int ci, cj;
      if (!scene::project_to_pixel(S.sc.camera, c + n * off, ci, cj)) continue;
      i = std::clamp(ci + static_cast<int>(rng() % 3) - 1, 0, cam.width - 1);
      j = std::clamp(cj + static_cast<int>(rng() % 3) - 1, 0, cam.height - 1);
    }
    const ref::RayGenOut ray = ref::ray_generator(p, cam, i, j);
    const ref::PlanePoint pp = ref::ray_plane_unit(p, cam, ray.vhat);
    if (!pp.valid) continue;
    const double x = static_cast<double>(pp.p0.x) / S.m.norm.scale + S.m.norm.offset.x;
    const double y = static_cast<double>(pp.p0.y) / S.m.norm.scale + S.m.norm.offset.y;
    for (auto seg : S.grid.lookup(x, y)) add(k, seg, i, j, kGrid, pp.p0);
    const double cell = S.grid.cell_size();
    const int di = static_cast<int>(rng() % 3) - 1, dj = static_cast<int>(rng() % 3) - 1;
    const auto near = S.grid.lookup(x + di * cell, y + dj * cell);
    if (near.size() > 0) add(k, near.begin()[rng() % near.size()], i, j, kNeighbour, pp.p0);
    add(k, rng() % nseg, i, j, kRandomSeg, pp.p0);
  }

  // What the vectors exercise.
  sim::Tally by_src(kSourceName, {"pairs", "covers", "pr1", "pr2", "pr3", "pr1 ∧ ¬pr3"});
  sim::Tally by_scene(kScenes, {"pairs"});
  long n_edge_out = 0, n_edge_in = 0, n_ovf = 0, n_clamp_lo = 0, n_clamp_hi = 0, n_plane_eq = 0,
       n_w0_eq = 0, n_round_cap = 0;
  for (const Item& it : items) {
    const ref::TextureOut& w = it.want;
    const ref::SegmentDesc& s = it.desc;
    const ref::WVec3 e{w.X.x - it.p0.x, w.X.y - it.p0.y, w.X.z - it.p0.z};
    const i128 e2 = e.x * e.x + e.y * e.y + e.z * e.z;
    by_src.add(it.source, 1, w.covers, w.pr1, w.pr2, w.pr3, w.pr1 && !w.pr3);
    by_scene.add(it.scene, 1);
    n_edge_out += w.pr1 && !w.pr3 && e2 <= 4 * s.w0_2;  // just outside the stroke
    n_edge_in += w.pr1 && w.pr3 && 4 * e2 >= s.w0_2;     // just inside it
    n_round_cap += s.round_join && w.pr2 && !w.pr1;      // a cap outside the slab: the join
    n_ovf += it.ovf;
    const ref::WVec3 r1{it.p0.x - s.p1.x, it.p0.y - s.p1.y, it.p0.z - s.p1.z};
    const i128 f1 = r1.x * s.d.x + r1.y * s.d.y + r1.z * s.d.z;
    n_clamp_lo += f1 < 0;
    n_clamp_hi += f1 > s.L2;
    n_plane_eq += f1 == 0 || f1 == s.L2;  // r1·d = 0 or r2·d = r1·d − L2 = 0
    const ref::WVec3 r2{r1.x - s.d.x, r1.y - s.d.y, r1.z - s.d.z};
    n_w0_eq += r1.x * r1.x + r1.y * r1.y + r1.z * r1.z == s.w0_2 ||
               r2.x * r2.x + r2.y * r2.y + r2.z * r2.z == s.w0_2 || e2 == s.w0_2;
  }
  const long n_covers = by_src.total(1);
  if (n_covers < count / 20 || n_edge_out < count / 50 || n_clamp_lo == 0 || n_clamp_hi == 0 ||
      n_ovf == 0 || n_plane_eq == 0 || n_w0_eq == 0 || n_round_cap < count / 1000) {
    return tb.fail("the vectors are too weak: %ld covers, %ld pr1 ∧ ¬pr3 near the edge, %ld / "
                   "%ld clamped low / high, %ld overflows, %ld / %ld equality cases, %ld round "
                   "caps outside the slab of %zu",
                   n_covers, n_edge_out, n_clamp_lo, n_clamp_hi, n_ovf, n_plane_eq, n_w0_eq,
                   n_round_cap, items.size());
  }

  sim::Stream<Vrpu_texture, Item> s{.latency = ref::texture_latency(p)};
  s.inputs = [](sim::Inputs& in, Vrpu_texture& t, const Item& it) {
    const ref::SegmentDesc& d = it.desc;
    in.vec("p0", t.p0_i, it.p0, kCw).vec("p1", t.p1_i, d.p1, kCw).vec("d", t.d_i, d.d, kDw);
    in("L2", t.l2_i, d.L2, kL2w)("inv_m", t.inv_m_i, d.inv_m, kInvW)("inv_s", t.inv_s_i, d.inv_s, 7);
    for (int k = 0; k < 2; ++k) {
      sim::guide_input(in, k ? "g2" : "g1", k ? t.g2_i : t.g1_i, sim::tb_params(), d.guide[k]);
    }
    in("w0_2", t.w0_2_i, d.w0_2, kW02w)("round_join", t.round_join_i, d.round_join ? 1 : 0, 1);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_texture& t, const Item& it) {
    const ref::TextureOut& w = it.want;
    o("pr1", t.pr1_o, w.pr1, 1)("pr2", t.pr2_o, w.pr2, 1)("pr3", t.pr3_o, w.pr3, 1);
    o("covers", t.covers_o, w.covers, 1).s("t", t.t_o, w.t, kTw).vec("X", t.x_o, w.X, kXw);
    o("ovf", t.ovf_o, it.ovf, 1);
  };
  s.what = [&](const Item& it) {
    return scenes[static_cast<size_t>(it.scene)].name + " segment " + std::to_string(it.seg) + " (" +
           kSourceName[it.source] + "), pixel (" + std::to_string(it.i) + ", " + std::to_string(it.j) + ")";
  };
  if (!tb.run(items, s)) return 1;
  by_scene.print("per scene");
  by_src.print("per source of (p0, segment)");
  std::printf("  pr1 ∧ ¬pr3 within 2·w0 of X %ld, pr3 with |X − p0| ≥ w0/2 %ld, (p0 − p1)·d "
              "clamped low %ld / high %ld, ovf %ld\n  equal: (p0 − p1)·d ∈ {0, L2} %ld, w0_2 ∈ "
              "{|r1|², |r2|², |X − p0|²} %ld\n", n_edge_out, n_edge_in, n_clamp_lo, n_clamp_hi,
              n_ovf, n_plane_eq, n_w0_eq);
  return tb.pass("CoordW=%d TFrac=%d UnitFrac=%d InvW=%d SqrtW=%d latency %ld", kCw, kFt, UNIT_FRAC,
                 kInvW, SQRT_W, s.latency);
}
