// Twin of rtl/texture/rpu_ray_plane.v | sim/tb/texture/tb_rpu_ray_plane.cpp |
// sim/tests/texture/rpu_texture.cmake
#include "model/texture/rpu_ray_plane.h"

#include "model/common/rpu_mul.h"

namespace rpu::ref {

using fixed::u128;

PlanePoint ray_plane_unit(const HwParams& p, const CameraDesc& cam, const IVec3& vhat) {
  PlanePoint pp;
  const i128 hz = cam.eye.z, vz = vhat.z;
  // t0 = -h_z / v̂_z > 0 needs h_z and v̂_z of opposite signs (neither zero).
  if (vz == 0 || hz == 0 || (hz > 0) == (vz > 0)) return pp;
  const u128 num = static_cast<u128>(hz < 0 ? -hz : hz) << p.dir_frac;
  const u128 den = static_cast<u128>(vz < 0 ? -vz : vz);
  const int qw = p.coord_w + 1;  // t0 < 2^(CW+1) LSB, or the hit is beyond every texture
  if ((num >> qw) >= den) return pp;
  const i128 t0 = static_cast<i128>(fixed::udiv(num, den, qw));
  const WVec3 h = widen(cam.eye);
  WVec3 p0 = h + scale_truncate(widen(vhat), t0, p.dir_frac);
  p0.z = 0;
  if (!fixed::fits_signed(p0.x, p.coord_w) || !fixed::fits_signed(p0.y, p.coord_w)) return pp;
  pp.valid = true;
  pp.p0 = p0;
  pp.depth = dot(p0 - h, widen(cam.w));
  return pp;
}

int ray_plane_latency(const HwParams& p) {
  return p.coord_w + 5 + mul_latency(p.ray_point_w(), p.dir_w(), true) +
         mul_latency(p.diff_w(), p.edge_w(), true);
}

}  // namespace rpu::ref
