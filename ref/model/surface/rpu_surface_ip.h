// Twin of rtl/surface/rpu_surface_ip.v
// The sign search of the indicator on one piece (docs/surfaces.md, "The search on a piece"): τ is
// an n-bit dyadic index m (τ = m·2^-n). Step k divides the current interval into 2^b_k
// sub-intervals, b_k = HwParams::surface_step_bits(k) (surf_n1_first, then n1, the last step what
// remains of n; seed: n1 at every step), evaluates the candidates τ_{k−1} + j·2^-(b_1+…+b_k),
// j = 0..2^b_k, of which 2^b_k − 1 are new (the ends are the previous interval's), and keeps the
// lowest j whose inside bits differ at j and j + 1. Step 1 without a change is a miss. The RTL
// runs the same schedule in passes of a unit of Indicators indicators (0: 2^n1 − 1)
// (surface_ip_passes), unrolled or iterative: the same arithmetic.
#pragma once

#include <array>
#include <cstdint>

#include "model/datapath.h"
#include "model/surface/rpu_surface_setup.h"

namespace rpu::ref {

// The candidate point pr_local(m) = lA' + floor(lAB'·m·2^-n), llsb (m ∈ [0, 2^n]).
WVec3 surface_candidate(const HwParams& p, const SurfaceSetupOut& piece, std::uint64_t m);

struct SurfaceIpState {
  std::uint64_t tau = 0;   // m of the selected interval's start, n bits
  bool lo_inside = false;  // inside bits of the interval's ends
  bool hi_inside = false;
  int k = 0;               // steps done
  bool miss = false;       // step 1 found no sign change
};
struct SurfaceIpStepTrace {
  std::array<bool, (1 << hw_range::surf_n1_first_max) + 1> inside{};  // s_j, j = 0..2^b_k
  int eta = -1;                    // selected index, −1: none (a miss at step 1)
};

// Step 0: the ends τ = 0 and τ = 1 evaluated.
SurfaceIpState surface_ip_start(const HwParams& p, const SurfaceDesc& s,
                                const SurfaceSetupOut& piece, Overflow& ovf);
// Step k = state.k + 1 (a missed state passes through unchanged).
void surface_ip_step(const HwParams& p, const SurfaceDesc& s, const SurfaceSetupOut& piece,
                     SurfaceIpState& state, Overflow& ovf, SurfaceIpStepTrace* trace = nullptr);
// All HwParams::surface_steps() steps.
SurfaceIpState surface_ip(const HwParams& p, const SurfaceDesc& s, const SurfaceSetupOut& piece,
                          Overflow& ovf);

}  // namespace rpu::ref
