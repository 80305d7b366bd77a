// The fixed-point layer (ref/fixed) proved against exact integer results: exhaustive over small
// widths, edge values and seeded random vectors over wide ones. Every expected value is computed
// here independently of the layer (plain 64-bit or 128-bit integer arithmetic).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_seed.h"
#include "fixed/fixed.h"

namespace rpu::fixed {
namespace {

// Fixed default seed so runs are reproducible; RPU_FIXED_SEED=<n> overrides it.
constexpr u64 kDefaultSeed = 20261121;

u64 test_seed() {
  if (const char* s = std::getenv("RPU_FIXED_SEED")) return std::strtoull(s, nullptr, 0);
  return kDefaultSeed;
}

// ---- printing 128-bit values ---------------------------------------------------------------

std::string str(u128 v) {
  if (v == 0) return "0";
  std::string s;
  while (v) {
    s.push_back(static_cast<char>('0' + static_cast<int>(v % 10)));
    v /= 10;
  }
  std::reverse(s.begin(), s.end());
  return s;
}

std::string str(i128 v) {
  if (v >= 0) return str(static_cast<u128>(v));
  return "-" + str(u128{0} - static_cast<u128>(v));  // also right for the minimum i128
}

// Report at most this many mismatches per test (the count of all of them is still checked).
constexpr int kMaxReported = 20;

struct Failures {
  int n = 0;
  // Returns true when this failure should be printed.
  bool report() { return ++n <= kMaxReported; }
};

#define RPU_CHECK(fails, cond, msg)                                  \
  do {                                                               \
    if (!(cond) && (fails).report()) ADD_FAILURE() << #cond << ": " << msg; \
  } while (0)

// ---- independent references ----------------------------------------------------------------

constexpr u128 pow2(int k) { return u128{1} << k; }

// Extremes of i128 spelled out (std::numeric_limits<__int128> is not guaranteed in strict modes).
constexpr i128 kI128Max = static_cast<i128>(~u128{0} >> 1);
constexpr i128 kI128Min = -kI128Max - 1;

// Smallest n ≥ 0 with v < 2^n (128 for v ≥ 2^127).
int ref_bit_length(u128 v) {
  for (int n = 0; n < 128; ++n)
    if (v < pow2(n)) return n;
  return 128;
}

// Floor division by a positive divisor, for any sign of the dividend.
i128 floor_div(i128 v, i128 d) {
  i128 q = v / d;  // truncates toward zero
  if (v % d != 0 && v < 0) --q;
  return q;
}

// Floor square root by binary search on u128 (x < 2^126, so the root < 2^63 and mid² fits).
u128 ref_isqrt(u128 x) {
  u128 lo = 0, hi = pow2(63);  // invariant: lo² ≤ x < hi²
  while (hi - lo > 1) {
    const u128 mid = lo + (hi - lo) / 2;
    if (mid * mid <= x) lo = mid; else hi = mid;
  }
  return lo;
}

// Random 128-bit pattern.
u128 rand128(std::mt19937_64& rng) { return (static_cast<u128>(rng()) << 64) | rng(); }

// ---- compile-time spot checks (the header's constexpr functions) ----------------------------

static_assert(max_signed(8) == 127 && min_signed(8) == -128);
static_assert(max_signed(1) == 0 && min_signed(1) == -1);
static_assert(max_unsigned(8) == 255 && max_unsigned(128) == ~u128{0});
static_assert(bit_length(0) == 0 && bit_length(1) == 1 && bit_length(255) == 8 && bit_length(256) == 9);
static_assert(truncate(-1, 1) == -1 && truncate(-3, 1) == -2 && truncate(3, -2) == 12);
static_assert(round_half_up(-3, 1) == -1 && round_half_up(3, 1) == 2 && round_half_up(-5, 2) == -1);

// =============================================================================================
// 1. isqrt
// =============================================================================================

// r is floor(sqrt(x)) iff r² ≤ x < (r+1)². For width ≤ 126, x < 2^126 and a correct r < 2^63,
// so (r+1)² ≤ 2^126 fits; a wild r is rejected first so the squares cannot overflow.
bool is_floor_sqrt(u128 x, u128 r) {
  if (r >= pow2(63)) return false;
  return r * r <= x && x < (r + 1) * (r + 1);
}

TEST(FixedIsqrt, ExhaustiveWidths1To16) {
  Failures f;
  long count = 0;
  for (int w = 1; w <= 16; ++w) {
    for (u64 x = 0; x < (u64{1} << w); ++x) {
      const u128 r = isqrt(x, w);
      // Plain 64-bit check.
      const u64 r64 = static_cast<u64>(r);
      const bool ok = r < 256 && r64 * r64 <= x && x < (r64 + 1) * (r64 + 1);
      RPU_CHECK(f, ok, "isqrt(" << x << ", " << w << ") = " << str(r) << ", expected "
                                << str(ref_isqrt(x)));
      ++count;
    }
  }
  std::printf("[isqrt exhaustive] widths 1..16: %ld vectors\n", count);
  EXPECT_EQ(f.n, 0);
}

TEST(FixedIsqrt, WideEdgeValues) {
  Failures f;
  long count = 0;
  auto check = [&](u128 x, int w) {
    if (!fits_unsigned(x, w)) return;  // candidate outside this width: not a valid input
    const u128 r = isqrt(x, w);
    RPU_CHECK(f, is_floor_sqrt(x, r), "isqrt(" << str(x) << ", " << w << ") = " << str(r)
                                               << ", expected " << str(ref_isqrt(x)));
    ++count;
  };
  for (int w = 17; w <= 126; ++w) {
    const u128 top = max_unsigned(w);
    for (u128 x : {u128{0}, u128{1}, u128{2}, u128{3}, top, top - 1, top - 2}) check(x, w);
    for (int k = 1; k <= w; ++k) {
      check(pow2(k) - 1, w);
      check(pow2(k), w);
      check(pow2(k) + 1, w);
    }
    // Perfect squares, squares ± 1, near the top of the range, and with exact expected roots.
    const u128 rmax = ref_isqrt(top);
    for (u128 d = 0; d < 64 && d <= rmax; ++d) {
      const u128 r = rmax - d;
      const u128 sq = r * r;
      check(sq, w);
      if (sq > 0) check(sq - 1, w);
      check(sq + 1, w);
      check(sq + 2 * r, w);  // (r+1)² - 1: the largest x with root r
      const u128 got = isqrt(sq, w);
      RPU_CHECK(f, got == r, "isqrt(" << str(sq) << ", " << w << ") = " << str(got)
                                      << ", expected " << str(r));
      ++count;
    }
    // Squares of powers of two and their neighbours at every scale.
    for (int k = 0; 2 * k <= w; ++k) {
      const u128 sq = pow2(2 * k);
      check(sq, w);
      check(sq - 1, w);
      check(sq + 1, w);
    }
  }
  std::printf("[isqrt edges] widths 17..126: %ld vectors\n", count);
  EXPECT_EQ(f.n, 0);
}

TEST(FixedIsqrt, WideRandom) {
  const u64 seed = test_seed();
  std::printf("[isqrt random] seed %llu (set RPU_FIXED_SEED to override)\n",
              static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(rpu::test::seed(seed));
  Failures f;
  constexpr long kCases = 250000;
  for (long i = 0; i < kCases; ++i) {
    const int w = 17 + static_cast<int>(rng() % 110);  // 17..126
    u128 x = rand128(rng) & max_unsigned(w);
    // Half the cases: a random shorter length, so small radicands in wide widths are covered too.
    if (i & 1) x >>= static_cast<int>(rng() % static_cast<u64>(w));
    const u128 r = isqrt(x, w);
    RPU_CHECK(f, is_floor_sqrt(x, r), "case " << i << " seed " << seed << ": isqrt(" << str(x)
                                              << ", " << w << ") = " << str(r) << ", expected "
                                              << str(ref_isqrt(x)));
  }
  std::printf("[isqrt random] %ld vectors\n", kCases);
  EXPECT_EQ(f.n, 0);
}

TEST(FixedIsqrt, RejectsBadArguments) {
  EXPECT_THROW(isqrt(0, 0), std::invalid_argument);
  EXPECT_THROW(isqrt(0, -1), std::invalid_argument);
  EXPECT_THROW(isqrt(0, 127), std::invalid_argument);
  EXPECT_THROW(isqrt(0, 128), std::invalid_argument);
  for (int w = 1; w <= 126; ++w) {
    EXPECT_THROW(isqrt(pow2(w), w), std::invalid_argument) << "width " << w;
    EXPECT_THROW(isqrt(~u128{0}, w), std::invalid_argument) << "width " << w;
    EXPECT_NO_THROW(isqrt(max_unsigned(w), w)) << "width " << w;
  }
  EXPECT_EQ(isqrt(max_unsigned(126), 126), pow2(63) - 1);
  EXPECT_EQ(isqrt(max_unsigned(125), 125), ref_isqrt(max_unsigned(125)));
}

// =============================================================================================
// 2. udiv
// =============================================================================================

TEST(FixedUdiv, ExhaustiveSmall) {
  Failures f;
  long count = 0, throws = 0;
  for (u64 a = 0; a < 1024; ++a) {
    for (u64 b = 1; b <= 256; ++b) {
      const u64 q = a / b;
      const int minw = std::max(1, ref_bit_length(q));  // smallest width ≥ 1 holding q
      for (int qw : {minw, minw + 3}) {
        const u128 got = udiv(a, b, qw);
        RPU_CHECK(f, got == q, "udiv(" << a << ", " << b << ", " << qw << ") = " << str(got)
                                       << ", expected " << q);
        ++count;
      }
      // One bit narrower must be refused (the quotient no longer fits).
      if (minw > 1) {
        bool threw = false;
        try {
          (void)udiv(a, b, minw - 1);
        } catch (const std::invalid_argument&) {
          threw = true;
        }
        RPU_CHECK(f, threw, "udiv(" << a << ", " << b << ", " << (minw - 1)
                                    << ") should throw: quotient " << q << " does not fit");
        ++throws;
      }
    }
  }
  std::printf("[udiv exhaustive] %ld quotients, %ld does-not-fit rejections\n", count, throws);
  EXPECT_EQ(f.n, 0);
}

// Shared by the random tests: a / b with the quotient width minw + slack (≤ 127), and the
// rejection at minw - 1.
void check_udiv(Failures& f, u128 a, u128 b, int slack, long i, u64 seed) {
  const u128 q = a / b;
  const int minw = std::max(1, ref_bit_length(q));
  if (minw > 127) return;  // a 128-bit quotient has no legal width
  const int qw = std::min(127, minw + slack);
  const u128 got = udiv(a, b, qw);
  RPU_CHECK(f, got == q, "case " << i << " seed " << seed << ": udiv(" << str(a) << ", " << str(b)
                                 << ", " << qw << ") = " << str(got) << ", expected " << str(q));
  if (minw > 1) {
    bool threw = false;
    try {
      (void)udiv(a, b, minw - 1);
    } catch (const std::invalid_argument&) {
      threw = true;
    }
    RPU_CHECK(f, threw, "case " << i << " seed " << seed << ": udiv(" << str(a) << ", " << str(b)
                                << ", " << (minw - 1) << ") should throw");
  }
}

TEST(FixedUdiv, WideRandom) {
  const u64 seed = test_seed() + 1;
  std::printf("[udiv random] seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(rpu::test::seed(seed));
  Failures f;
  constexpr long kCases = 150000;
  for (long i = 0; i < kCases; ++i) {
    // Dividend < 2^120 and divisor < 2^60 (nonzero), each of a random bit length.
    const int la = 1 + static_cast<int>(rng() % 120);
    const int lb = 1 + static_cast<int>(rng() % 60);
    const u128 a = rand128(rng) & max_unsigned(la);
    u128 b = rand128(rng) & max_unsigned(lb);
    if (b == 0) b = 1;
    check_udiv(f, a, b, static_cast<int>(rng() % 4), i, seed);
  }
  std::printf("[udiv random] %ld vectors\n", kCases);
  EXPECT_EQ(f.n, 0);
}

// Beyond the formats in use: full 128-bit dividends and divisors up to 2^128 - 1, where the
// partial remainder gets close to 2^128 (checks that the shift-in never overflows).
TEST(FixedUdiv, FullWidthRandom) {
  const u64 seed = test_seed() + 2;
  std::printf("[udiv full-width random] seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(rpu::test::seed(seed));
  Failures f;
  constexpr long kCases = 50000;
  for (long i = 0; i < kCases; ++i) {
    const int la = 1 + static_cast<int>(rng() % 128);
    const int lb = 1 + static_cast<int>(rng() % 128);
    const u128 a = rand128(rng) & max_unsigned(la);
    u128 b = rand128(rng) & max_unsigned(lb);
    if (b == 0) b = 1;
    check_udiv(f, a, b, static_cast<int>(rng() % 4), i, seed);
  }
  // Hand-picked extremes.
  const u128 all = ~u128{0};
  for (u128 b : {pow2(127) + 1, pow2(127) - 1, pow2(127), all, all - 1, pow2(64) + 1, u128{2},
                 u128{3}})
    check_udiv(f, all, b, 0, -1, seed);
  std::printf("[udiv full-width random] %ld vectors + 8 extremes\n", kCases);
  EXPECT_EQ(udiv(all, 2, 127), pow2(127) - 1);
  EXPECT_EQ(udiv(all, all, 1), 1u);
  EXPECT_EQ(udiv(all - 1, all, 1), 0u);
  EXPECT_EQ(f.n, 0);
}

TEST(FixedUdiv, RejectsBadArguments) {
  EXPECT_THROW(udiv(0, 0, 8), std::invalid_argument);
  EXPECT_THROW(udiv(5, 0, 8), std::invalid_argument);
  EXPECT_THROW(udiv(256, 1, 8), std::invalid_argument);
  EXPECT_EQ(udiv(255, 1, 8), 255u);
  EXPECT_THROW(udiv(512, 2, 8), std::invalid_argument);
  EXPECT_EQ(udiv(511, 2, 8), 255u);
  EXPECT_THROW(udiv(1, 1, 0), std::invalid_argument);
  EXPECT_THROW(udiv(1, 1, -1), std::invalid_argument);
  EXPECT_THROW(udiv(1, 1, 128), std::invalid_argument);
  EXPECT_THROW(udiv(0, 1, 128), std::invalid_argument);  // quotient fits: only the width is bad
  EXPECT_THROW(udiv(1, 2, 128), std::invalid_argument);
  EXPECT_THROW(udiv(0, 1, 0), std::invalid_argument);
  EXPECT_THROW(udiv(~u128{0}, 1, 127), std::invalid_argument);
  EXPECT_EQ(udiv(0, 7, 1), 0u);
}

// =============================================================================================
// 3. truncate and round_half_up
// =============================================================================================

TEST(FixedRounding, ExhaustiveSmall) {
  Failures f;
  long count = 0;
  for (i64 v = -4096; v <= 4096; ++v) {
    for (int bits = 0; bits <= 8; ++bits) {
      const i128 d = i128{1} << bits;
      const i128 t_exp = floor_div(v, d);
      const i128 r_exp = bits > 0 ? floor_div(v + d / 2, d) : i128{v};
      const i128 t = truncate(v, bits);
      const i128 r = round_half_up(v, bits);
      RPU_CHECK(f, t == t_exp, "truncate(" << v << ", " << bits << ") = " << str(t)
                                           << ", expected " << str(t_exp));
      RPU_CHECK(f, r == r_exp, "round_half_up(" << v << ", " << bits << ") = " << str(r)
                                                << ", expected " << str(r_exp));
      count += 2;
    }
    for (int bits = -8; bits < 0; ++bits) {  // negative bits: exact multiplication
      const i128 exp = i128{v} * (i128{1} << -bits);
      const i128 t = truncate(v, bits);
      const i128 r = round_half_up(v, bits);
      RPU_CHECK(f, t == exp, "truncate(" << v << ", " << bits << ") = " << str(t) << ", expected "
                                         << str(exp));
      RPU_CHECK(f, r == exp, "round_half_up(" << v << ", " << bits << ") = " << str(r)
                                              << ", expected " << str(exp));
      count += 2;
    }
  }
  std::printf("[rounding exhaustive] %ld vectors\n", count);
  EXPECT_EQ(f.n, 0);
}

TEST(FixedRounding, TiesGoUp) {
  // x.5 rounds toward +∞ for either sign.
  EXPECT_EQ(round_half_up(1, 1), 1);    //  0.5 →  1
  EXPECT_EQ(round_half_up(-1, 1), 0);   // -0.5 →  0
  EXPECT_EQ(round_half_up(3, 1), 2);    //  1.5 →  2
  EXPECT_EQ(round_half_up(-3, 1), -1);  // -1.5 → -1
  EXPECT_EQ(round_half_up(-5, 2), -1);  // -1.25 → -1
  EXPECT_EQ(round_half_up(-6, 2), -1);  // -1.5  → -1
  EXPECT_EQ(round_half_up(-7, 2), -2);  // -1.75 → -2
  EXPECT_EQ(truncate(-1, 8), -1);       // floor, not toward zero
  EXPECT_EQ(truncate(-256, 8), -1);
  EXPECT_EQ(truncate(-257, 8), -2);
}

TEST(FixedRounding, LargeValues) {
  Failures f;
  long count = 0;
  const i128 p120 = i128{1} << 120;
  std::vector<i128> values;
  for (i128 base : {p120, -p120, p120 - 1, -p120 + 1, i128{1} << 125, -(i128{1} << 125)})
    for (i128 off = -3; off <= 3; ++off) values.push_back(base + off);
  // A value with a tie at every scale: 2^120 + 2^(bits-1) patterns.
  for (int k = 0; k < 120; k += 7) {
    values.push_back(p120 + (i128{1} << k));
    values.push_back(-p120 - (i128{1} << k));
    values.push_back(-p120 + (i128{1} << k));
  }
  for (i128 v : values) {
    for (int bits : {0, 1, 2, 7, 31, 32, 63, 64, 65, 100, 119, 120, 121, 125}) {
      const i128 d = i128{1} << bits;
      const i128 t_exp = floor_div(v, d);
      const i128 r_exp = bits > 0 ? floor_div(v + d / 2, d) : v;  // |v| + d/2 < 2^127
      const i128 t = truncate(v, bits);
      const i128 r = round_half_up(v, bits);
      RPU_CHECK(f, t == t_exp, "truncate(" << str(v) << ", " << bits << ") = " << str(t)
                                           << ", expected " << str(t_exp));
      RPU_CHECK(f, r == r_exp, "round_half_up(" << str(v) << ", " << bits << ") = " << str(r)
                                                << ", expected " << str(r_exp));
      count += 2;
    }
  }
  // Negative bits on large values (exact, staying below 2^127 in magnitude).
  EXPECT_EQ(truncate(p120, -6), i128{1} << 126);
  EXPECT_EQ(truncate(-p120, -6), -(i128{1} << 126));
  EXPECT_EQ(round_half_up(-p120 - 1, -3), -(i128{1} << 123) - 8);
  std::printf("[rounding large] %ld vectors\n", count);
  EXPECT_EQ(f.n, 0);
}

// =============================================================================================
// 4. saturate, saturate_unsigned, fits_*, max_/min_signed
// =============================================================================================

TEST(FixedSaturate, ExhaustiveSmall) {
  Failures f;
  long count = 0;
  for (int w = 1; w <= 12; ++w) {
    const i64 lo = -(i64{1} << (w - 1)), hi = (i64{1} << (w - 1)) - 1;
    const i64 uhi = (i64{1} << w) - 1;
    RPU_CHECK(f, max_signed(w) == hi, "max_signed(" << w << ") = " << str(max_signed(w)));
    RPU_CHECK(f, min_signed(w) == lo, "min_signed(" << w << ") = " << str(min_signed(w)));
    RPU_CHECK(f, max_unsigned(w) == static_cast<u128>(uhi),
              "max_unsigned(" << w << ") = " << str(max_unsigned(w)));
    Overflow sticky_s, sticky_u;  // carried across the whole sweep
    bool any_s = false, any_u = false;
    for (i64 v = -8192; v <= 8192; ++v) {
      // Signed.
      const i64 s_exp = std::clamp(v, lo, hi);
      const bool s_clamped = s_exp != v;
      Overflow o;
      const i128 s = saturate(v, w, o);
      RPU_CHECK(f, s == s_exp, "saturate(" << v << ", " << w << ") = " << str(s) << ", expected "
                                           << s_exp);
      RPU_CHECK(f, o.flag == s_clamped, "saturate(" << v << ", " << w << ") overflow flag "
                                                    << o.flag << ", expected " << s_clamped);
      Overflow already{true};
      (void)saturate(v, w, already);
      RPU_CHECK(f, already.flag, "saturate(" << v << ", " << w << ") cleared a set flag");
      (void)saturate(v, w, sticky_s);
      any_s = any_s || s_clamped;
      RPU_CHECK(f, sticky_s.flag == any_s, "saturate sticky flag at v=" << v << ", w=" << w
                                                                        << ": " << sticky_s.flag);
      RPU_CHECK(f, fits_signed(v, w) == !s_clamped,
                "fits_signed(" << v << ", " << w << ") = " << fits_signed(v, w));

      // Unsigned.
      const i64 u_exp = std::clamp(v, i64{0}, uhi);
      const bool u_clamped = u_exp != v;
      Overflow ou;
      const i128 u = saturate_unsigned(v, w, ou);
      RPU_CHECK(f, u == u_exp, "saturate_unsigned(" << v << ", " << w << ") = " << str(u)
                                                    << ", expected " << u_exp);
      RPU_CHECK(f, ou.flag == u_clamped, "saturate_unsigned(" << v << ", " << w << ") flag "
                                                              << ou.flag << ", expected "
                                                              << u_clamped);
      Overflow already_u{true};
      (void)saturate_unsigned(v, w, already_u);
      RPU_CHECK(f, already_u.flag, "saturate_unsigned(" << v << ", " << w << ") cleared a set flag");
      (void)saturate_unsigned(v, w, sticky_u);
      any_u = any_u || u_clamped;
      RPU_CHECK(f, sticky_u.flag == any_u, "saturate_unsigned sticky flag at v=" << v << ", w="
                                                                                 << w);
      if (v >= 0) {
        RPU_CHECK(f, fits_unsigned(static_cast<u128>(v), w) == (v <= uhi),
                  "fits_unsigned(" << v << ", " << w << ")");
      }
      count += 1;
    }
    EXPECT_TRUE(sticky_s.flag && sticky_u.flag);  // the sweep always leaves the range
  }
  std::printf("[saturate exhaustive] widths 1..12: %ld values (x signed+unsigned+fits)\n", count);
  EXPECT_EQ(f.n, 0);
}

TEST(FixedSaturate, WideEdges) {
  Failures f;
  long count = 0;
  for (int w : {63, 64, 65, 120, 126, 127}) {
    const i128 hi = (i128{1} << (w - 1)) - 1, lo = -hi - 1;
    const u128 uhi = pow2(w) - 1;  // w ≤ 127
    EXPECT_EQ(max_signed(w), hi) << w;
    EXPECT_EQ(min_signed(w), lo) << w;
    EXPECT_EQ(max_unsigned(w), uhi) << w;
    std::vector<i128> vs;
    for (i128 base : {hi, lo, i128{0}, static_cast<i128>(uhi)})
      for (i128 off = -2; off <= 2; ++off) {
        // Skip anything that would overflow i128 itself (base ± 2 at the i128 edges).
        if (off > 0 && base > kI128Max - off) continue;
        if (off < 0 && base < kI128Min - off) continue;
        vs.push_back(base + off);
      }
    vs.push_back(kI128Max);
    vs.push_back(kI128Min);
    for (i128 v : vs) {
      const i128 s_exp = std::clamp(v, lo, hi);
      Overflow o;
      const i128 s = saturate(v, w, o);
      RPU_CHECK(f, s == s_exp && o.flag == (s_exp != v),
                "saturate(" << str(v) << ", " << w << ") = " << str(s) << " flag " << o.flag
                            << ", expected " << str(s_exp));
      RPU_CHECK(f, fits_signed(v, w) == (s_exp == v), "fits_signed(" << str(v) << ", " << w << ")");
      const i128 u_exp = v < 0 ? 0 : (static_cast<u128>(v) > uhi ? static_cast<i128>(uhi) : v);
      Overflow ou;
      const i128 u = saturate_unsigned(v, w, ou);
      RPU_CHECK(f, u == u_exp && ou.flag == (u_exp != v),
                "saturate_unsigned(" << str(v) << ", " << w << ") = " << str(u) << " flag "
                                     << ou.flag << ", expected " << str(u_exp));
      if (v >= 0) {
        RPU_CHECK(f, fits_unsigned(static_cast<u128>(v), w) == (static_cast<u128>(v) <= uhi),
                  "fits_unsigned(" << str(v) << ", " << w << ")");
      }
      ++count;
    }
  }
  EXPECT_EQ(max_signed(64), std::numeric_limits<i64>::max());
  EXPECT_EQ(min_signed(64), std::numeric_limits<i64>::min());
  EXPECT_EQ(max_unsigned(64), std::numeric_limits<u64>::max());
  EXPECT_EQ(max_signed(127), (i128{1} << 126) - 1);
  EXPECT_TRUE(fits_unsigned(~u128{0}, 128));
  EXPECT_FALSE(fits_unsigned(~u128{0}, 127));
  std::printf("[saturate edges] %ld vectors\n", count);
  EXPECT_EQ(f.n, 0);
}

// =============================================================================================
// 5. bit_length
// =============================================================================================

TEST(FixedBitLength, AllSixteenBitAndPowersOfTwo) {
  Failures f;
  long count = 0;
  for (u64 v = 0; v < (u64{1} << 16); ++v) {
    const int exp = ref_bit_length(v);
    RPU_CHECK(f, bit_length(v) == exp, "bit_length(" << v << ") = " << bit_length(v)
                                                     << ", expected " << exp);
    ++count;
  }
  for (int k = 0; k <= 127; ++k) {
    RPU_CHECK(f, bit_length(pow2(k)) == k + 1, "bit_length(2^" << k << ") = "
                                                               << bit_length(pow2(k)));
    RPU_CHECK(f, bit_length(pow2(k) - 1) == k, "bit_length(2^" << k << " - 1) = "
                                                               << bit_length(pow2(k) - 1));
    if (k >= 1)
      RPU_CHECK(f, bit_length(pow2(k) + 1) == k + 1, "bit_length(2^" << k << " + 1)");
    count += 3;
  }
  RPU_CHECK(f, bit_length(~u128{0}) == 128, "bit_length(2^128 - 1) = " << bit_length(~u128{0}));
  std::printf("[bit_length] %ld vectors\n", count);
  EXPECT_EQ(f.n, 0);
}

}  // namespace
}  // namespace rpu::fixed

namespace rpu::fixed {
namespace {

// The fast floor root used by the model and the hardware's digit-by-digit recurrence agree
// everywhere: exhaustively to 2^20 and on seeded random values of every width to 126 bits.
TEST(FixedIsqrt, FastPathEqualsDigitByDigit) {
  for (u64 x = 0; x < (u64{1} << 20); ++x) ASSERT_EQ(isqrt(x, 20), isqrt_digits(x, 20)) << x;
  std::mt19937_64 rng(rpu::test::seed(20261121));
  for (int trial = 0; trial < 300000; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 126);
    const u128 x = ((static_cast<u128>(rng()) << 64) | rng()) & max_unsigned(w);
    ASSERT_EQ(isqrt(x, w), isqrt_digits(x, w)) << "width " << w;
    // Near perfect squares, where a first guess is most likely to be off by one.
    const u128 r = isqrt_digits(x, w);
    for (int dx = -2; dx <= 2; ++dx) {
      const u128 y = r * r + static_cast<u128>(static_cast<i128>(dx));
      if (dx < 0 && r == 0) continue;
      if (!fits_unsigned(y, w)) continue;
      ASSERT_EQ(isqrt(y, w), isqrt_digits(y, w)) << "width " << w;
    }
  }
}

}  // namespace
}  // namespace rpu::fixed
