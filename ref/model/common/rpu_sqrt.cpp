// Twin of rtl/common/rpu_sqrt.v | sim/tb/common/tb_rpu_sqrt.cpp | sim/tests/common/rpu_sqrt.cmake
#include "model/common/rpu_sqrt.h"

namespace rpu::ref {

using fixed::u128;

i128 sqrt_unit(i128 x, int format_w, int sqrt_w, Overflow& ovf) {
  x = fixed::saturate_unsigned(x, format_w, ovf);
  if (sqrt_w == 0 || format_w <= sqrt_w)
    return static_cast<i128>(fixed::isqrt(static_cast<u128>(x), format_w));
  const int s = (format_w - sqrt_w + 1) / 2;  // pre-shift by 2s ≥ format_w - sqrt_w
  const u128 r = fixed::isqrt(static_cast<u128>(x) >> (2 * s), format_w - 2 * s);
  return static_cast<i128>(r << s);
}

}  // namespace rpu::ref
