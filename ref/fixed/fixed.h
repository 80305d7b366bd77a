// The fixed-point layer of the bit-accurate model: plain two's-complement integers with
// explicit widths, and every narrowing, truncation, rounding and saturation a named operation.
// Hardware does exactly these operations (rtl/ mirrors each one); no floating point here.
#pragma once

#include <cstdint>
#include <string>

namespace rpu::fixed {

using i64 = std::int64_t;
using u64 = std::uint64_t;
__extension__ typedef __int128 i128;            // GCC/Clang 128-bit integers
__extension__ typedef unsigned __int128 u128;

// Largest and smallest value of a signed `width`-bit integer (1 ≤ width ≤ 127).
constexpr i128 max_signed(int width) { return (i128{1} << (width - 1)) - 1; }
constexpr i128 min_signed(int width) { return -(i128{1} << (width - 1)); }
constexpr u128 max_unsigned(int width) {
  return width >= 128 ? ~u128{0} : (u128{1} << width) - 1;
}

constexpr bool fits_signed(i128 v, int width) {
  return v >= min_signed(width) && v <= max_signed(width);
}
constexpr bool fits_unsigned(u128 v, int width) { return v <= max_unsigned(width); }

// Number of bits needed to hold v as an unsigned value (0 → 0).
constexpr int bit_length(u128 v) {
  int n = 0;
  while (v) {
    v >>= 1;
    ++n;
  }
  return n;
}

// Sticky overflow flag carried by a pair through the datapath: any saturation sets it, so that
// overflow is never silent. Hardware carries the same bit.
struct Overflow {
  bool flag = false;
};

// Clamp to a signed `width`-bit range, recording whether clamping happened.
constexpr i128 saturate(i128 v, int width, Overflow& ovf) {
  if (v > max_signed(width)) {
    ovf.flag = true;
    return max_signed(width);
  }
  if (v < min_signed(width)) {
    ovf.flag = true;
    return min_signed(width);
  }
  return v;
}

// Clamp to [0, 2^width - 1].
constexpr i128 saturate_unsigned(i128 v, int width, Overflow& ovf) {
  if (v < 0) {
    ovf.flag = true;
    return 0;
  }
  if (static_cast<u128>(v) > max_unsigned(width)) {
    ovf.flag = true;
    return static_cast<i128>(max_unsigned(width));
  }
  return v;
}

// Drop `bits` fraction bits, rounding toward -∞ (an arithmetic right shift: what a hardware
// truncation of the low bits does). bits may be 0; negative bits shift left (exact).
constexpr i128 truncate(i128 v, int bits) { return bits >= 0 ? v >> bits : v * (i128{1} << -bits); }

// Drop `bits` fraction bits, rounding to nearest with ties toward +∞ (add half, then shift).
constexpr i128 round_half_up(i128 v, int bits) {
  return bits > 0 ? (v + (i128{1} << (bits - 1))) >> bits : truncate(v, bits);
}

// Floor square root of an unsigned integer of at most `width` bits (1 ≤ width ≤ 126). The
// hardware (rtl/common/rpu_sqrt) takes two radicand bits per stage, ceil(width/2) stages, each one
// add or subtract chosen by the sign of the partial remainder (non-restoring); it produces the
// same root digits as the restoring compare-and-subtract recurrence that isqrt_digits writes
// out literally. floor(√x) is a unique integer, so `isqrt` may reach it faster: below 2^64 it
// refines a first guess with exact integer comparisons (r² ≤ x < (r+1)²). Both are tested
// equal (tests/test_fixed.cpp), and the RTL against them (sim/tests/common/rpu_sqrt.cmake).
u128 isqrt(u128 x, int width);
u128 isqrt_digits(u128 x, int width);

// Floor quotient of unsigned integers, restoring division one quotient bit per step, as the
// hardware's divider pipeline: `quotient_width` stages. The divisor must be non-zero and the
// true quotient must fit in quotient_width bits (callers guarantee it by format; checked).
u128 udiv(u128 dividend, u128 divisor, int quotient_width);

// Decimal text of a 128-bit integer (reports and test failures; the standard library has none).
std::string to_decimal(i128 v);

}  // namespace rpu::fixed
