// Twin of rtl/curve/rpu_capture.v | sim/tb/curve/tb_rpu_capture.cpp |
// sim/tests/curve/rpu_capture.cmake
// Capture unit: the PVP plane-sign test.
#pragma once

#include <array>

#include "model/datapath.h"
#include "model/top/rpu_ray_gen.h"

namespace rpu::ref {

struct CaptureOut {
  bool hit = false;
  bool t_in_range = false;
  i128 depth = 0;  // c = (X - h)·W, Q(.FE) in LSB
  std::array<bool, 4> signs{};  // left, right, top, bottom tests passed
};
CaptureOut capture_unit(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                        const WVec3& X, i128 t);

}  // namespace rpu::ref
