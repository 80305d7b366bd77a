// Twin of rtl/top/rpu_top.v | sim/tb/top/tb_rpu_top.cpp | sim/tests/top/rpu_top.cmake
// One curve work item through the whole curve pipeline. The other twins of rpu_top: per
// texture work item rpu_ray_plane.h + rpu_texture.h, per pixel rpu_resolve.h.
#pragma once

#include <cstdint>

#include "model/curve/rpu_sphere.h"
#include "model/surface/rpu_surface_top.h"
#include "model/datapath.h"
#include "model/top/rpu_ray_gen.h"

namespace rpu::ref {

struct PairResult {
  bool hit = false;
  bool overflow = false;
  i128 depth = 0;
  std::uint64_t tau = 0;   // τ_K index
  i128 t = 0;              // chord parameter of the test point
  WVec3 X;                 // the test point
  SearchInterval interval;
};
PairResult process_curve_pair(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                              const SegmentDesc& s);
inline PairResult process_curve_pair(const HwParams& p, const CameraDesc& cam,
                                     const SegmentDesc& s, int i, int j) {
  return process_curve_pair(p, cam, ray_generator(p, cam, i, j), s);
}

// rpu_top built without the surface path (`surfaces` off, Surfaces = 0): its answer to a
// surface item, one cycle after the descriptor stage — no piece, no hit, the overflow bit, and
// primitive 0 (the renderers refuse such scenes up front: require_built_kinds).
inline SurfacePieceResult unbuilt_surface_result() {
  SurfacePieceResult r;
  r.overflow = true;
  return r;
}

}  // namespace rpu::ref
