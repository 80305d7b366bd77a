// Twin of rtl/texture/rpu_texture.v | sim/tb/texture/tb_rpu_texture.cpp |
// sim/tests/texture/rpu_texture.cmake
#include "model/texture/rpu_texture.h"

#include <algorithm>

#include "model/common/rpu_mul.h"
#include "model/curve/rpu_chord.h"
#include "model/curve/rpu_curve_point.h"
#include "model/curve/rpu_guide_pair.h"

namespace rpu::ref {

TextureOut texture_unit(const HwParams& p, const SegmentDesc& s, const WVec3& p0, Overflow& ovf) {
  TextureOut o;
  const WVec3 d = widen(s.d);
  const WVec3 r1 = p0 - widen(s.p1), r2 = r1 - d;  // p0 - p1, p0 - p2
  // pr1: between the planes through p1 and p2 perpendicular to d (seed 001 eqs 7–9).
  const i128 f1 = dot(r1, d);
  o.pr1 = f1 >= 0 && dot(r2, d) <= 0;
  // pr2: round caps at the end points (eq 10).
  o.pr2 = dot(r1, r1) <= s.w0_2 || dot(r2, r2) <= s.w0_2;
  // pr3: the curve point on the guide line through p0 within w_0 (eqs 15–24).
  // t̂ = (p0 - p1)·d / L²; where pr1 fails the value is never used, so f1 is clamped to
  // [0, L²] first (a mux in hardware) and t̂ stays in [0, 1] without saturating.
  o.t = chord_parameter(p, s, std::clamp<i128>(f1, 0, s.L2), ovf);
  const GuidePair g = guide_pair(p, s.guide[0], s.guide[1], s.L2, o.t, ovf);
  o.X = curve_point_unit(p, s, o.t, g.g1, g.g2);
  const WVec3 e = o.X - p0;
  o.pr3 = dot(e, e) <= s.w0_2;
  // The seed's join (eq 25) or the round one (docs/algorithms.md §2).
  o.covers = s.round_join ? (o.pr1 && o.pr3) || o.pr2 : o.pr1 && (o.pr2 || o.pr3);
  return o;
}

int texture_latency(const HwParams& p) {
  const int cw = p.coord_w, r1w = cw + 1, r2w = cw + 2, dw = cw + 1, ew = cw + 4;
  const int lf = std::max(std::max(mul_latency(r1w, dw, true), mul_latency(dw, r2w, true)),
                          std::max(mul_latency(r1w, r1w, true), mul_latency(r2w, r2w, true)));
  return 6 + lf + mul_latency(ew, ew, true) + chord_latency(p) + guide_pair_latency(p) +
         curve_point_latency(p);
}

}  // namespace rpu::ref
