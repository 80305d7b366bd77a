// The per-pixel refiners of docs/algorithms.md §4 (seed 003): from a start (u0, v0) on one patch,
// find the root of S_x(u, v) = S_y(u, v) = 0 in the ray-aligned frame (eq 1; ray_frame.h).
//   gradient_descent  (Bézier, eq 4):  (u, v) −= h·∇g, g = S_x² + S_y² (eq 2), h fixed per start
//                                      (1 / the Lipschitz constant of ∇g at the start), halved
//                                      when g would increase.
//   steepest_descent  (B-spline, eq 9): walk along the unit descent direction with step h while g
//                                      decreases (point evaluations only); when g would increase,
//                                      h ← h/φ (inverse golden ratio) and the direction is
//                                      recomputed (one evaluation with derivatives).
//   newton_cramer     (NURBS, eqs 10–13): Newton on the projected homogeneous form with Cramer's
//                                      3×3 determinants M, M_u, M_v: (u, v) += (w/M)·(M_u, M_v).
//   newton            (control; Martin's iteration): Newton on (S_x, S_y) with the Cartesian
//                                      Jacobian of the full (rational) evaluation.
// Parameters are clamped to the domain [0, 1]² after every step (wrapped around in a closed
// direction, PatchSurface::closed_u/closed_v). Convergence: the distance of
// the surface point from the ray, sqrt(g), below `tolerance_pixels` of a pixel across the ray at
// the point's own depth (RayFrame::pixel_angle·c); a point behind the eye has not converged.
#pragma once

#include <cstdint>

#include "patch/patch_surface.h"
#include "patch/ray_frame.h"

namespace rpu::patch {

enum class RefineStatus {
  kConverged,       // sqrt(g) below the tolerance
  kLeftDomain,      // pushed against the domain boundary without progress (the ray passes the
                    // patch outside its edge)
  kStalled,         // no descent possible any more with g above the tolerance (the ray passes
                    // the surface: a local minimum of the distance, at a silhouette)
  kIterationLimit,  // the iteration budget ran out
  kSingular,        // Newton: a singular Jacobian / M = 0
};

struct RefineOptions {
  double tolerance_pixels = 1e-2;  // convergence: distance from the ray, pixels at the point
  int max_iterations = 64;         // gradient steps (eq 4) / directions (eq 9)
  int max_newton_iterations = 16;  // Newton-type iterations (quadratic convergence needs few)
  int max_evaluations = 256;       // surface evaluations (steepest descent's point evaluations)
  // Steepest descent: restart h at the linearised line minimum of every new direction instead
  // of keeping the shrunk h (a variant, not in the thesis; docs/patches.md compares both).
  bool steepest_restart_step = false;
};

struct RefineResult {
  RefineStatus status = RefineStatus::kIterationLimit;
  double u = 0, v = 0;
  double depth = 0;     // c = W·(S − eye) at (u, v)
  double distance = 0;  // sqrt(g) at (u, v), world units
  int iterations = 0;
  int evaluations = 0;  // surface evaluations (with or without derivatives)
  bool converged() const { return status == RefineStatus::kConverged; }
};

RefineResult gradient_descent(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                              const RefineOptions& o = {});
RefineResult steepest_descent(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                              const RefineOptions& o = {});
RefineResult newton_cramer(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                           const RefineOptions& o = {});
RefineResult newton(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                    const RefineOptions& o = {});

// Which refiner a method uses for a patch.
enum class Refiner { kGradientDescent, kSteepestDescent, kNewtonCramer, kNewton };
RefineResult refine(Refiner r, const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                    const RefineOptions& o = {});
const char* refiner_name(Refiner r);

}  // namespace rpu::patch
