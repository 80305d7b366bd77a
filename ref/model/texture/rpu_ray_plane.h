// Twin of rtl/texture/rpu_ray_plane.v | sim/tb/texture/tb_rpu_ray_plane.cpp |
// sim/tests/texture/rpu_texture.cmake
// Ray/plane unit of the texture path.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

struct PlanePoint {
  bool valid = false;  // the ray meets z = 0 in front of the eye, within the coordinate range
  WVec3 p0;            // LSB, z = 0
  i128 depth = 0;      // (p0 - h)·W, same format as CaptureOut::depth
};
PlanePoint ray_plane_unit(const HwParams& p, const CameraDesc& cam, const IVec3& vhat);
// rpu_ray_plane's latency in cycles at these widths (its header: two stages, the divider, the
// products v̂·t0, one stage, the depth products, one stage).
int ray_plane_latency(const HwParams& p);

}  // namespace rpu::ref
