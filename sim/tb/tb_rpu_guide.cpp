// rpu_guide against its twin (rpu::ref::guide_weight, then rpu::ref::guide_unit): edge values,
// then seeded random guides built like tests/test_model.cpp GuideUnit.ArcAndFlatWithinBound (arc
// and flat, h from 0.01 L to 1000 L, L from 2^8 up to 2^CW) and straight ones, with t over the
// whole Q(3.FT) range (w clamps outside [0, 1]), plus random values over the full port range
// (mode code 3, saturating radicands). Random valid gaps and junk on idle cycles; compares g, w,
// the overflow bit, the tag and the latency of every item, in order.
#include <cmath>
#include <deque>
#include <memory>

#include "Vrpu_guide.h"
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
#ifndef VECTORS
#define VECTORS 100000
#endif

namespace {

using namespace rpu;
using rpu::sim::i128;
using rpu::sim::u128;
using ld = long double;

constexpr int kCW = COORD_W, kFT = T_FRAC, kSqrtW = SQRT_W, kTagW = TAG_W;
constexpr int kTW = kFT + 3, kWW = kFT - 1, kHW = kCW + 5, kAW = kCW, kL2W = 2 * kCW + 3;
constexpr int kGW = kCW + 2, kRadW = 2 * kCW + 10;
constexpr int kShift = (kSqrtW == 0 || kRadW <= kSqrtW) ? 0 : (kRadW - kSqrtW + 1) / 2;
constexpr int kLatency = 3 + (kRadW - 2 * kShift + 1) / 2 + 1;

struct Op {
  int mode = 0;
  i128 h = 0, a = 0, b = 0, l2 = 0, t = 0;
};

struct Item {
  Op op;
  i128 g, w;
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

// A descriptor-like guide (the model test's construction): L in [2^8, 2^CW), h = L·10^(−2..3).
Op design_guide(std::mt19937_64& rng, std::uniform_real_distribution<double>& unit) {
  Op op;
  const int span = kCW - 8;
  const ld L = std::ldexp(1.0L, 8 + static_cast<int>(rng() % span)) * (1 + unit(rng));
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
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_guide>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_guide");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const long random_count = sim::vector_count(VECTORS);

  ref::HwParams p;
  p.coord_w = kCW;
  p.t_frac = kFT;
  p.sqrt_w = kSqrtW;
  p.validate();

  // ---- the operand list: edges first, then random ----
  std::deque<Op> ops;
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
  for (int mode = 0; mode < 4; ++mode)
    for (i128 t : t_edges) {
      Op op = mode == 2 ? flat : arc;
      op.mode = mode;
      op.t = t;
      ops.push_back(op);
    }
  const i128 l2_max = static_cast<i128>(fixed::max_unsigned(kL2W));
  const i128 h_max = static_cast<i128>(fixed::max_unsigned(kHW));
  for (i128 h : {i128{0}, i128{1}, i128{1} << (kCW + 4), h_max - 1, h_max})
    for (i128 l2 : {i128{0}, l2_max})
      for (i128 t : {one / 2, one / 3, i128{0}, one}) ops.push_back({1, h, 0, 0, l2, t});
  for (i128 a : {i128{0}, i128{1}, static_cast<i128>(fixed::max_unsigned(kAW))})
    for (i128 b : {i128{0}, i128{1}, static_cast<i128>(fixed::max_unsigned(kFT))})
      for (i128 t : {one / 2, one / 3}) ops.push_back({2, 0, a, b, l2_max, t});
  const long edge_count = static_cast<long>(ops.size());
  long design = 0, raw = 0;
  for (long k = 0; k < random_count; ++k) {
    Op op;
    if (rng() % 10 == 0) {  // anything the ports can carry
      op.mode = static_cast<int>(rng() % 4);
      op.h = random_spread(rng, kHW);
      op.a = random_spread(rng, kAW);
      op.b = random_spread(rng, kFT);
      op.l2 = random_spread(rng, kL2W);
      if (rng() % 4 == 0) {  // h near its maximum: h² + floor(L2·w) crosses 2^RadW
        op.mode = 1;
        op.h = static_cast<i128>(fixed::max_unsigned(kHW)) - random_spread(rng, kHW - 9);
        op.l2 = static_cast<i128>(fixed::max_unsigned(kL2W)) - random_spread(rng, kL2W - 2);
      }
      ++raw;
    } else {
      op = design_guide(rng, unit);
      ++design;
    }
    op.t = random_t(rng);
    ops.push_back(op);
  }

  // ---- drive and check ----
  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0, arcs = 0, flats = 0, overflows = 0, negative_g = 0;
  std::uint32_t tag = 0;
  const long total = static_cast<long>(ops.size());
  const std::uint32_t tag_mask = kTagW >= 32 ? 0xFFFFFFFFu : ((1u << kTagW) - 1);
  while (matched < total) {
    const bool issue = !ops.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    Op op;
    if (issue) {
      op = ops.front();
      ops.pop_front();
    } else {  // junk on idle cycles: must not matter
      op = {static_cast<int>(rng() % 4), random_bits(rng, kHW), random_bits(rng, kAW),
            random_bits(rng, kFT), random_bits(rng, kL2W), random_bits(rng, kTW)};
    }
    drive(top->t_i, op.t, kTW);
    drive(top->mode_i, op.mode, 2);
    drive(top->h_i, op.h, kHW);
    drive(top->a_i, op.a, kAW);
    drive(top->b_i, op.b, kFT);
    drive(top->l2_i, op.l2, kL2W);
    const std::uint32_t this_tag = static_cast<std::uint32_t>(rng()) & tag_mask;
    drive(top->tag_i, this_tag, kTagW);
    if (issue) {
      ref::GuideDesc g;
      g.mode = static_cast<ref::GuideMode>(op.mode);  // code 3 is not a named mode: g = 0
      g.h = static_cast<fixed::i64>(op.h);
      g.a = static_cast<fixed::i64>(op.a);
      g.b = static_cast<fixed::i64>(op.b);
      const i128 w = ref::guide_weight(p, op.t);
      fixed::Overflow ovf;
      const i128 gv = ref::guide_unit(p, g, op.l2, w, ovf);
      expected.push_back({op, gv, w, ovf.flag, this_tag, cycle});
      arcs += op.mode == 1;
      flats += op.mode == 2;
      overflows += ovf.flag;
      negative_g += gv < 0;
      ++tag;
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
      const i128 g = sim::get_signed(top->g_o, kGW);
      const i128 w = static_cast<i128>(sim::get_unsigned(top->w_o, kWW));
      const bool ovf = top->ovf_o;
      const auto got_tag = static_cast<std::uint32_t>(sim::get_unsigned(top->tag_o, kTagW));
      const long latency = cycle - want.issued;
      if (g != want.g || w != want.w || ovf != want.ovf || got_tag != want.tag ||
          latency != kLatency) {
        std::printf("FAILURE cycle %ld item %ld: mode %d h %s a %s b %s L2 %s t %s\n", cycle,
                    matched, want.op.mode, sim::to_string(want.op.h).c_str(),
                    sim::to_string(want.op.a).c_str(), sim::to_string(want.op.b).c_str(),
                    sim::to_string(want.op.l2).c_str(), sim::to_string(want.op.t).c_str());
        std::printf("  expected g %s w %s ovf %d tag %u latency %d\n",
                    sim::to_string(want.g).c_str(), sim::to_string(want.w).c_str(), want.ovf,
                    want.tag, kLatency);
        std::printf("  got      g %s w %s ovf %d tag %u latency %ld\n", sim::to_string(g).c_str(),
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
  std::printf("rpu_guide CoordW=%d TFrac=%d SqrtW=%d TagW=%d latency %d: matched %ld items "
              "(%ld edges, %ld descriptor-like, %ld full-range; %ld arc, %ld flat, %ld overflow, "
              "%ld negative g) in %ld cycles\n",
              kCW, kFT, kSqrtW, kTagW, kLatency, matched, edge_count, design, raw, arcs, flats,
              overflows, negative_g, cycle);
  return 0;
}
