// rpu_guide_pair against its twin (rpu::ref::guide_pair: guide_weight, then guide_unit for each
// guide): edge values (every pair of modes at every edge t), then seeded random pairs of guides
// of one segment built like tests/test_model.cpp GuideUnit.ArcAndFlatWithinBound (arc and flat,
// h from 0.01 L to 1000 L, L from 2^8 up to 2^CW) and straight ones, with t over the whole
// Q(3.FT) range (w clamps outside [0, 1]), plus random values over the full port range (mode
// code 3, saturating radicands). With HhIn = 1 the h² ports carry h² (the caller's contract);
// with HhIn = 0 they carry junk, which must not matter. Random valid gaps and junk on idle
// cycles; compares g1, g2, w, the overflow bit, the tag and the latency of every item, in order.
#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>

#include "Vrpu_guide_pair.h"
#include "model/units.h"
#include "tb_common.h"

#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef T_FRAC
#define T_FRAC 24
#endif
#ifndef SQRT_W
#define SQRT_W 0
#endif
#ifndef TAG_W
#define TAG_W 1
#endif
#ifndef HH_IN
#define HH_IN 1
#endif
#ifndef VECTORS
#define VECTORS 100000
#endif

namespace {

using namespace rpu;
using rpu::sim::i128;
using rpu::sim::u128;
using ld = long double;

constexpr int kCW = COORD_W, kFT = T_FRAC, kSqrtW = SQRT_W, kTagW = TAG_W;
constexpr bool kHhIn = HH_IN != 0;
constexpr int kTW = kFT + 3, kWW = kFT - 1, kHW = kCW + 5, kAW = kCW, kL2W = 2 * kCW + 3;
constexpr int kGW = kCW + 2, kRadW = 2 * kCW + 10;


struct Op {  // one guide (l2 and t are the pair's: guide 1's fields hold them)
  int mode = 0;
  i128 h = 0, a = 0, b = 0, l2 = 0, t = 0;
};
struct PairOp {
  Op g[2];
};

struct Item {
  PairOp op;
  i128 g1, g2, w;
  bool ovf;
  std::uint32_t tag;
  long issued;  // cycle count before the issuing edge
};

// Ports take the value's low `width` bits (Verilator wants the bits above a port's width clear).
template <class P>
void drive(P& port, i128 v, int width) {
  sim::put(port, static_cast<i128>(static_cast<u128>(v) & fixed::max_unsigned(width)), width);
}

i128 random_bits(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  return static_cast<i128>(bits & fixed::max_unsigned(width));
}
// Spread over magnitudes: a random width 1..width, then random bits.
i128 random_spread(std::mt19937_64& rng, int width) {
  return random_bits(rng, 1 + static_cast<int>(rng() % static_cast<unsigned>(width)));
}
i128 random_signed(std::mt19937_64& rng, int width) {
  const i128 u = random_bits(rng, width);
  return u > fixed::max_signed(width) ? u - (i128{1} << width) : u;
}

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

// t over Q(3.FT): mostly inside [0, 1], some near its ends, the rest anywhere (w clamps).
i128 random_t(std::mt19937_64& rng) {
  const i128 one = i128{1} << kFT;
  switch (rng() % 8) {
    case 0: return static_cast<i128>(rng() % 17) - 8;
    case 1: return one + static_cast<i128>(rng() % 17) - 8;
    case 2:
    case 3: return random_signed(rng, kTW);
    default: return random_bits(rng, kFT + 1) % (one + 1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_guide_pair");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_guide_pair>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_guide_pair");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const long random_count = sim::vector_count(VECTORS);

  ref::HwParams p;
  p.coord_w = kCW;
  p.t_frac = kFT;
  p.sqrt_w = kSqrtW;
  p.validate();
  const int kLatency = ref::guide_pair_latency(p);  // its header: w, the products, the roots

  // ---- the operand list: edges first, then random ----
  std::deque<PairOp> ops;
  const auto pair_of = [](Op g1, Op g2, i128 t) {
    g1.t = t;
    g2.l2 = g1.l2;
    return PairOp{{g1, g2}};
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
    op.g[0].t = random_t(rng);
    ops.push_back(op);
  }

  // ---- drive and check ----
  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0, arcs = 0, flats = 0, overflows = 0, negative_g = 0;
  const long total = static_cast<long>(ops.size());
  const std::uint32_t tag_mask = kTagW >= 32 ? 0xFFFFFFFFu : ((1u << kTagW) - 1);
  const auto junk_op = [&] {
    Op g{static_cast<int>(rng() % 4), random_bits(rng, kHW), random_bits(rng, kAW),
         random_bits(rng, kFT), random_bits(rng, kL2W), random_bits(rng, kTW)};
    return g;
  };
  while (matched < total) {
    const bool issue = !ops.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    PairOp op;
    if (issue) {
      op = ops.front();
      ops.pop_front();
    } else {  // junk on idle cycles: must not matter
      op.g[0] = junk_op();
      op.g[1] = junk_op();
    }
    drive(top->t_i, op.g[0].t, kTW);
    drive(top->l2_i, op.g[0].l2, kL2W);
    const auto hh = [&](const Op& g) { return kHhIn ? g.h * g.h : random_bits(rng, kRadW); };
    drive(top->mode1_i, op.g[0].mode, 2);
    drive(top->h1_i, op.g[0].h, kHW);
    drive(top->hh1_i, hh(op.g[0]), kRadW);
    drive(top->a1_i, op.g[0].a, kAW);
    drive(top->b1_i, op.g[0].b, kFT);
    drive(top->mode2_i, op.g[1].mode, 2);
    drive(top->h2_i, op.g[1].h, kHW);
    drive(top->hh2_i, hh(op.g[1]), kRadW);
    drive(top->a2_i, op.g[1].a, kAW);
    drive(top->b2_i, op.g[1].b, kFT);
    const std::uint32_t this_tag = static_cast<std::uint32_t>(rng()) & tag_mask;
    drive(top->tag_i, this_tag, kTagW);
    if (issue) {
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
      const ref::GuidePair gp = ref::guide_pair(p, g[0], g[1], op.g[0].l2, op.g[0].t, ovf);
      expected.push_back({op, gp.g1, gp.g2, gp.w, ovf.flag, this_tag, cycle});
      overflows += ovf.flag;
      negative_g += (gp.g1 < 0) + (gp.g2 < 0);
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Item want = expected.front();
      expected.pop_front();
      const i128 g1 = sim::get_signed(top->g1_o, kGW);
      const i128 g2 = sim::get_signed(top->g2_o, kGW);
      const i128 w = static_cast<i128>(sim::get_unsigned(top->w_o, kWW));
      const bool ovf = top->ovf_o;
      const auto got_tag = static_cast<std::uint32_t>(sim::get_unsigned(top->tag_o, kTagW));
      const long latency = cycle - want.issued;
      if (g1 != want.g1 || g2 != want.g2 || w != want.w || ovf != want.ovf ||
          got_tag != want.tag || latency != kLatency) {
        std::printf("FAILURE cycle %ld item %ld: L2 %s t %s\n", cycle, matched,
                    sim::to_string(want.op.g[0].l2).c_str(), sim::to_string(want.op.g[0].t).c_str());
        for (int k = 0; k < 2; ++k)
          std::printf("  guide %d: mode %d h %s a %s b %s\n", k + 1, want.op.g[k].mode,
                      sim::to_string(want.op.g[k].h).c_str(), sim::to_string(want.op.g[k].a).c_str(),
                      sim::to_string(want.op.g[k].b).c_str());
        std::printf("  expected g1 %s g2 %s w %s ovf %d tag %u latency %d\n",
                    sim::to_string(want.g1).c_str(), sim::to_string(want.g2).c_str(),
                    sim::to_string(want.w).c_str(), want.ovf, want.tag, kLatency);
        std::printf("  got      g1 %s g2 %s w %s ovf %d tag %u latency %ld\n",
                    sim::to_string(g1).c_str(), sim::to_string(g2).c_str(),
                    sim::to_string(w).c_str(), ovf, got_tag, latency);
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
  std::printf("rpu_guide_pair CoordW=%d TFrac=%d SqrtW=%d HhIn=%d TagW=%d latency %d: matched "
              "%ld items (%ld edges, %ld descriptor-like, %ld full-range; %ld arc, %ld flat "
              "guides, %ld overflow, %ld negative g) in %ld cycles\n",
              kCW, kFT, kSqrtW, static_cast<int>(kHhIn), kTagW, kLatency, matched, edge_count,
              design, raw, arcs, flats, overflows, negative_g, cycle);
  return 0;
}
