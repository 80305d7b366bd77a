#include "fixed/fixed.h"

#include <stdexcept>

namespace rpu::fixed {

namespace {

// Floor square root of a 64-bit value. The double's root is only a first guess (within a few
// units for x < 2^64); the result is fixed by exact integer comparisons, so it is floor(√x)
// exactly, the value the digit-by-digit recurrence (isqrt_digits) produces.
u64 isqrt64(u64 x) {
  u64 r = static_cast<u64>(__builtin_sqrt(static_cast<double>(x)));
  if (r > 0xFFFFFFFFull) r = 0xFFFFFFFFull;  // floor(√x) < 2^32 for x < 2^64
  while (r * r > x) --r;
  while (r < 0xFFFFFFFFull && (r + 1) * (r + 1) <= x) ++r;
  return r;
}

}  // namespace

u128 isqrt_digits(u128 x, int width) {
  if (width < 1 || width > 126) throw std::invalid_argument("isqrt: width out of range");
  if (!fits_unsigned(x, width)) throw std::invalid_argument("isqrt: radicand wider than width");
  const int stages = (width + 1) / 2;
  u128 root = 0, rem = 0;
  for (int s = stages - 1; s >= 0; --s) {
    rem = (rem << 2) | ((x >> (2 * s)) & 3);
    const u128 trial = (root << 2) | 1;
    root <<= 1;
    if (rem >= trial) {
      rem -= trial;
      root |= 1;
    }
  }
  return root;
}

u128 isqrt(u128 x, int width) {
  if (width < 1 || width > 126) throw std::invalid_argument("isqrt: width out of range");
  if (!fits_unsigned(x, width)) throw std::invalid_argument("isqrt: radicand wider than width");
  if ((x >> 64) == 0) return isqrt64(static_cast<u64>(x));
  return isqrt_digits(x, width);
}

u128 udiv(u128 dividend, u128 divisor, int quotient_width) {
  if (divisor == 0) throw std::invalid_argument("udiv: division by zero");
  if (quotient_width < 1 || quotient_width > 127)
    throw std::invalid_argument("udiv: quotient width out of range");
  // The quotient must fit: dividend < divisor · 2^quotient_width.
  if ((dividend >> quotient_width) >= divisor)
    throw std::invalid_argument("udiv: quotient does not fit its width");
  u128 rem = dividend >> quotient_width;  // < divisor
  u128 q = 0;
  for (int s = quotient_width - 1; s >= 0; --s) {
    rem = (rem << 1) | ((dividend >> s) & 1);
    q <<= 1;
    if (rem >= divisor) {
      rem -= divisor;
      q |= 1;
    }
  }
  return q;
}

}  // namespace rpu::fixed

namespace rpu::fixed {

std::string to_decimal(i128 v) {
  if (v == 0) return "0";
  const bool neg = v < 0;
  u128 u = neg ? static_cast<u128>(-(v + 1)) + 1 : static_cast<u128>(v);
  std::string s;
  while (u) {
    s.insert(s.begin(), static_cast<char>('0' + static_cast<int>(u % 10)));
    u /= 10;
  }
  return neg ? "-" + s : s;
}

}  // namespace rpu::fixed
