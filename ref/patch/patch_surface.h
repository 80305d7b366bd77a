// Evaluation of the parametric patches of docs/algorithms.md §4 (seed 003): Bézier (Bernstein / de
// Casteljau), B-spline (de Boor) and NURBS (rational de Boor), with first derivatives. The
// parameter domain of every patch is normalised to [0, 1]² (B-spline/NURBS knots are mapped
// linearly from [knots[deg], knots[size]]), so the preliminary map and the refiners treat every
// type alike.
#pragma once

#include <array>
#include <vector>

#include "common/limits.h"
#include "common/vec3.h"
#include "scene/scene.h"

namespace rpu::patch {

inline constexpr int kMaxPatchDegree = limits::kMaxPatchDegree;

// B-spline helpers on a knot vector (exposed for the tests). `find_knot_span`: the index k with
// knots[k] <= t < knots[k+1] within [knots[degree], knots[size]] (the last non-empty span at the
// upper end). `bspline_basis`: the degree+1 non-zero basis functions N_{span-degree..span} at t
// and their first derivatives (Cox–de Boor).
int find_knot_span(const std::vector<double>& knots, int degree, int size, double t);
void bspline_basis(const std::vector<double>& knots, int degree, int span, double t, double* n,
                   double* dn);

// A point of the surface and its partial derivatives with respect to the normalised u and v.
struct SurfacePoint {
  Vec3 p, du, dv;
};

// Homogeneous form (NURBS: (w·x, w·y, w·z, w); other types w = 1) and its derivatives, for the
// projected Newton + Cramer refiner (eqs 10-13).
struct HomogeneousPoint {
  double hx = 0, hy = 0, hz = 0, w = 1;
  double hx_u = 0, hy_u = 0, hz_u = 0, w_u = 0;
  double hx_v = 0, hy_v = 0, hz_v = 0, w_v = 0;
};

// A patch prepared for evaluation (knot spans, Bézier coefficients): built once per scene.
class PatchSurface {
 public:
  explicit PatchSurface(const scene::Patch& patch);
  const scene::Patch& patch() const { return patch_; }
  Vec3 point(double u, double v) const;             // u, v in [0, 1] (clamped)
  SurfacePoint evaluate(double u, double v) const;  // point and first derivatives
  HomogeneousPoint homogeneous(double u, double v) const;
  bool rational() const { return rational_; }
  // Closed directions: the first and the last control row (closed_u) or column (closed_v)
  // coincide, weights included, so the clamped surface meets itself along u = 0 ≡ 1 (v = 0 ≡ 1).
  // The refiners wrap the parameter there instead of clamping it.
  bool closed_u() const { return closed_u_; }
  bool closed_v() const { return closed_v_; }
  // Knots mapped to [0, 1] (empty for Bézier): the parameter values where the surface may lose
  // smoothness.
  const std::vector<double>& knots_u() const { return ku_; }
  const std::vector<double>& knots_v() const { return kv_; }

 private:
  scene::Patch patch_;
  std::vector<double> ku_, kv_;  // knots mapped to [0, 1]
  bool rational_ = false;        // NURBS
  bool bezier_ = false;          // Bernstein basis, no knots
  bool closed_u_ = false, closed_v_ = false;
  std::vector<std::array<double, 4>> hw_;  // homogeneous control points (w·x, w·y, w·z, w)
};

}  // namespace rpu::patch
