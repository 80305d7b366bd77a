// Twin of rtl/curve/rpu_sphere.v | sim/tb/curve/tb_rpu_sphere.cpp |
// sim/tests/curve/rpu_sphere.cmake
#include "model/curve/rpu_sphere.h"

#include <algorithm>

#include "model/common/rpu_mul.h"
#include "model/common/rpu_sqrt.h"
#include "model/curve/rpu_chord.h"

namespace rpu::ref {

using fixed::truncate;

SearchInterval sphere_unit(const HwParams& p, const IVec3& eye, const IVec3& vhat,
                           const SegmentDesc& s, Overflow& ovf) {
  SearchInterval si;
  const WVec3 h = widen(eye), v = widen(vhat);
  const WVec3 q = widen(s.c0) - h;                        // LSB, CW+1 bits
  si.tc = truncate(dot(v, q), p.dir_frac);                // LSB
  // The squared distance of c0 from the ray, from the cross product q × v̂ (exact), each
  // component floored to kSphereGuard fraction bits, squared and summed exactly, floored to LSB².
  // Not R² + tc² − q·q: that cancels two numbers of (distance to the eye)² when the camera is
  // far from the segment, and a one-LSB error of tc or of |v̂| then swamps R² (issue 11, item 9).
  const int g = HwParams::kSphereGuard, sh = p.dir_frac - g;
  const WVec3 w = {truncate(q.y * v.z - q.z * v.y, sh), truncate(q.z * v.x - q.x * v.z, sh),
                   truncate(q.x * v.y - q.y * v.x, sh)};  // Q(.G) LSB
  const i128 perp2 = truncate(dot(w, w), 2 * g);           // LSB², < 2^(2CW+4)
  const i128 disc = s.R2 - perp2;                          // LSB², in (−2^(2CW+4), 2^(2CW))
  if (disc < 0) return si;                                // pred_1: the ray misses the sphere
  si.half_chord = sqrt_unit(disc, p.sphere_radicand_w(), p.sqrt_w, ovf);
  const i128 t2 = si.tc + si.half_chord;
  if (t2 <= 0) return si;                                 // the sphere is behind the eye
  const i128 t1 = std::max<i128>(0, si.tc - si.half_chord);  // eye inside: start at the eye
  si.pred1 = true;
  si.A = saturate_vec(h + scale_truncate(v, t1, p.dir_frac), p.coord_w, ovf);
  si.B = saturate_vec(h + scale_truncate(v, t2, p.dir_frac), p.coord_w, ovf);
  si.AB = si.B - si.A;
  const WVec3 d = widen(s.d);
  si.alpha = chord_parameter(p, s, dot(si.A - widen(s.p1), d), ovf);
  si.beta = chord_parameter(p, s, dot(si.AB, d), ovf);
  return si;
}

int sphere_latency(const HwParams& p) {
  const int rad_w = p.sphere_radicand_w();
  const int shift = (p.sqrt_w == 0 || rad_w <= p.sqrt_w) ? 0 : (rad_w - p.sqrt_w + 1) / 2;
  const int wt_w = p.coord_w + 6;  // q × v̂ floored to kSphereGuard fraction bits
  return (rad_w - 2 * shift + 1) / 2 + 9 + mul_latency(p.diff_w(), p.dir_w(), true) +
         mul_latency(wt_w, wt_w, true) + mul_latency(p.dir_w(), p.coord_w + 5, true) +
         mul_latency(p.diff_w(), p.diff_w(), true) + chord_latency(p);
}

}  // namespace rpu::ref
