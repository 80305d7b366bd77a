// Evaluation of the parametric patches of ALGORITHM 4 (seed 003): Bézier (Bernstein / de
// Casteljau), B-spline (de Boor) and NURBS (rational de Boor), with first derivatives. The
// parameter domain of every patch is normalised to [0, 1]² (B-spline/NURBS knots are mapped
// linearly from [knots[deg], knots[size]]), so the preliminary map and the refiners treat every
// type alike.
#pragma once

#include <vector>

#include "common/vec3.h"
#include "scene/scene.h"

namespace rpu::patch {

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

 private:
  scene::Patch patch_;
  // implementation data (the implementer adds what it needs)
  std::vector<double> ku_, kv_;  // knots mapped to [0, 1]
};

}  // namespace rpu::patch
