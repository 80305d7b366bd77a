// Twin of rtl/top/rpu_ray_gen.v | sim/tb/top/tb_rpu_ray_gen.cpp | sim/tests/top/rpu_ray_gen.cmake
// Ray generator.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

struct RayGenOut {
  IVec3 v;                // unnormalised direction of the pixel centre, Q(4.FV)
  IVec3 vhat;             // v / |v|, Q(2.FV)
  WVec3 e_left, e_right;  // PVP edge vectors E_left(i), E_left(i+1), Q(4.FE+14)
  WVec3 e_top, e_bottom;  // E_top(j), E_top(j+1), Q(4.FE+14)
};
RayGenOut ray_generator(const HwParams& p, const CameraDesc& cam, int i, int j);
// rpu_ray_gen's latency in cycles at these widths and pixel-index width idx_w (its IdxW; its
// header: the square root, the divider, three rpu_mul groups and three single stages).
int ray_gen_latency(const HwParams& p, int idx_w = 14);

}  // namespace rpu::ref
