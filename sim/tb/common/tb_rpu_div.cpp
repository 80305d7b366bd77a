// rpu_div against its twin (rpu::fixed::udiv): exhaustive over every dividend and non-zero
// divisor whose quotient fits when the operands are narrow; edge values, the ray generator's
// reciprocal 2^(2FV+2) / |v| and seeded random vectors (spread over magnitudes) when wide.
#include <vector>

#include "Vrpu_div.h"
#include "tb_base.h"

#if !defined(NUM_W) || !defined(DEN_W) || !defined(QUOT_W)
#error "NUM_W, DEN_W and QUOT_W must be defined to the parameters of the verilated configuration"
#endif
#ifndef RECIP_FV  // > 0: also the ray generator's reciprocal, dividend 2^(2·RECIP_FV+2)
#define RECIP_FV 0
#endif

constexpr int kNumW = NUM_W, kDenW = DEN_W, kQuotW = QUOT_W;

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

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_div> tb("tb_rpu_div", argc, argv);
  auto& rng = tb.rng;
  const auto random_bits = [&](int w) { return static_cast<u128>(sim::random_bits(rng, w)); };
  const bool exhaustive = kNumW + kDenW <= 24;
  const long random_count = tb.vectors(exhaustive ? 0 : 100000);

  struct Item {
    u128 num, den, quot;
  };
  std::vector<Item> items;
  const u128 num_max = fixed::max_unsigned(kNumW), den_max = fixed::max_unsigned(kDenW);
  const auto add = [&](u128 num, u128 den) {
    if (fits(num, den)) items.push_back({num, den, fixed::udiv(num, den, kQuotW)});
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
        add(one, lo + 1 + random_bits(fv + 4) % span);
      }
    }
    // Random: a divisor of random magnitude, then a dividend whose quotient fits, also of
    // random magnitude (so small quotients are exercised as well as full ones).
    long made = 0;
    while (made < random_count) {
      const u128 den = random_bits(1 + static_cast<int>(rng() % kDenW));
      if (den == 0) continue;
      const u128 top_num = max_num(den);
      const int w = 1 + static_cast<int>(rng() % fixed::bit_length(top_num));
      const u128 num = random_bits(w) % (top_num + 1);
      add(num, den);
      ++made;
    }
  }

  sim::Stream<Vrpu_div, Item> s{.latency = kQuotW};
  s.inputs = [](sim::Inputs& in, Vrpu_div& t, const Item& it) {
    in("num", t.num_i, static_cast<i128>(it.num), kNumW)("den", t.den_i, static_cast<i128>(it.den), kDenW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_div& t, const Item& it) {
    o("quot", t.quot_o, static_cast<i128>(it.quot), kQuotW);
  };
  return tb.check(items, s, "NumW=%d DenW=%d QuotW=%d TagW=%d, %s", kNumW, kDenW, kQuotW, TAG_W,
                  exhaustive ? "exhaustive" : "edges + random");
}
