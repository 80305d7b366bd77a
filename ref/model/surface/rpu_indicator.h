// Twin of rtl/surface/rpu_indicator.v
// Indicator unit: the inside bit of one candidate point in the surface's local frame, for every
// primitive type (docs/surfaces.md, "The indicators"), integers only. Angles are binary angles
// (AW bits = one turn) from the CORDIC (rpu_cordic.h): ψ and ρ by vectoring, sines and the
// spiral's section rotation by rotation. Formats: docs/fixed-point.md, "Surfaces".
#pragma once

#include <cstdint>

#include "model/common/rpu_cordic.h"
#include "model/datapath.h"

namespace rpu::ref {

// The CORDIC configuration of the surface path: width HwParams::surf_cordic_w(), AW-bit angles,
// AW micro-rotations.
CordicConfig surface_cordic(const HwParams& p);

// What the unit computed, for testbenches and tests.
struct IndicatorTrace {
  std::uint64_t angle = 0;  // ψ = atan2(x, z) (spiral, snail, rocket) or φ = atan2(x/a, z/c)
                            // (relief), AW bits
  i128 rho = 0;             // ρ (spiral, snail, rocket), llsb
  i128 lhs = 0, rhs = 0;    // the comparison of the single-test types: inside ⇔ lhs < rhs
                            // (relief also needs rhs > 0 through s² > 0)
  unsigned turn_enable = 0; // spiral, snail: lanes m in range (bit m)
  unsigned turn_inside = 0; // spiral, snail: enabled lanes whose section holds the point
};

// The azimuth ψ unwrapped onto the piece's branch (AW + 2 signed bits): on x ≥ 0 (ψ ∈ [0, π]) a
// ψ in the last quarter turn is ψ − 2^AW (just below 0); on x < 0 a ψ in the first quarter turn is
// ψ + 2^AW (just above a full turn). Rounding near the plane x = 0 then cannot jump a turn.
i64 unwrap_azimuth(std::uint64_t psi, bool x_negative, int aw);

// inside (true) or outside (false) for the local point l (llsb, LW bits). x_negative and
// last_turn are the piece's azimuth branch (rpu_surface_setup; ignored by the slab types).
bool indicator_unit(const HwParams& p, const SurfaceDesc& s, const WVec3& l, bool x_negative,
                    bool last_turn, Overflow& ovf, IndicatorTrace* trace = nullptr);

}  // namespace rpu::ref
