// Latency of rtl/surface/rpu_surface_setup.v | sim/tb/surface/tb_rpu_surface_setup.cpp |
// sim/tests/surface/rpu_surface_setup.cmake
#include "model/surface/rpu_surface_setup_latency.h"

#include <algorithm>

#include "model/common/rpu_mul.h"
#include "model/curve/rpu_sphere.h"

namespace rpu::ref {

int surface_setup_latency(const HwParams& p) {
  const int lw = p.surf_w, mw = p.surf_mant_w(), constw = p.surf_const_frac() + 2;
  const int sw = p.surf_cut_frac() + 1;  // the piece parameter s ∈ [0, 1], unsigned
  const int local = mul_latency(p.diff_w(), mw, true);     // (X − origin)_k · M_rk
  const int end_plane = mul_latency(lw, constw, true);         // x·cos, z·sin
  const int piece = std::max(mul_latency(p.diff_w(), sw + 1, true),   // (B − A)_k · s
                             mul_latency(lw + 1, sw + 1, true));      // (lb − la)_k · s
  return sphere_latency(p) + 1 + local + 4 + end_plane + 3 + sw + 2 + piece + 2;
}

}  // namespace rpu::ref
