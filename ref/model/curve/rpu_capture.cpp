// Twin of rtl/curve/rpu_capture.v | sim/tb/curve/tb_rpu_capture.cpp |
// sim/tests/curve/rpu_capture.cmake
#include "model/curve/rpu_capture.h"

namespace rpu::ref {

CaptureOut capture_unit(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                        const WVec3& X, i128 t) {
  CaptureOut c;
  c.t_in_range = t >= 0 && t <= (i128{1} << p.t_frac);
  const WVec3 q = X - widen(cam.eye);
  // Four multiply-subtract sign tests (seed 000 eqs 24–26): left/top edges inclusive.
  c.signs = {dot(q, ray.e_left) >= 0, dot(q, ray.e_right) < 0, dot(q, ray.e_top) >= 0,
             dot(q, ray.e_bottom) < 0};
  c.depth = dot(q, widen(cam.w));
  c.hit = c.t_in_range && c.depth > 0 && c.signs[0] && c.signs[1] && c.signs[2] && c.signs[3];
  return c;
}

}  // namespace rpu::ref
