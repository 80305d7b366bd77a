// Twin of rtl/rpu_texture.v | sim/tb/tb_rpu_texture.cpp | sim/tests/rpu_texture.cmake
#include "model/rpu_texture.h"

#include <algorithm>

#include "model/rpu_chord.h"
#include "model/rpu_curve_point.h"
#include "model/rpu_guide.h"

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
  const i128 w = guide_weight(p, o.t);
  o.X = curve_point_unit(p, s, o.t, guide_unit(p, s.guide[0], s.L2, w, ovf),
                         guide_unit(p, s.guide[1], s.L2, w, ovf));
  const WVec3 e = o.X - p0;
  o.pr3 = dot(e, e) <= s.w0_2;
  o.covers = o.pr1 && (o.pr2 || o.pr3);
  return o;
}

}  // namespace rpu::ref
