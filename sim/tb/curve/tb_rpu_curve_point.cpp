// rpu_curve_point against its twin (rpu::ref::curve_point_unit) on the real segments of
// scenes/curve12.json and scenes/polyline9.json (load_scene + compile_scene + quantize_scene at
// the verilated parameters): edge values of t per segment, then seeded random t over Q(3.FT)
// with g1, g2 from the guide unit's twin at that t (exact and pre-shifted square roots), and
// the X of every such item checked to fit the CW+3-bit port. Then random values over the full
// port range, where X may exceed CW+3 bits: compared modulo 2^(CW+3), which checks every
// internal product and floor.
#include <algorithm>
#include <string>
#include <vector>

#include "Vrpu_curve_point.h"
#include "tb_base.h"

#ifndef VECTORS
#define VECTORS 100000
#endif

namespace {

using sim::random_bits;

constexpr int kCW = COORD_W, kFT = T_FRAC, kFU = UNIT_FRAC;
constexpr int kTW = kFT + 3, kDW = kCW + 1, kUW = kFU + 2, kGW = kCW + 2, kXW = kCW + 3;

struct Op {
  ref::SegmentDesc seg;  // p1, d, guide[0].u, guide[1].u are used
  i128 t = 0, g1 = 0, g2 = 0;
  bool full_range = false;  // X compared modulo 2^XW
  ref::WVec3 x;             // the twin's
};

// Signed, spread over magnitudes (a random width 1..width), extremes included.
i128 random_value(std::mt19937_64& rng, int width) {
  switch (rng() % 16) {
    case 0: return fixed::max_signed(width);
    case 1: return fixed::min_signed(width);
    default: return sim::random_magnitude(rng, width);
  }
}
ref::IVec3 random_vec(std::mt19937_64& rng, int width) {
  return {static_cast<fixed::i64>(random_value(rng, width)),
          static_cast<fixed::i64>(random_value(rng, width)),
          static_cast<fixed::i64>(random_value(rng, width))};
}

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_curve_point> tb("tb_rpu_curve_point", argc, argv);
  auto& rng = tb.rng;
  const long random_count = tb.vectors(VECTORS);
  const ref::HwParams p = sim::tb_params();

  // ---- the scenes' segments ----
  std::vector<ref::SegmentDesc> segs;
  for (const char* name : {"curve12", "polyline9"}) {
    const scene::CompiledScene sc = sim::compiled_demo_scene(name);
    const ref::ModelScene m = ref::quantize_scene(sc, p);
    segs.insert(segs.end(), m.curve_segments.begin(), m.curve_segments.end());
    segs.insert(segs.end(), m.texture_segments.begin(), m.texture_segments.end());
  }
  // g from the guide unit's twin at weight w, with an exact or a pre-shifted square root.
  const auto guides = [&](const ref::SegmentDesc& s, i128 t_for_g, int sqrt_w, Op& op) {
    ref::HwParams pg = p;
    pg.sqrt_w = sqrt_w;
    const i128 w = ref::guide_weight(pg, t_for_g);
    fixed::Overflow ovf;
    op.g1 = ref::guide_unit(pg, s.guide[0], s.L2, w, ovf);
    op.g2 = ref::guide_unit(pg, s.guide[1], s.L2, w, ovf);
  };

  // ---- the operand list ----
  std::vector<Op> ops;
  const i128 one = i128{1} << kFT;
  for (const ref::SegmentDesc& s : segs)
    for (i128 t : {i128{0}, i128{1}, one / 2, one - 1, one, one + 1, i128{-1},
                   fixed::max_signed(kTW), fixed::min_signed(kTW)})
      for (int sw : {0, 40}) {
        Op op;
        op.seg = s;
        op.t = t;
        guides(s, t, sw, op);
        ops.push_back(op);
      }
  const long edge_count = static_cast<long>(ops.size());
  const int sqrt_ws[] = {0, 0, 0, 32, 40, 48};
  for (long k = 0; k < random_count; ++k) {
    Op op;
    op.seg = segs[rng() % segs.size()];
    op.t = sim::random_t(rng, kFT);
    const int sw = sqrt_ws[rng() % 6];
    if (rng() % 10 == 0) {  // g of another t in [0, 1] (t in [0, 1] too)
      op.t = random_bits(rng, kFT + 1) % (one + 1);
      guides(op.seg, random_bits(rng, kFT + 1) % (one + 1), sw, op);
    } else {
      guides(op.seg, op.t, sw, op);
    }
    ops.push_back(op);
  }
  const long full_count = std::max<long>(random_count / 10, 1000);
  for (long k = 0; k < full_count; ++k) {
    Op op;
    op.full_range = true;
    op.seg.p1 = random_vec(rng, kCW);
    op.seg.d = random_vec(rng, kDW);
    op.seg.guide[0].u = random_vec(rng, kUW);
    op.seg.guide[1].u = random_vec(rng, kUW);
    op.t = random_value(rng, kTW);
    op.g1 = random_value(rng, kGW);
    op.g2 = random_value(rng, kGW);
    ops.push_back(op);
  }

  // ---- the twin ----
  long wrapped = 0;
  i128 max_abs_x = 0;  // over the scene vectors
  for (Op& op : ops) {
    op.x = ref::curve_point_unit(p, op.seg, op.t, op.g1, op.g2);
    for (i128 c : {op.x.x, op.x.y, op.x.z}) {
      if (op.full_range) {
        wrapped += !fixed::fits_signed(c, kXW);
        continue;
      }
      if (!fixed::fits_signed(c, kXW))
        return tb.fail("the twin's X component %s does not fit CW+3 = %d bits (t %s g1 %s g2 %s)",
                       sim::str(c).c_str(), kXW, sim::str(op.t).c_str(), sim::str(op.g1).c_str(),
                       sim::str(op.g2).c_str());
      max_abs_x = std::max(max_abs_x, c < 0 ? -c : c);
    }
  }

  // The latency, as its header says: the products of t, of u, the sum.
  sim::Stream<Vrpu_curve_point, Op> s{.latency = ref::curve_point_latency(p)};
  s.inputs = [](sim::Inputs& in, Vrpu_curve_point& t, const Op& op) {
    in.vec("p1", t.p1_i, op.seg.p1, kCW).vec("d", t.d_i, op.seg.d, kDW);
    in.vec("u1", t.u1_i, op.seg.guide[0].u, kUW).vec("u2", t.u2_i, op.seg.guide[1].u, kUW);
    in("t", t.t_i, op.t, kTW)("g1", t.g1_i, op.g1, kGW)("g2", t.g2_i, op.g2, kGW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_curve_point& t, const Op& op) {
    if (op.full_range) o.modulo();  // the port's value modulo 2^XW
    o.vec("X", t.x_o, op.x, kXW);
  };
  s.what = [](const Op& op) { return op.full_range ? "full range, modulo 2^XW" : "scene"; };
  return tb.check(ops, s,
                  "CoordW=%d TFrac=%d UnitFrac=%d TagW=%d latency %ld; %zu segments: %ld edges + "
                  "%ld random scene items, max |X| = %.4f·2^CW; %ld full-range items modulo "
                  "2^(CW+3), %ld components beyond CW+3 bits", kCW, kFT, kFU, TAG_W, s.latency,
                  segs.size(), edge_count, random_count,
                  static_cast<double>(max_abs_x) / static_cast<double>(i128{1} << kCW), full_count,
                  wrapped);
}
