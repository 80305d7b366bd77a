// The CORDIC twin (ref/model/common/rpu_cordic.h) against libm: the constants, and every result
// within the error bounds derived in docs/fixed-point.md ("CORDIC"): exhaustive over the input
// range at w = 8, edges and random vectors at the default configuration. Prints the measured
// maximum errors beside the bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "test_seed.h"
#include "common/error.h"
#include "model/common/rpu_cordic.h"

namespace {

using rpu::ref::CordicConfig;
using ld = long double;

constexpr ld kPi = 3.141592653589793238462643383279502884L;
constexpr CordicConfig kNarrow{8, 10, 8};
constexpr CordicConfig kDefault{32, 24, 24};

// The bounds of docs/fixed-point.md ("CORDIC"), evaluated in long double. n = iters,
// α_i = atan(2^−i), K_{<i} = Π_{k<i} √(1 + 2^−2k), K = K_{<n}:
//   Ê_i  = √2 Σ_{j=1}^{i−1} Π_{k=j+1}^{i−1} √(1 + 2^−2k)   bound on |v̂_i − u_i| (internal LSB)
//   D(r) = max_{2≤i<n} asin(Ê_i / (K_{<i} 2^G r))          angle of v̂_i vs the exact u_i
//   vectoring angle (LSB of aw):  1/2 + (n−1)(1/2 + 2^−12) 2^−GA + (α_{n−1} + D(r)) 2^aw / 2π
//   vectoring magnitude (LSB):    1/2 + r (1 − cos ψ) + e + κ (r + e),  ψ = α_{n−1} + D(r)
//   rotation, per component:      1/2 + r ψ_rot + e + κ (r + e),
//                                 ψ_rot = (α̂_{n−1} + c + (n−1)(1/2 + 2^−12)) 2π / 2^(aw+GA)
//   with e = Ê_n / (K 2^G), κ = (1/2 + 2^−7) K / 2^KF (relative error of the gain constant),
//   α̂ the integer table and c = max(0, max_i (α̂_i − Σ_{j>i} α̂_j − α̂_{n−1})) its convergence
//   slack (the rounded table may miss the condition α̂_i ≤ Σ_{j>i} α̂_j + α̂_{n−1} by an LSB).
struct Bounds {
  CordicConfig c;
  int g, ga, kf;
  std::vector<ld> e_hat, k_before;  // Ê_i and K_{<i}, i = 0..n
  ld gain = 1, alpha_last = 0, kappa = 0, e_out = 0;
  ld table_last = 0, slack = 0;  // α̂_{n−1} and c, in LSB of 2^−(aw+GA) turn

  explicit Bounds(const CordicConfig& cfg)
      : c(cfg),
        g(rpu::ref::cordic_guard_bits(cfg)),
        ga(rpu::ref::cordic_angle_guard_bits(cfg)),
        kf(rpu::ref::cordic_gain_frac_bits(cfg)) {
    const int n = c.iters;
    std::vector<ld> scale(static_cast<std::size_t>(n));  // √(1 + 2^−2k)
    for (int k = 0; k < n; ++k)
      scale[static_cast<std::size_t>(k)] = std::sqrt(1 + std::ldexp(1.0L, -2 * k));
    for (int i = 0; i <= n; ++i) {
      ld e = 0, kb = 1;
      for (int k = 0; k < i; ++k) kb *= scale[static_cast<std::size_t>(k)];
      for (int j = 1; j <= i - 1; ++j) {
        ld p = std::sqrt(2.0L);
        for (int k = j + 1; k <= i - 1; ++k) p *= scale[static_cast<std::size_t>(k)];
        e += p;
      }
      e_hat.push_back(e);
      k_before.push_back(kb);
    }
    gain = k_before.back();
    alpha_last = std::atan(std::ldexp(1.0L, -(n - 1)));
    kappa = (0.5L + std::ldexp(1.0L, -7)) * gain / std::ldexp(1.0L, kf);
    e_out = e_hat.back() / (gain * std::ldexp(1.0L, g));
    const auto t = rpu::ref::cordic_tables(c);
    table_last = static_cast<ld>(t.atan.back());
    slack = convergence_slack(t.atan);
  }
  static ld convergence_slack(const std::vector<std::uint64_t>& atan) {
    ld c = 0, sum = 0;  // sum = Σ_{j>i} α̂_j
    for (std::size_t i = atan.size(); i-- > 0;) {
      c = std::max(c, static_cast<ld>(atan[i]) - sum - static_cast<ld>(atan.back()));
      sum += static_cast<ld>(atan[i]);
    }
    return c;
  }
  // D(r); a negative value when the bound does not apply (r too small: never for r ≥ 1 here).
  ld angle_noise(ld r) const {
    ld d = 0;
    for (int i = 2; i < c.iters; ++i) {
      const ld s = e_hat[static_cast<std::size_t>(i)] /
                   (k_before[static_cast<std::size_t>(i)] * std::ldexp(1.0L, g) * r);
      if (s >= 1) return -1;
      d = std::max(d, std::asin(s));
    }
    return d;
  }
  ld angle_lsb(ld r) const {
    const ld d = angle_noise(r);
    if (d < 0) return std::ldexp(1.0L, c.aw - 1);  // trivial: half a turn
    return 0.5L + (c.iters - 1) * (0.5L + std::ldexp(1.0L, -12)) * std::ldexp(1.0L, -ga) +
           (alpha_last + d) * std::ldexp(1.0L, c.aw) / (2 * kPi);
  }
  ld magnitude_lsb(ld r) const {
    const ld d = angle_noise(r);
    const ld psi = d < 0 ? kPi : alpha_last + d;
    return 0.5L + r * (1 - std::cos(psi)) + e_out + kappa * (r + e_out);
  }
  ld rotation_lsb(ld r) const {
    const ld psi = (table_last + slack + (c.iters - 1) * (0.5L + std::ldexp(1.0L, -12))) * 2 *
                   kPi / std::ldexp(1.0L, c.aw + ga);
    return 0.5L + r * psi + e_out + kappa * (r + e_out);
  }
};

// atan2(y, x) in LSB of aw, in [0, 2^aw).
ld exact_angle(const CordicConfig& c, ld x, ld y) {
  ld a = std::atan2(y, x) / (2 * kPi);
  if (a < 0) a += 1;
  return a * std::ldexp(1.0L, c.aw);
}
// Distance of two angles modulo a turn, in LSB.
ld angle_distance(const CordicConfig& c, ld a, ld b) {
  const ld turn = std::ldexp(1.0L, c.aw);
  ld d = std::fmod(std::fabs(a - b), turn);
  return std::min(d, turn - d);
}

struct Worst {
  ld err = 0, ratio = 0;  // largest error, largest error / bound
  ld bound_at_err = 0;
  void add(ld e, ld bound) {
    if (e > err) {
      err = e;
      bound_at_err = bound;
    }
    ratio = std::max(ratio, e / bound);
  }
};

// The worst case per band of magnitudes r ∈ [2^(5k), 2^(5k+5)): the angle bound falls as 1/r.
struct Bands {
  std::vector<Worst> band = std::vector<Worst>(8);
  Worst& at(ld r) {
    const int k = std::clamp(static_cast<int>(std::log2(std::max(r, 1.0L)) / 5), 0, 7);
    return band[static_cast<std::size_t>(k)];
  }
};

void report_bands(const char* what, const CordicConfig& c, const Bands& b) {
  for (std::size_t k = 0; k < b.band.size(); ++k)
    if (b.band[k].err > 0 || b.band[k].ratio > 0)
      std::printf("cordic w=%d aw=%d iters=%d %s, r in [2^%zu, 2^%zu): max error %.4Lf LSB "
                  "(bound there %.4Lf), max error/bound %.3Lf\n",
                  c.w, c.aw, c.iters, what, 5 * k, 5 * k + 5, b.band[k].err,
                  b.band[k].bound_at_err, b.band[k].ratio);
}

// One vectoring check; returns false (and reports) outside the bound.
bool check_vectoring(const CordicConfig& c, const Bounds& b, rpu::ref::i64 x, rpu::ref::i64 y,
                     Worst& ang, Worst& mag, Bands* ang_bands = nullptr) {
  const auto p = rpu::ref::cordic_vectoring(c, x, y);
  const ld r = std::sqrt(static_cast<ld>(x) * x + static_cast<ld>(y) * y);
  if (x == 0 && y == 0) {
    EXPECT_EQ(p.mag, 0);
    EXPECT_EQ(p.angle, 0u) << "atan2(0, 0) is defined as 0";
    return p.mag == 0 && p.angle == 0;
  }
  const ld ea = angle_distance(c, static_cast<ld>(p.angle), exact_angle(c, x, y));
  const ld em = std::fabs(static_cast<ld>(p.mag) - r);
  const ld ba = b.angle_lsb(r), bm = b.magnitude_lsb(r);
  ang.add(ea, ba);
  mag.add(em, bm);
  if (ang_bands) ang_bands->at(r).add(ea, ba);
  EXPECT_LT(p.angle, std::uint64_t{1} << c.aw);
  EXPECT_LE(ea, ba) << "x " << x << " y " << y << " angle " << p.angle;
  EXPECT_LE(em, bm) << "x " << x << " y " << y << " mag " << p.mag;
  return ea <= ba && em <= bm;
}

bool check_rotation(const CordicConfig& c, const Bounds& b, rpu::ref::i64 x, rpu::ref::i64 y,
                    std::uint64_t angle, Worst& err) {
  const auto q = rpu::ref::cordic_rotation(c, x, y, angle);
  const ld th = static_cast<ld>(angle) * 2 * kPi / std::ldexp(1.0L, c.aw);
  const ld ex = x * std::cos(th) - y * std::sin(th), ey = x * std::sin(th) + y * std::cos(th);
  const ld r = std::sqrt(static_cast<ld>(x) * x + static_cast<ld>(y) * y);
  const ld e = std::max(std::fabs(q.x - ex), std::fabs(q.y - ey));
  const ld bound = b.rotation_lsb(r);
  err.add(e, bound);
  EXPECT_LE(e, bound) << "x " << x << " y " << y << " angle " << angle << " -> " << q.x << ", "
                      << q.y;
  return e <= bound;
}

void report(const char* what, const CordicConfig& c, const Worst& w, const char* unit) {
  std::printf("cordic w=%d aw=%d iters=%d %s: max error %.4Lf %s (bound there %.4Lf), max "
              "error/bound %.3Lf\n",
              c.w, c.aw, c.iters, what, w.err, unit, w.bound_at_err, w.ratio);
}

TEST(Cordic, RejectsUnsupportedConfigurations) {
  EXPECT_NO_THROW(rpu::ref::cordic_validate(kDefault));
  EXPECT_NO_THROW(rpu::ref::cordic_validate(kNarrow));
  for (const CordicConfig& bad :
       {CordicConfig{5, 24, 8}, CordicConfig{49, 24, 24}, CordicConfig{32, 3, 24},
        CordicConfig{32, 49, 24}, CordicConfig{32, 24, 3}, CordicConfig{32, 24, 49},
        CordicConfig{8, 10, 13}}) {
    EXPECT_THROW(rpu::ref::cordic_validate(bad), rpu::Error);
    EXPECT_THROW(rpu::ref::cordic_vectoring(bad, 1, 1), rpu::Error);
  }
  try {
    rpu::ref::cordic_validate(CordicConfig{8, 10, 13});
  } catch (const rpu::Error& e) {
    EXPECT_STREQ(e.what(), "cordic: iters = 13 is outside [4, 12]");
  }
}

TEST(Cordic, Formats) {
  EXPECT_EQ(rpu::ref::cordic_guard_bits(kDefault), 7);
  EXPECT_EQ(rpu::ref::cordic_angle_guard_bits(kDefault), 7);
  EXPECT_EQ(rpu::ref::cordic_gain_frac_bits(kDefault), 34);
  EXPECT_EQ(rpu::ref::cordic_guard_bits(kNarrow), 5);
  // Pre-rotation + iters + rpu_mul (3 × 2 tiles of 13 × 17 bits: 5; one tile: 2) + rounding.
  EXPECT_EQ(rpu::ref::cordic_latency(kDefault, true), 31);
  EXPECT_EQ(rpu::ref::cordic_latency(kDefault, false), 31);
  EXPECT_EQ(rpu::ref::cordic_latency(kNarrow, true), 12);
  EXPECT_EQ(rpu::ref::cordic_latency(kNarrow, false), 12);
  EXPECT_TRUE(rpu::ref::cordic_in_range(kNarrow, -64, 64));
  EXPECT_FALSE(rpu::ref::cordic_in_range(kNarrow, 65, 0));
  EXPECT_FALSE(rpu::ref::cordic_in_range(kNarrow, 0, -65));
}

// The integer constants against libm: each α_i within 1/2 + 2^−12 LSB of atan(2^−i) · 2^F / 2π,
// the gain constant within 1/2 + 2^−7 of 2^KF / K; the rounded table's convergence slack c is at
// most one LSB and the table reaches a quarter turn (rotation's pre-rotated range).
TEST(Cordic, ConstantsMatchLibm) {
  for (const CordicConfig& c :
       {kNarrow, kDefault, CordicConfig{48, 40, 48}, CordicConfig{6, 4, 4},
        CordicConfig{30, 48, 34}}) {
    const auto t = rpu::ref::cordic_tables(c);
    const int f = c.aw + rpu::ref::cordic_angle_guard_bits(c);
    ASSERT_EQ(t.atan.size(), static_cast<std::size_t>(c.iters));
    ld worst = 0;
    for (int i = 0; i < c.iters; ++i) {
      const ld exact = std::atan(std::ldexp(1.0L, -i)) / (2 * kPi) * std::ldexp(1.0L, f);
      const ld e = std::fabs(static_cast<ld>(t.atan[static_cast<std::size_t>(i)]) - exact);
      worst = std::max(worst, e);
      EXPECT_LE(e, 0.5L + std::ldexp(1.0L, -12)) << "i " << i << " f " << f;
    }
    std::uint64_t sum = 0;
    for (auto a : t.atan) sum += a;
    const ld slack = Bounds::convergence_slack(t.atan);
    EXPECT_LE(slack, 1) << "f " << f;
    EXPECT_GE(sum + t.atan.back(), std::uint64_t{1} << (f - 2));
    const Bounds b(c);
    const ld exact_gain = std::ldexp(1.0L, b.kf) / b.gain;
    EXPECT_LE(std::fabs(static_cast<ld>(t.gain_inv) - exact_gain), 0.5L + std::ldexp(1.0L, -7));
    std::printf("cordic w=%d aw=%d iters=%d: atan table max error %.6Lf LSB of 2^-%d turn, "
                "convergence slack %.0Lf, gain_inv %llu (exact %.4Lf)\n",
                c.w, c.aw, c.iters, worst, f, slack, static_cast<unsigned long long>(t.gain_inv),
                exact_gain);
  }
}

TEST(Cordic, CardinalDirections) {
  const CordicConfig c = kDefault;
  const std::int64_t a = std::int64_t{1} << 29;
  const std::uint64_t q = std::uint64_t{1} << (c.aw - 2);  // a quarter turn
  const auto near = [&](std::uint64_t got, std::uint64_t want) {
    return angle_distance(c, static_cast<ld>(got), static_cast<ld>(want)) <= 1;
  };
  EXPECT_TRUE(near(rpu::ref::cordic_vectoring(c, a, 0).angle, 0));
  EXPECT_TRUE(near(rpu::ref::cordic_vectoring(c, 0, a).angle, q));
  EXPECT_TRUE(near(rpu::ref::cordic_vectoring(c, -a, 0).angle, 2 * q));
  EXPECT_TRUE(near(rpu::ref::cordic_vectoring(c, 0, -a).angle, 3 * q));
  EXPECT_EQ(rpu::ref::cordic_vectoring(c, a, 0).mag, a);
  // A quarter turn is not exact: the micro-rotations leave a residual of up to about
  // atan(2^−(n−1)), i.e. up to r · 2^−23 ≈ 64 LSB here (the rotation bound).
  const auto r = rpu::ref::cordic_rotation(c, a, 0, q);
  const ld bound = Bounds(c).rotation_lsb(static_cast<ld>(a));
  EXPECT_LE(std::abs(r.x), bound);
  EXPECT_LE(std::abs(r.y - a), bound);
  EXPECT_GT(bound, 32);
  EXPECT_LT(bound, 128);
  // Switching configurations between calls (the twin caches one per thread).
  const auto n1 = rpu::ref::cordic_vectoring(kNarrow, 3, 4);
  const auto d1 = rpu::ref::cordic_vectoring(kDefault, 3, 4);
  EXPECT_EQ(rpu::ref::cordic_vectoring(kNarrow, 3, 4).angle, n1.angle);
  EXPECT_EQ(n1.mag, 5);
  EXPECT_EQ(d1.mag, 5);
}

// Every (x, y) with |x|, |y| ≤ 2^(w−2) at w = 8, aw = 10, iters = 8.
TEST(Cordic, VectoringExhaustiveNarrow) {
  const CordicConfig c = kNarrow;
  const Bounds b(c);
  const int lim = 1 << (c.w - 2);
  Worst ang, mag;
  Bands bands;
  long failures = 0;
  for (int x = -lim; x <= lim && failures < 10; ++x)
    for (int y = -lim; y <= lim && failures < 10; ++y)
      if (!check_vectoring(c, b, x, y, ang, mag, &bands)) ++failures;
  report("vectoring angle (exhaustive)", c, ang, "LSB");
  report_bands("vectoring angle (exhaustive)", c, bands);
  report("vectoring magnitude (exhaustive)", c, mag, "LSB");
  EXPECT_EQ(failures, 0);
  EXPECT_GT(ang.err, 0.5L);  // the bound is not vacuous: errors reach past the final rounding
}

// Every (x, y) in range × 64 angles (the quadrant edges and 60 spread ones), and every angle
// for the vectors on a stride-8 grid, at the narrow configuration.
TEST(Cordic, RotationExhaustiveNarrow) {
  const CordicConfig c = kNarrow;
  const Bounds b(c);
  const int lim = 1 << (c.w - 2);
  const std::uint64_t turn = std::uint64_t{1} << c.aw;
  std::vector<std::uint64_t> angles;
  for (std::uint64_t k = 0; k < 4; ++k) angles.push_back(k * turn / 4);
  for (std::uint64_t k = 0; k < 60; ++k) angles.push_back((k * 17 + 3) % turn);
  Worst err;
  long failures = 0;
  for (int x = -lim; x <= lim && failures < 10; ++x)
    for (int y = -lim; y <= lim && failures < 10; ++y)
      for (std::uint64_t a : angles)
        if (!check_rotation(c, b, x, y, a, err)) ++failures;
  for (int x = -lim; x <= lim && failures < 10; x += 8)
    for (int y = -lim; y <= lim && failures < 10; y += 8)
      for (std::uint64_t a = 0; a < turn; ++a)
        if (!check_rotation(c, b, x, y, a, err)) ++failures;
  report("rotation (exhaustive subset)", c, err, "LSB");
  EXPECT_EQ(failures, 0);
}

// Random magnitudes (a random bit length, then random bits) so that small vectors, where the
// rounding of the micro-rotations matters most, are as frequent as large ones.
std::int64_t random_coordinate(std::mt19937_64& rng, int w) {
  const int bits = static_cast<int>(rng() % static_cast<unsigned>(w - 1));  // 0 .. w−2
  const std::int64_t lim = std::int64_t{1} << (w - 2);
  std::int64_t v =
      bits == 0 ? 0 : static_cast<std::int64_t>(rng() & ((std::uint64_t{1} << bits) - 1));
  if (bits == w - 2 && (rng() % 16) == 0) v = lim;  // the range's end
  return (rng() & 1) ? -v : v;
}

std::vector<std::int64_t> edge_coordinates(int w) {
  const std::int64_t lim = std::int64_t{1} << (w - 2);
  return {0, 1, -1, 2, -2, lim, -lim, lim - 1, -lim + 1, lim / 2, -lim / 2, 3, -3};
}

TEST(Cordic, VectoringDefaultRandom) {
  const CordicConfig c = kDefault;
  const Bounds b(c);
  std::mt19937_64 rng(rpu::test::seed(20261121));
  Worst ang, mag, ang_large;
  Bands bands;
  long failures = 0;
  const auto edges = edge_coordinates(c.w);
  for (auto x : edges)
    for (auto y : edges)
      if (!check_vectoring(c, b, x, y, ang, mag, &bands)) ++failures;
  for (long k = 0; k < 100000 && failures < 10; ++k) {
    const std::int64_t x = random_coordinate(rng, c.w), y = random_coordinate(rng, c.w);
    if (!check_vectoring(c, b, x, y, ang, mag, &bands)) ++failures;
  }
  // Large vectors only (r ≥ 2^20): the angle good to about one LSB.
  Worst unused;
  for (long k = 0; k < 100000 && failures < 10; ++k) {
    const std::int64_t lim = std::int64_t{1} << (c.w - 2);
    const std::int64_t x = static_cast<std::int64_t>(rng() % (2 * lim + 1)) - lim;
    const std::int64_t y = static_cast<std::int64_t>(rng() % (2 * lim + 1)) - lim;
    if (static_cast<ld>(x) * x + static_cast<ld>(y) * y < std::ldexp(1.0L, 40)) continue;
    if (!check_vectoring(c, b, x, y, ang_large, unused, &bands)) ++failures;
  }
  report_bands("vectoring angle (all random)", c, bands);
  report("vectoring angle (edges + 1e5 random)", c, ang, "LSB");
  report("vectoring magnitude (edges + 1e5 random)", c, mag, "LSB");
  report("vectoring angle, r >= 2^20 (1e5 random)", c, ang_large, "LSB");
  std::printf("cordic default bounds: angle %.3Lf LSB at r = 2^10, %.3Lf at 2^15, %.3Lf at 2^20, "
              "%.3Lf at 2^23, %.3Lf at 2^30; magnitude %.3Lf LSB at r = 2^30\n",
              b.angle_lsb(std::ldexp(1.0L, 10)), b.angle_lsb(std::ldexp(1.0L, 15)),
              b.angle_lsb(std::ldexp(1.0L, 20)), b.angle_lsb(std::ldexp(1.0L, 23)),
              b.angle_lsb(std::ldexp(1.0L, 30)),
              b.magnitude_lsb(std::ldexp(1.0L, 30)));
  EXPECT_EQ(failures, 0);
  // What the surface model needs: 2^−20 turn (16 LSB) from r = 2^15 on; 1 LSB from 2^23 on.
  EXPECT_LE(b.angle_lsb(std::ldexp(1.0L, 15)), 16);
  EXPECT_LE(b.angle_lsb(std::ldexp(1.0L, 23)), 1);
  EXPECT_LE(b.magnitude_lsb(std::sqrt(2.0L) * std::ldexp(1.0L, 30)), 1);
}

TEST(Cordic, RotationDefaultRandom) {
  const CordicConfig c = kDefault;
  const Bounds b(c);
  std::mt19937_64 rng(rpu::test::seed(20261122));
  Worst err;
  long failures = 0;
  const std::uint64_t turn = std::uint64_t{1} << c.aw;
  const std::vector<std::uint64_t> edge_angles = {0, 1, turn / 4 - 1, turn / 4, turn / 4 + 1,
                                                  turn / 2, 3 * turn / 4 - 1, 3 * turn / 4,
                                                  turn - 1, turn / 8};
  const auto edges = edge_coordinates(c.w);
  for (auto x : edges)
    for (auto y : edges)
      for (auto a : edge_angles)
        if (!check_rotation(c, b, x, y, a, err)) ++failures;
  for (long k = 0; k < 100000 && failures < 10; ++k) {
    const std::int64_t x = random_coordinate(rng, c.w), y = random_coordinate(rng, c.w);
    if (!check_rotation(c, b, x, y, rng() % turn, err)) ++failures;
  }
  report("rotation (edges + 1e5 random)", c, err, "LSB");
  EXPECT_EQ(failures, 0);
}

}  // namespace
