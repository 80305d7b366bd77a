// Twin of rtl/top/rpu_ray_gen.v | sim/tb/top/tb_rpu_ray_gen.cpp | sim/tests/top/rpu_ray_gen.cmake
#include "model/top/rpu_ray_gen.h"

#include <algorithm>

#include "model/common/rpu_mul.h"
#include "model/common/rpu_sqrt.h"

namespace rpu::ref {

using fixed::truncate;
using fixed::u128;

RayGenOut ray_generator(const HwParams& p, const CameraDesc& cam, int i, int j) {
  RayGenOut r;
  // v = v0 + i·dx + j·dy exactly in Q(4.FV+14) (the compiler checked the image corners fit),
  // then the guard bits dropped: Q(4.FV).
  const WVec3 vg = widen(cam.v0) + scale_truncate(widen(cam.dx), i, 0) +
                   scale_truncate(widen(cam.dy), j, 0);
  const WVec3 v = {truncate(vg.x, HwParams::kRayGuard), truncate(vg.y, HwParams::kRayGuard),
                   truncate(vg.z, HwParams::kRayGuard)};
  r.v = {static_cast<i64>(v.x), static_cast<i64>(v.y), static_cast<i64>(v.z)};
  // |v| = floor(sqrt(v·v)), Q(.FV); 1/|v| = floor(2^(2FV+2) / |v|), Q(.FV+2); v̂ = v·(1/|v|).
  Overflow unused;
  const int vv_w = 2 * p.dir_w() + 4;
  const i128 len = sqrt_unit(dot(v, v), vv_w, 0, unused);
  const i128 recip = static_cast<i128>(
      fixed::udiv(u128{1} << (2 * p.dir_frac + 2), static_cast<u128>(len), p.dir_frac + 3));
  const WVec3 vh = scale_truncate(v, recip, p.dir_frac + 2);
  r.vhat = {static_cast<i64>(vh.x), static_cast<i64>(vh.y), static_cast<i64>(vh.z)};
  // Edge vectors, linear in i and j: E_left(i) = el0 - i·σW, E_top(j) = et0 - j·σW.
  const WVec3 el0 = widen(cam.el0), et0 = widen(cam.et0), sw = widen(cam.sw);
  r.e_left = el0 - scale_truncate(sw, i, 0);
  r.e_right = el0 - scale_truncate(sw, i + 1, 0);
  r.e_top = et0 - scale_truncate(sw, j, 0);
  r.e_bottom = et0 - scale_truncate(sw, j + 1, 0);
  return r;
}

int ray_gen_latency(const HwParams& p, int idx_w) {
  const int fv = p.dir_frac, vg_w = HwParams::kDirInt + fv + HwParams::kRayGuard;
  const int v_w = HwParams::kDirInt + fv, quot_w = fv + 3;
  const int l1 = std::max(mul_latency(vg_w, idx_w + 1, true), mul_latency(p.edge_w(), idx_w + 1, true));
  return 2 * fv + 10 + l1 + mul_latency(v_w, v_w, true) + mul_latency(quot_w + 1, v_w, true);
}

}  // namespace rpu::ref
