// The local geometry of a vector-described surface (docs/algorithms.md §3, seed 004,
// docs/surfaces.md): the exact inside test (the indicator the search evaluates), its continuous
// form for normals, the pieces a ray's search interval is cut into at the parameter-range
// boundaries, and the seed's parametric form R(φ, ·) (eqs 2, 3, 5, 6, 7), used by the tests. Double
// precision, for the float backends (`float`, `float-ip`); every function works in the primitive's
// local frame.
#pragma once

#include <array>

#include "common/vec3.h"
#include "scene/surface.h"

namespace rpu::scene {

// A ray's search interval yields at most this many pieces (spiral, snail: two cutting planes).
inline constexpr int kMaxSurfacePieces = 3;

// How the azimuth ψ is measured on a piece of a spiral or snail ray, and which turns are in range
// there (docs/surfaces.md, "Ranges"). A piece never crosses the plane x = 0 or the end plane, so
// both are fixed per piece; a piece end that rounding puts a hair across a plane still gets the
// piece's continuous formula (no sign change can appear at a piece end).
struct AzimuthBranch {
  bool x_negative = false;  // ψ ∈ [π, 2π] (the piece lies in x ≤ 0), else ψ ∈ [0, π]
  int top_turn = 0;         // turns m = 0..top_turn have φ_m = ψ + 2πm within [0, phi_max]
};

// One piece of a ray o + d·t: t ∈ [t0, t1] (t0 < t1).
struct SurfacePiece {
  double t0 = 0.0, t1 = 0.0;
  AzimuthBranch branch;  // spiral, snail only
};

class SurfaceGeometry {
 public:
  SurfaceGeometry(SurfaceType type, const SurfaceParams& p);
  explicit SurfaceGeometry(const Surface& s) : SurfaceGeometry(s.type, s.p) {}

  SurfaceType type() const { return type_; }
  const SurfaceParams& params() const { return p_; }
  // Spiral and snail: the range is φ ∈ [0, phi_max], cut by planes through the y axis.
  bool has_azimuth_range() const {
    return type_ == SurfaceType::kSpiral || type_ == SurfaceType::kSnail;
  }
  // phi_max mod 2π, snapped to 0 within 1e-9 of a whole number of turns (the end plane then is
  // the plane x = 0 itself; no second cut).
  double end_azimuth() const { return end_azimuth_; }

  // The exact inside test (docs/surfaces.md, "The indicators"; points on the surface are
  // outside). ψ = atan2(x, z) in [0, 2π) and the turns in range at that ψ. The slab range of the
  // ellipsoid, relief ellipsoid and rocket is not part of it: the pieces apply it. The rocket's
  // r(ψ, y) continues the fins below y = −c and the cone above y = b + e (negative there).
  bool inside(const Vec3& p) const { return inside(p, branch_at(p)); }
  // The same on a piece: ψ on the piece's side of x = 0, the piece's turns.
  bool inside(const Vec3& p, const AzimuthBranch& b) const;

  // Continuous form F of the indicator (F < 0 ⇔ inside), for gradients:
  //   ellipsoid (x/a)² + (y/b)² + (z/c)² − 1;  relief q² − k²s²;  spiral min over turns of
  //   (u/c)² + (w/b)² − 1;  snail min over turns of √((ρ − R_m)² + y²) − aφ_m;  rocket ρ − r(ψ, y).
  double indicator(const Vec3& p) const { return indicator(p, branch_at(p)); }
  double indicator(const Vec3& p, const AzimuthBranch& b) const;

  // ∇F by central differences of step h (local units), all six samples on p's branch.
  Vec3 gradient(const Vec3& p, double h) const;

  // The branch of a point: its side of x = 0 (x < 0 → x_negative) and the turns in range at its ψ.
  AzimuthBranch branch_at(const Vec3& p) const;

  // The pieces of the ray o + d·t, t ∈ [t_lo, t_hi], in increasing t (docs/surfaces.md):
  // ellipsoid, relief ellipsoid, rocket: the interval clipped to the slab y_min ≤ y ≤ y_max
  // (rocket −c ≤ y ≤ b + e), at most one piece; spiral, snail: cut where the ray crosses the
  // plane x = 0 or the plane through the y axis at azimuth end_azimuth(), at most three.
  // Returns the number of pieces; empty pieces (t1 ≤ t0) are dropped.
  int pieces(const Vec3& o, const Vec3& d, double t_lo, double t_hi,
             std::array<SurfacePiece, kMaxSurfacePieces>& out) const;

  // The seed's parametric point: R(φ, y) for the ellipsoid, relief ellipsoid and rocket (eqs 2,
  // 3, 7), R(φ, γ) for the spiral and snail (eqs 5, 6).
  Vec3 point(double phi, double v) const;
  // The axis term R_1 at the same parameters (the centre of the section through point(φ, v)).
  Vec3 section_centre(double phi, double v) const;

 private:
  // ψ of p on branch b, in [0, π] or [π, 2π].
  static double azimuth_on_branch(const Vec3& p, bool x_negative);
  // Rocket radius r(ψ, y) of eq 7, continued beyond [−c, b + e].
  double rocket_radius(double psi, double y) const;
  // Snail axis distance R_m on turn m at azimuth ψ: aφ_m + 2a(πm(m − 1) + mψ) (eq 6).
  double snail_axis(int m, double psi) const;

  SurfaceType type_;
  SurfaceParams p_;
  double end_azimuth_ = 0.0;
};

// The azimuth ψ = atan2(x, z) of a point, in [0, 2π] (2π only by rounding of a tiny negative x).
double azimuth(const Vec3& p);

}  // namespace rpu::scene
