// rpu_div against its twin (rpu::fixed::udiv): exhaustive over every dividend and non-zero
// divisor whose quotient fits when the operands are narrow; edge values, the ray generator's
// reciprocal 2^(2FV+2) / |v| and seeded random vectors (spread over magnitudes) when wide.
// Random valid gaps; every output compared in order, tag included.
#include <deque>
#include <memory>
#include <vector>

#include "Vrpu_div.h"
#include "fixed/fixed.h"
#include "tb_common.h"

#if !defined(NUM_W) || !defined(DEN_W) || !defined(QUOT_W)
#error "NUM_W, DEN_W and QUOT_W must be defined to the parameters of the verilated configuration"
#endif
#ifndef TAG_W
#define TAG_W 1
#endif
#ifndef RECIP_FV  // > 0: also the ray generator's reciprocal, dividend 2^(2·RECIP_FV+2)
#define RECIP_FV 0
#endif

namespace {

using namespace rpu;
using rpu::sim::i128;
using rpu::sim::u128;

struct Operands {
  u128 num, den;
};

struct Item {
  Operands op;
  u128 expected;
  std::uint64_t tag;
  long issued;  // cycle of valid_i
};

constexpr int kNumW = NUM_W, kDenW = DEN_W, kQuotW = QUOT_W, kTagW = TAG_W;

// The quotient fits QuotW bits (and the operands their ports).
bool fits(u128 num, u128 den) {
  return den != 0 && fixed::fits_unsigned(num, kNumW) && fixed::fits_unsigned(den, kDenW) &&
         (num >> kQuotW) < den;
}

// The largest dividend whose quotient by den still fits (den · 2^QuotW − 1, capped to NumW).
u128 max_num(u128 den) {
  const u128 cap = fixed::max_unsigned(kNumW);
  if (kQuotW + kDenW >= 127) return cap;
  const u128 lim = (den << kQuotW) - 1;
  return lim < cap ? lim : cap;
}

u128 random_bits(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  return bits & fixed::max_unsigned(width);
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_div");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_div>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_div");
  std::mt19937_64 rng(seed);
  const bool exhaustive = kNumW + kDenW <= 24;
  const long random_count = sim::vector_count(exhaustive ? 0 : 100000);

  std::deque<Operands> operands;
  const u128 num_max = fixed::max_unsigned(kNumW), den_max = fixed::max_unsigned(kDenW);
  const auto add = [&](u128 num, u128 den) {
    if (fits(num, den)) operands.push_back({num, den});
  };
  if (exhaustive) {
    for (u128 den = 1; den <= den_max; ++den)
      for (u128 num = 0; num <= num_max; ++num) add(num, den);
  } else {
    // Edges: smallest and largest divisors, quotients 0, 1, exact multiples and their
    // neighbours, the largest quotient 2^QuotW − 1, powers of two.
    for (u128 den : {u128{1}, u128{2}, u128{3}, den_max, den_max - 1, den_max >> 1,
                     (den_max >> 1) + 1}) {
      const u128 top_num = max_num(den);
      for (u128 num : {u128{0}, u128{1}, den - 1, den, den + 1, 2 * den - 1, 2 * den, top_num,
                       top_num - 1, top_num - den, top_num - den + 1, top_num >> 1})
        add(num, den);
    }
    for (int k = 0; k < kDenW; ++k) {
      const u128 den = u128{1} << k;
      for (u128 d : {den - 1, den, den + 1})
        if (d != 0) {
          add(max_num(d), d);
          add(max_num(d) / 3, d);
          add(num_max, d);
        }
    }
    for (int k = 0; k < kNumW; ++k)
      for (u128 den : {u128{1}, u128{3}, den_max}) add(u128{1} << k, den);
    // The ray generator's reciprocal: 2^(2FV+2) / |v| for |v| around its legal range
    // (2^(FV−1), 2^(FV+4)) — the smallest fitting divisors, 1.0, √3·8 and random ones.
    if (RECIP_FV > 0) {
      const int fv = RECIP_FV > 0 ? RECIP_FV : 1;  // (never 1: guarded)
      const u128 one = u128{1} << (2 * fv + 2), lo = u128{1} << (fv - 1);
      for (u128 den : {lo + 1, lo + 2, lo + 3, u128{1} << fv, (u128{1} << fv) + 1,
                       (u128{1} << fv) - 1, (u128{1} << (fv + 3)) - 1, u128{1} << (fv + 3),
                       (u128{1} << (fv + 4)) - 1, (u128{1} << (fv + 3)) * 1732 / 1000})
        add(one, den);
      for (long k = 0; k < random_count / 4; ++k) {
        const u128 span = (u128{1} << (fv + 4)) - lo - 1;
        add(one, lo + 1 + random_bits(rng, fv + 4) % span);
      }
    }
    // Random: a divisor of random magnitude, then a dividend whose quotient fits, also of
    // random magnitude (so small quotients are exercised as well as full ones).
    long made = 0;
    while (made < random_count) {
      const u128 den = random_bits(rng, 1 + static_cast<int>(rng() % kDenW));
      if (den == 0) continue;
      const u128 top_num = max_num(den);
      const int w = 1 + static_cast<int>(rng() % fixed::bit_length(top_num));
      const u128 num = random_bits(rng, w) % (top_num + 1);
      add(num, den);
      ++made;
    }
  }

  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0;
  std::uint64_t tag = 0;
  const std::uint64_t tag_mask = kTagW >= 64 ? ~0ull : (1ull << kTagW) - 1;
  const long total = static_cast<long>(operands.size());
  while (matched < total) {
    // Drive: a new operand on ~85 % of the cycles; garbage on the data inputs otherwise.
    const bool issue = !operands.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Operands op = operands.front();
      operands.pop_front();
      sim::put(top->num_i, static_cast<i128>(op.num), kNumW);
      sim::put(top->den_i, static_cast<i128>(op.den), kDenW);
      top->tag_i = tag & tag_mask;
      expected.push_back({op, fixed::udiv(op.num, op.den, kQuotW), tag & tag_mask, cycle});
      ++tag;
    } else {
      sim::put(top->num_i, static_cast<i128>(random_bits(rng, kNumW)), kNumW);
      sim::put(top->den_i, static_cast<i128>(random_bits(rng, kDenW)), kDenW);
      top->tag_i = rng() & tag_mask;
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
      const u128 got = sim::get_unsigned(top->quot_o, kQuotW);
      const std::uint64_t got_tag = top->tag_o;
      if (got != want.expected || got_tag != want.tag || cycle - want.issued != kQuotW) {
        std::printf("FAILURE cycle %ld item %ld (latency %ld, expected %d): num = %s den = %s "
                    "expected quot %s tag %llu, got quot %s tag %llu\n",
                    cycle, matched, cycle - want.issued, kQuotW,
                    sim::to_string(static_cast<i128>(want.op.num)).c_str(),
                    sim::to_string(static_cast<i128>(want.op.den)).c_str(),
                    sim::to_string(static_cast<i128>(want.expected)).c_str(),
                    static_cast<unsigned long long>(want.tag),
                    sim::to_string(static_cast<i128>(got)).c_str(),
                    static_cast<unsigned long long>(got_tag));
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  // Nothing may come out after the last item.
  top->valid_i = 0;
  for (int k = 0; k < kQuotW + 4; ++k) {
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      std::printf("FAILURE cycle %ld: spurious valid_o after the last item\n", cycle);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_div NumW=%d DenW=%d QuotW=%d TagW=%d: matched %ld items (%s) in %ld cycles\n",
              kNumW, kDenW, kQuotW, kTagW, matched, exhaustive ? "exhaustive" : "edges + random",
              cycle);
  return 0;
}
