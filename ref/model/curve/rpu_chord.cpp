// Twin of rtl/curve/rpu_chord.v | sim/tb/curve/tb_rpu_chord.cpp | sim/tests/curve/rpu_sphere.cmake
#include "model/curve/rpu_chord.h"

#include "model/common/rpu_mul.h"

namespace rpu::ref {

using fixed::truncate;

i128 chord_parameter(const HwParams& p, const SegmentDesc& s, i128 dot_value, Overflow& ovf) {
  const i128 t = truncate(dot_value * s.inv_m, s.inv_s - p.t_frac);
  return fixed::saturate(t, p.t_w(), ovf);
}

int chord_latency(const HwParams& p) {
  return mul_latency(p.inv_w + 1, 2 * p.diff_w() + 2, true) + 3;
}

}  // namespace rpu::ref
