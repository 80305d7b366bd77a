// Twin of rtl/curve/rpu_curve_point.v | sim/tb/curve/tb_rpu_curve_point.cpp |
// sim/tests/curve/rpu_curve_point.cmake
#include "model/curve/rpu_curve_point.h"

#include <algorithm>

#include "model/common/rpu_mul.h"

namespace rpu::ref {

using fixed::truncate;

WVec3 curve_point_unit(const HwParams& p, const SegmentDesc& s, i128 t, i128 g1, i128 g2) {
  const i128 one = i128{1} << p.t_frac;
  // s(t) = p(t) + u_1·g_1·(1-t) + u_2·g_2·t  (seed 000 eq 13 with the closed-form guides).
  const WVec3 pt = widen(s.p1) + scale_truncate(widen(s.d), t, p.t_frac);
  const i128 G1 = truncate(g1 * (one - t), p.t_frac);
  const i128 G2 = truncate(g2 * t, p.t_frac);
  return pt + scale_truncate(widen(s.guide[0].u), G1, p.unit_frac) +
         scale_truncate(widen(s.guide[1].u), G2, p.unit_frac);
}

int curve_point_latency(const HwParams& p) {
  const int gw = p.ray_point_w(), tw = p.t_w(), gkw = p.guide_h_w();
  return std::max(mul_latency(gw, tw + 1, true), mul_latency(gw, tw, true)) +
         mul_latency(p.unit_w(), gkw, true) + 1;
}

}  // namespace rpu::ref
