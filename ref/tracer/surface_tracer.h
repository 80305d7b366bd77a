// Ray tracing vector-described surfaces (docs/algorithms.md §3, docs/surfaces.md) in double
// precision: per pixel-centre ray and surface, the bounding-sphere interval, its pieces, then
// per piece
//   kIterative (`float-ip`): the sign search of the indicator with the model's schedule
//                            (docs/surfaces.md, "The search on a piece"): a first step of
//                            2^surf_n1_first sub-intervals, then 2^n1 per step (seed: 2^n1 at
//                            every step, K = n / n1 steps, as docs/algorithms.md §3 says);
//   kIdeal     (`float`):    the first crossing of the surface — the ellipsoid analytically, the
//                            others by dense sampling of the indicator plus bisection.
// The nearest hit over the pieces and the surfaces wins (equal depth: lower primitive id).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/compiled_scene.h"
#include "scene/surface_geometry.h"
#include "model/hw_params.h"
#include "tracer/float_tracer.h"

namespace rpu::tracer {

// `float` samples the indicator at most this far apart along a piece: the surface's local
// bounding radius / kIdealSamplesPerRadius (and at least kIdealMinSamples intervals per piece).
// A crossing pair closer than that (a ray grazing the surface within about step²/(8·curvature
// radius), a part of the surface thinner than the step: the snail's first turn for φ below about
// 0.13 at the seed's a) can be missed. At the seed's parameters the step is 3.0e-3 local units
// for the relief ellipsoid, 5.9e-3 for the spiral, 2.6e-3 for the snail, 1.4e-3 for the rocket;
// the demo scenes scenes/surf_*.json at 256×256 then differ from 8× denser sampling in 4 of the
// spiral's 8711 hit pixels and in none of the others.
inline constexpr int kIdealSamplesPerRadius = 1024;
inline constexpr int kIdealMinSamples = 64;
// Bisection of `float` stops when the bracket is below this fraction of the piece.
inline constexpr double kIdealBisectionTolerance = 1e-12;

struct SurfaceStats {
  std::uint64_t pairs_tested = 0;  // ray/surface pairs examined
  std::uint64_t pieces = 0;        // pieces of the pairs that met the bounding sphere (the
                                   // hardware's work items; all counted, searched or not)
  std::uint64_t pairs_hit = 0;     // pairs with a hit on some piece
  std::uint64_t evaluations = 0;   // inside tests evaluated (the search of a pair stops at the
                                   // first piece with a hit: pieces are ordered along the ray)
  SurfaceStats& operator+=(const SurfaceStats& o) {
    pairs_tested += o.pairs_tested;
    pieces += o.pieces;
    pairs_hit += o.pairs_hit;
    evaluations += o.evaluations;
    return *this;
  }
};

// The bounding-sphere interval of the local ray o + d·t: roots t1 ≤ t2, t1 clamped to 0 when
// the origin is inside. False when the ray misses the sphere or meets it only behind the origin.
bool surface_interval(const scene::CompiledSurface& s, const Vec3& o, const Vec3& d, double& t1,
                      double& t2);

// The iterative process on the piece pr(τ) = A + (B − A)·τ (local points) with the schedule of
// `schedule` (its n, n1 and surf_n1_first: ref::HwParams::surface_step_bits): τ of the start of
// the final interval, or false when step 1 finds no sign change. `evaluations` (optional) counts
// the inside tests.
bool iterative_piece(const scene::SurfaceGeometry& g, const scene::AzimuthBranch& branch,
                     const Vec3& A, const Vec3& B, const ref::HwParams& schedule, double& tau,
                     std::uint64_t* evaluations = nullptr);

// The ideal first crossing on the same piece: τ of the first sign change of the indicator
// (ellipsoid: the analytic root; others: `samples` equal intervals, then bisection), false when
// there is none. A tangent touch is not a crossing.
bool ideal_piece(const scene::SurfaceGeometry& g, const scene::AzimuthBranch& branch,
                 const Vec3& A, const Vec3& B, int samples, double& tau,
                 std::uint64_t* evaluations = nullptr);

// Sample count of `float` for a piece of local length `length` of a surface of local bounding
// radius `radius`.
int ideal_samples(double length, double radius);

struct SurfaceRayHit {
  bool hit = false;
  double t = 0.0;  // ray parameter of the hit: X = eye + v·t
  Vec3 local;      // the hit in the surface's local frame
};

// One world ray eye + v·t against one surface: the nearest hit over its pieces.
SurfaceRayHit trace_surface(const scene::CompiledSurface& s, const scene::SurfaceGeometry& g,
                            const Vec3& eye, const Vec3& v, Method method,
                            const ref::HwParams& schedule, SurfaceStats* stats = nullptr);

// The surfaces of a scene, prepared once per render (geometry, eye in each local frame).
class SurfaceTracer {
 public:
  SurfaceTracer(const scene::CompiledScene& sc, Method method, int n, int n1, int surf_n1_first);
  bool empty() const { return geometry_.empty(); }
  // The nearest surface hit of pixel (i, j)'s centre ray: its depth (X − h)·W and primitive id
  // (equal depth: lower id). False when no surface is hit.
  bool trace_pixel(int i, int j, double& depth, std::int32_t& primitive, SurfaceStats& stats) const;

 private:
  const scene::CompiledScene* sc_;
  Method method_;
  ref::HwParams schedule_;  // n, n1, surf_n1_first: the search's steps
  std::vector<scene::SurfaceGeometry> geometry_;
};

}  // namespace rpu::tracer
