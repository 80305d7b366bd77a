// Twin of rtl/surface/rpu_surface_setup.v
// Surface setup unit: one work item is (pixel ray, surface, piece index). The bounding-sphere
// interval [A, B] (the curves' sphere unit with d = 0), A and B in the surface's local frame, the
// cuts at the range boundaries (docs/surfaces.md, "Ranges"), and the requested piece as its own
// search interval in both frames, with the piece's azimuth branch for the spiral and snail.
#pragma once

#include "model/curve/rpu_sphere.h"
#include "model/datapath.h"

namespace rpu::ref {

// Work items per (ray, surface) pair the host issues: 3 for the spiral and snail (two cutting
// planes), 1 for the slab types. Pieces the ray does not produce come back not valid.
int surface_piece_items(scene::SurfaceType t);

struct SurfaceSetupOut {
  bool valid = false;      // the sphere is met in front of the eye and piece `index` exists
  int pieces = 0;          // non-empty pieces of this pair (0..3); the valid indices are below it
  SearchInterval sphere;   // the sphere unit: pred_1, A, B (LSB)
  WVec3 la, lb;            // A, B in llsb (LW bits, sat)
  i128 s_lo = 0, s_hi = 0; // the piece along A → B, Q(1.SF), 0 ≤ s_lo < s_hi ≤ 2^SF
  WVec3 A, AB;             // piece start A' = A + floor(AB·s_lo) and B' − A', LSB
  WVec3 lA, lAB;           // the same in llsb
  // Spiral and snail: the piece's azimuth branch. It never crosses the plane x = 0 nor the end
  // plane, so ψ's side of x = 0 and the turns in range are fixed on it.
  bool x_negative = false; // the piece lies in x < 0: ψ ∈ (π, 2π); else ψ ∈ [0, π]
  bool last_turn = false;  // turn full_turns (φ = ψ + 2π·full_turns ≤ phi_max) is in range
};

// World LSB → llsb: floor(M·(X − origin)·2^-to_local_s), each component saturated to LW bits.
WVec3 surface_to_local(const HwParams& p, const SurfaceDesc& s, const WVec3& X, Overflow& ovf);

SurfaceSetupOut surface_setup(const HwParams& p, const IVec3& eye, const IVec3& vhat,
                              const SurfaceDesc& s, int piece, Overflow& ovf);

}  // namespace rpu::ref
