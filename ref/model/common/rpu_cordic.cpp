// Twin of rtl/common/rpu_cordic.v | sim/tb/common/tb_rpu_cordic.cpp |
// sim/tests/common/rpu_cordic.cmake
#include "model/common/rpu_cordic.h"

#include <algorithm>
#include <string>

#include "common/error.h"
#include "model/common/rpu_mul.h"

namespace rpu::ref {

using fixed::u128;

// The helpers live in a named namespace: the unit twins compile as one unity translation unit,
// where anonymous namespaces of different files would share names.
namespace cordic_detail {

// Fraction bits of the elaboration-time arithmetic (the RTL's constant functions use the same).
constexpr int kAtanFrac = 70;  // atan and 2π in radians · 2^70
constexpr int kGainFrac = 62;  // K² and K · 2^62

int ceil_log2(int v) {
  int n = 0;
  while ((1 << n) < v) ++n;
  return n;
}

// atan(2^−i) · 2^70 for i ≥ 1: Σ_k (−1)^k 2^(70−i(2k+1)) / (2k+1), each term floored.
u128 atan_pow2(int i) {
  u128 sum = 0, t = u128{1} << (kAtanFrac - i);
  for (int k = 0; t != 0; ++k, t >>= 2 * i) {
    const u128 term = t / static_cast<u128>(2 * k + 1);
    sum = (k % 2 == 0) ? sum + term : sum - term;
  }
  return sum;
}

// atan(1/m) · 2^70: the same series, x^(2k+1) = 2^70 / m^(2k+1) floored (nested floors of
// exact divisions equal the floor of the whole quotient).
u128 atan_inv(unsigned m) {
  u128 sum = 0, t = (u128{1} << kAtanFrac) / m;
  for (int k = 0; t != 0; ++k, t /= static_cast<u128>(m) * m) {
    const u128 term = t / static_cast<u128>(2 * k + 1);
    sum = (k % 2 == 0) ? sum + term : sum - term;
  }
  return sum;
}

// Sign-extend the low `width` bits (a `width`-bit register of the hardware).
i128 wrap(i128 v, int width) {
  const u128 m = fixed::max_unsigned(width);
  const u128 sign = u128{1} << (width - 1);
  return static_cast<i128>(((static_cast<u128>(v) & m) ^ sign) - sign);
}

// Everything the datapath of one configuration needs, derived once.
struct Unit {
  CordicConfig c{0, 0, 0};
  int g = 0;   // guard bits of x, y
  int ga = 0;  // guard bits of the angle
  int kf = 0;  // fraction bits of gain_inv
  int xw = 0;  // internal x, y width, w + 1 + g (signed)
  int f = 0;   // internal angle width, aw + ga
  CordicTables t;
};

Unit make_unit(const CordicConfig& c) {
  Unit u;
  u.c = c;
  u.g = cordic_guard_bits(c);
  u.ga = cordic_angle_guard_bits(c);
  u.kf = cordic_gain_frac_bits(c);
  u.xw = c.w + 1 + u.g;
  u.f = c.aw + u.ga;
  u.t = cordic_tables(c);
  return u;
}

// The unit of the last configuration used on this thread (the renderer calls the twin millions
// of times with one configuration; the tables take microseconds to compute).
const Unit& unit_for(const CordicConfig& c) {
  thread_local Unit cached;
  thread_local bool valid = false;
  if (!valid || !(cached.c == c)) {
    cordic_validate(c);
    cached = make_unit(c);
    valid = true;
  }
  return cached;
}

// One micro-rotation by ±atan(2^−i), counter-clockwise when `ccw`: x, y wrap at xw bits, the
// angle register z at f bits (modulo a full turn). x·2^−i and y·2^−i are arithmetic shifts
// (floor), as the hardware's sign-extended slices.
struct State {
  i128 x, y;
  u128 z;
};
State micro_rotation(const Unit& u, const State& s, int i, bool ccw) {
  const i128 xs = s.x >> i, ys = s.y >> i;
  const u128 a = u.t.atan[static_cast<std::size_t>(i)];
  return {wrap(ccw ? s.x - ys : s.x + ys, u.xw), wrap(ccw ? s.y + xs : s.y - xs, u.xw),
          (ccw ? s.z - a : s.z + a) & fixed::max_unsigned(u.f)};
}

// Gain compensation of one coordinate: round(v · gain_inv / 2^(g+kf)), ties up (floor of the
// product shifted, plus the first dropped bit), modulo 2^w.
i128 compensate(const Unit& u, i128 product) {
  const int s = u.g + u.kf;
  return wrap((product >> s) + ((product >> (s - 1)) & 1), u.c.w);
}

}  // namespace cordic_detail

int cordic_guard_bits(const CordicConfig& c) { return cordic_detail::ceil_log2(c.iters) + 2; }
int cordic_angle_guard_bits(const CordicConfig& c) {
  return cordic_detail::ceil_log2(c.iters) + 2;
}
int cordic_gain_frac_bits(const CordicConfig& c) { return c.w + 2; }

void cordic_validate(const CordicConfig& c) {
  const auto check = [](const char* name, int v, int lo, int hi) {
    if (v < lo || v > hi)
      throw Error("cordic", std::string(name) + " = " + std::to_string(v) + " is outside [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
  };
  check("w", c.w, 6, 48);
  check("aw", c.aw, 4, 48);
  check("iters", c.iters, 4, std::min(48, c.w + 4));
}

bool cordic_in_range(const CordicConfig& c, i64 x, i64 y) {
  const i64 lim = i64{1} << (c.w - 2);
  return x >= -lim && x <= lim && y >= -lim && y <= lim;
}

CordicTables cordic_tables(const CordicConfig& c) {
  cordic_validate(c);
  const int f = c.aw + cordic_angle_guard_bits(c);
  CordicTables t;
  // 2π · 2^70 = 8 (4 atan(1/5) − atan(1/239)) · 2^70 (Machin).
  const u128 two_pi = 8 * (4 * cordic_detail::atan_inv(5) - cordic_detail::atan_inv(239));
  t.atan.push_back(std::uint64_t{1} << (f - 3));  // atan(1) = 1/8 turn, exactly
  for (int i = 1; i < c.iters; ++i) {
    // round(atan · 2^f / 2π), ties up: floor((2 a 2^f + 2π) / (2 · 2π)).
    const u128 a = cordic_detail::atan_pow2(i) << f;
    t.atan.push_back(static_cast<std::uint64_t>((2 * a + two_pi) / (2 * two_pi)));
  }
  // K² = Π (1 + 2^−2i) at 62 fraction bits (each step floored), K = isqrt(K² · 2^62),
  // gain_inv = round(2^(62+KF) / K), ties up.
  u128 k2 = u128{1} << cordic_detail::kGainFrac;
  for (int i = 0; i < c.iters; ++i) k2 += k2 >> (2 * i);
  const u128 k = fixed::isqrt(k2 << cordic_detail::kGainFrac, 126);
  const int kf = cordic_gain_frac_bits(c);
  const u128 half_scale = u128{1} << (cordic_detail::kGainFrac + kf + 1);
  t.gain_inv = static_cast<std::uint64_t>((half_scale + k) / (2 * k));
  return t;
}

int cordic_latency(const CordicConfig& c, bool vectoring) {
  cordic_validate(c);
  const int g = cordic_guard_bits(c), kf = cordic_gain_frac_bits(c);
  // Pre-rotation, one stage per micro-rotation, the gain product (rpu_mul: unsigned magnitude
  // × KF bits, or signed coordinate × signed KF+1 bits), the rounding stage.
  // Tiles of 13 × 17 bits (rtl/common/rpu_cordic.v, MulChunkA: the adder tree's first level fits
  // 3.5 ns).
  constexpr int kChunkA = 13, kChunkB = 17;
  const int mul = vectoring ? mul_latency(c.w + g, kf, false, kChunkA, kChunkB)
                            : mul_latency(c.w + 1 + g, kf + 1, true, kChunkA, kChunkB);
  return 1 + c.iters + mul + 1;
}

CordicPolar cordic_vectoring(const CordicConfig& c, i64 x, i64 y) {
  using cordic_detail::wrap;
  const cordic_detail::Unit& u = cordic_detail::unit_for(c);
  const int w = c.w;
  const i128 xi = wrap(x, w), yi = wrap(y, w);
  const bool zero = xi == 0 && yi == 0;  // atan2(0, 0) := 0
  // Pre-rotation by a half turn into the right half plane (x ≥ 0): negate both, modulo 2^w;
  // the angle register starts at 1/2 turn, plus half an output LSB so that the final
  // truncation of the GA guard bits rounds to nearest (ties up).
  const bool flip = xi < 0;
  cordic_detail::State s{wrap(flip ? -xi : xi, w) << u.g, wrap(flip ? -yi : yi, w) << u.g,
                         (flip ? u128{1} << (u.f - 1) : 0) | (u128{1} << (u.ga - 1))};
  for (int i = 0; i < c.iters; ++i)
    s = cordic_detail::micro_rotation(u, s, i, s.y < 0);  // drive y to 0
  // x ≥ 0 in range: the multiplier takes its low w + g bits as unsigned.
  const u128 xu = static_cast<u128>(s.x) & fixed::max_unsigned(w + u.g);
  const i128 mag = cordic_detail::compensate(u, static_cast<i128>(xu * u.t.gain_inv));
  CordicPolar out;
  out.mag = static_cast<i64>(static_cast<u128>(mag) & fixed::max_unsigned(w));  // unsigned
  out.angle = zero ? 0 : static_cast<std::uint64_t>(s.z >> u.ga);
  return out;
}

CordicXY cordic_rotation(const CordicConfig& c, i64 x, i64 y, std::uint64_t angle) {
  using cordic_detail::wrap;
  const cordic_detail::Unit& u = cordic_detail::unit_for(c);
  const int w = c.w;
  const i128 xi = wrap(x, w), yi = wrap(y, w);
  const std::uint64_t a = angle & static_cast<std::uint64_t>(fixed::max_unsigned(c.aw));
  // Pre-rotation by a half turn when the angle is in [1/4, 3/4) turn (its top two bits differ):
  // negate x and y (modulo 2^w) and flip the angle's top bit. The remaining angle, as a signed
  // f-bit value, is in [−1/4, 1/4) turn.
  const bool flip = (((a >> (c.aw - 1)) ^ (a >> (c.aw - 2))) & 1) != 0;
  const u128 z0 = static_cast<u128>(a ^ (flip ? std::uint64_t{1} << (c.aw - 1) : 0)) << u.ga;
  cordic_detail::State s{wrap(flip ? -xi : xi, w) << u.g, wrap(flip ? -yi : yi, w) << u.g, z0};
  for (int i = 0; i < c.iters; ++i) {
    const bool z_neg = ((s.z >> (u.f - 1)) & 1) != 0;
    s = cordic_detail::micro_rotation(u, s, i, !z_neg);  // drive the remaining angle to 0
  }
  const i128 k = static_cast<i128>(u.t.gain_inv);
  return {static_cast<i64>(cordic_detail::compensate(u, s.x * k)),
          static_cast<i64>(cordic_detail::compensate(u, s.y * k))};
}

}  // namespace rpu::ref
