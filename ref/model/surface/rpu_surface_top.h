// Twin of rtl/surface/rpu_surface_top.v
// One surface work item (pixel ray, surface, piece) through the surface path: rpu_surface_setup,
// rpu_surface_ip (its candidates through rpu_indicator), then the hit point X = pr(τ_K) in world
// LSB and its depth (X − h)·W in the format of rpu_capture's depth, so that rpu_resolve orders
// surface hits against curves and textures. The pixel-centre ray decides (no pyramid capture).
#pragma once

#include <cstdint>

#include "model/datapath.h"
#include "model/surface/rpu_surface_setup.h"
#include "model/top/rpu_ray_gen.h"

namespace rpu::ref {

struct SurfacePieceResult {
  bool valid = false;     // the piece exists (the IP ran)
  bool hit = false;
  bool overflow = false;  // some value of the work item saturated
  int pieces = 0;         // non-empty pieces of the pair (from the setup unit)
  std::uint64_t tau = 0;  // τ_K index
  WVec3 X;                // hit point, LSB
  i128 depth = 0;         // (X − h)·W, Q(.FE+14) in LSB (rpu_capture's depth)
};
SurfacePieceResult process_surface_piece(const HwParams& p, const CameraDesc& cam,
                                         const IVec3& vhat, const SurfaceDesc& s, int piece);
inline SurfacePieceResult process_surface_piece(const HwParams& p, const CameraDesc& cam,
                                                const SurfaceDesc& s, int i, int j, int piece) {
  return process_surface_piece(p, cam, ray_generator(p, cam, i, j).vhat, s, piece);
}

}  // namespace rpu::ref
