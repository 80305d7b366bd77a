// rpu_guide_pair against its twin (rpu::ref::guide_pair: guide_weight, then guide_unit for each
// guide): edge values (every pair of modes at every edge t), then seeded random pairs of guides
// of one segment built like tests/test_model.cpp GuideUnit.ArcAndFlatWithinBound (arc and flat,
// h from 0.01 L to 1000 L, L from 2^8 up to 2^CW) and straight ones, with t over the whole
// Q(3.FT) range (w clamps outside [0, 1]), plus random values over the full port range (mode
// code 3, saturating radicands). With HhIn = 1 the h² ports carry h² (the caller's contract);
// with HhIn = 0 they carry junk, which must not matter.
#include <cmath>
#include <vector>

#include "Vrpu_guide_pair.h"
#include "tb_base.h"
#include "tb_guide.h"

#ifndef HH_IN
#define HH_IN 1
#endif
#ifndef VECTORS
#define VECTORS 100000
#endif

namespace {

using sim::random_spread;
using ld = long double;

constexpr int kCW = COORD_W, kFT = T_FRAC;
constexpr bool kHhIn = HH_IN != 0;
constexpr int kTW = kFT + 3, kWW = kFT - 1, kHW = kCW + 5, kAW = kCW, kL2W = 2 * kCW + 3;
constexpr int kGW = kCW + 2, kRadW = 2 * kCW + 10;

struct Op {  // one guide (l2 and t are the pair's: guide 1's fields hold them)
  int mode = 0;
  i128 h = 0, a = 0, b = 0, l2 = 0, t = 0;
};
struct PairOp {
  Op g[2];
  ref::GuidePair want;  // the twin's g1, g2, w
  bool ovf = false;
};

// A descriptor-like guide (the model test's construction) of a segment of length L in
// [2^8, 2^CW): h = L·10^(−2..3).
ld random_length(std::mt19937_64& rng, std::uniform_real_distribution<double>& unit) {
  const int span = kCW - 8;
  return std::ldexp(1.0L, 8 + static_cast<int>(rng() % span)) * (1 + unit(rng));
}
Op design_guide(std::mt19937_64& rng, std::uniform_real_distribution<double>& unit, ld L) {
  Op op;
  op.l2 = static_cast<i128>(L * L);
  if (rng() % 10 == 0) {  // straight
    op.mode = 0;
    return op;
  }
  const ld h = L * std::pow(10.0L, -2 + 5 * unit(rng));
  if (h <= ref::HwParams::kFlatRatio * L) {
    op.mode = 1;
    op.h = std::llround(h);
  } else {
    op.mode = 2;
    op.a = std::llround(static_cast<ld>(op.l2) / (2 * h));
    op.b = std::llround(std::ldexp(static_cast<ld>(op.l2) / (4 * h * h), kFT));
  }
  return op;
}

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_guide_pair> tb("tb_rpu_guide_pair", argc, argv);
  auto& rng = tb.rng;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const long random_count = tb.vectors(VECTORS);
  const ref::HwParams p = sim::tb_params();

  // ---- the operand list: edges first, then random ----
  std::vector<PairOp> ops;
  const auto pair_of = [](Op g1, Op g2, i128 t) {
    g1.t = t;
    g2.l2 = g1.l2;
    return PairOp{{g1, g2}, {}, false};
  };
  const i128 one = i128{1} << kFT;
  const i128 t_edges[] = {0, 1, 2, one / 2, one / 2 + 1, one - 1, one, one + 1, -1,
                          fixed::max_signed(kTW), fixed::min_signed(kTW), one / 4, 3 * one / 4};
  Op arc, flat;
  {
    const ld L = std::ldexp(1.5L, kCW - 1);
    arc.mode = 1;
    arc.l2 = flat.l2 = static_cast<i128>(L * L);
    arc.h = std::llround(L / 3);
    flat.mode = 2;
    flat.a = std::llround(static_cast<ld>(flat.l2) / (200 * L));
    flat.b = std::llround(std::ldexp(static_cast<ld>(flat.l2) / (40000 * L * L), kFT));
  }
  for (int m1 = 0; m1 < 4; ++m1)
    for (int m2 = 0; m2 < 4; ++m2)
      for (i128 t : t_edges) {
        Op g1 = m1 == 2 ? flat : arc, g2 = m2 == 2 ? flat : arc;
        g1.mode = m1;
        g2.mode = m2;
        g2.h = arc.h / 2 + 7;  // the two arcs differ
        ops.push_back(pair_of(g1, g2, t));
      }
  const i128 l2_max = static_cast<i128>(fixed::max_unsigned(kL2W));
  const i128 h_max = static_cast<i128>(fixed::max_unsigned(kHW));
  for (i128 h : {i128{0}, i128{1}, i128{1} << (kCW + 4), h_max - 1, h_max})
    for (i128 l2 : {i128{0}, l2_max})
      for (i128 t : {one / 2, one / 3, i128{0}, one})
        ops.push_back(pair_of({1, h, 0, 0, l2, 0}, {1, h_max - h, 0, 0, 0, 0}, t));
  for (i128 a : {i128{0}, i128{1}, static_cast<i128>(fixed::max_unsigned(kAW))})
    for (i128 b : {i128{0}, i128{1}, static_cast<i128>(fixed::max_unsigned(kFT))})
      for (i128 t : {one / 2, one / 3})
        ops.push_back(pair_of({2, 0, a, b, l2_max, 0}, {1, h_max, 0, 0, 0, 0}, t));
  const long edge_count = static_cast<long>(ops.size());
  long design = 0, raw = 0;
  for (long k = 0; k < random_count; ++k) {
    PairOp op;
    if (rng() % 10 == 0) {  // anything the ports can carry
      const i128 l2 = random_spread(rng, kL2W);
      for (Op& g : op.g) {
        g.mode = static_cast<int>(rng() % 4);
        g.h = random_spread(rng, kHW);
        g.a = random_spread(rng, kAW);
        g.b = random_spread(rng, kFT);
        g.l2 = l2;
      }
      if (rng() % 4 == 0) {  // h near its maximum: h² + floor(L2·w) crosses 2^RadW
        const int k2 = static_cast<int>(rng() % 2);
        op.g[k2].mode = 1;
        op.g[k2].h = static_cast<i128>(fixed::max_unsigned(kHW)) - random_spread(rng, kHW - 9);
        op.g[0].l2 = op.g[1].l2 =
            static_cast<i128>(fixed::max_unsigned(kL2W)) - random_spread(rng, kL2W - 2);
      }
      ++raw;
    } else {
      const ld L = random_length(rng, unit);
      op.g[0] = design_guide(rng, unit, L);
      op.g[1] = design_guide(rng, unit, L);
      ++design;
    }
    op.g[0].t = sim::random_t(rng, kFT);
    ops.push_back(op);
  }

  // ---- the twin ----
  long arcs = 0, flats = 0, overflows = 0, negative_g = 0;
  for (PairOp& op : ops) {
    ref::GuideDesc g[2];
    for (int k = 0; k < 2; ++k) {
      g[k].mode = static_cast<ref::GuideMode>(op.g[k].mode);  // code 3: not a named mode, g = 0
      g[k].h = static_cast<fixed::i64>(op.g[k].h);
      g[k].a = static_cast<fixed::i64>(op.g[k].a);
      g[k].b = static_cast<fixed::i64>(op.g[k].b);
      arcs += op.g[k].mode == 1;
      flats += op.g[k].mode == 2;
    }
    fixed::Overflow ovf;
    op.want = ref::guide_pair(p, g[0], g[1], op.g[0].l2, op.g[0].t, ovf);
    op.ovf = ovf.flag;
    overflows += ovf.flag;
    negative_g += (op.want.g1 < 0) + (op.want.g2 < 0);
  }

  // The latency, as its header says: w, the products, the roots.
  sim::Stream<Vrpu_guide_pair, PairOp> s{.latency = ref::guide_pair_latency(p)};
  s.inputs = [](sim::Inputs& in, Vrpu_guide_pair& t, const PairOp& op) {
    const auto hh = [&](const Op& g) { return kHhIn ? g.h * g.h : in.random(kRadW); };
    in("t", t.t_i, op.g[0].t, kTW)("L2", t.l2_i, op.g[0].l2, kL2W);
    for (int k = 0; k < 2; ++k) {
      const Op& g = op.g[k];
      sim::guide_shape_input(in, k ? "g2" : "g1", k ? t.g2_i : t.g1_i, sim::tb_params(),
                             static_cast<int>(g.mode), g.h, g.a, g.b);
      in(k ? "hh2" : "hh1", k ? t.hh2_i : t.hh1_i, hh(g), kRadW);
    }
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_guide_pair& t, const PairOp& op) {
    o.s("g1", t.g1_o, op.want.g1, kGW).s("g2", t.g2_o, op.want.g2, kGW)("w", t.w_o, op.want.w, kWW);
    o("ovf", t.ovf_o, op.ovf, 1);
  };
  return tb.check(ops, s,
                  "CoordW=%d TFrac=%d SqrtW=%d HhIn=%d TagW=%d latency %ld; %ld edges, %ld "
                  "descriptor-like, %ld full-range; %ld arc, %ld flat guides, %ld overflow, %ld "
                  "negative g", kCW, kFT, SQRT_W, static_cast<int>(kHhIn), TAG_W, s.latency,
                  edge_count, design, raw, arcs, flats, overflows, negative_g);
}
