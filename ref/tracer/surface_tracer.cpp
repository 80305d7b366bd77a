#include "tracer/surface_tracer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tracer/sphere_interval.h"

namespace rpu::tracer {

using scene::AzimuthBranch;
using scene::CompiledSurface;
using scene::SurfaceGeometry;
using scene::SurfacePiece;
using scene::SurfaceType;

bool surface_interval(const CompiledSurface& s, const Vec3& o, const Vec3& d, double& t1,
                      double& t2) {
  return sphere_interval(o, d, s.local_centre, s.local_radius, t1, t2);
}

bool iterative_piece(const SurfaceGeometry& g, const AzimuthBranch& branch, const Vec3& A,
                     const Vec3& B, const ref::HwParams& schedule, double& tau,
                     std::uint64_t* evaluations) {
  const Vec3 D = B - A;
  std::uint64_t evals = 0;
  const auto inside = [&](double t) {
    ++evals;
    return g.inside(A + D * t, branch);
  };
  std::array<bool, (1 << ref::hw_range::surf_n1_first_max) + 1> s{};
  bool s_lo = inside(0.0), s_hi = inside(1.0);
  tau = 0.0;
  bool found = true;
  int done = 0;  // bits of τ fixed so far
  for (int k = 1; k <= schedule.surface_steps(); ++k) {
    const int bits = schedule.surface_step_bits(k);
    const int J = 1 << bits;
    done += bits;
    const double delta = std::ldexp(1.0, -done);
    s[0] = s_lo;
    s[J] = s_hi;
    for (int j = 1; j < J; ++j) s[j] = inside(tau + j * delta);
    int eta = -1;
    for (int j = 0; j < J; ++j)
      if (s[j] != s[j + 1]) {  // the first change, in either direction (docs/surfaces.md)
        eta = j;
        break;
      }
    if (eta < 0) {  // only possible at step 1: later intervals have ends that differ
      found = false;
      break;
    }
    tau += eta * delta;
    s_lo = s[eta];
    s_hi = s[eta + 1];
  }
  if (evaluations) *evaluations += evals;
  return found;
}

namespace {

// The ellipsoid's first crossing in τ ∈ [0, 1]: (x/a)² + (y/b)² + (z/c)² − 1 = ατ² + 2βτ + γ.
// The entry root r1 counts for r1 ∈ [0, 1) and the exit root r2 for r2 ∈ (0, 1] (a point on the
// surface is outside, so an entry at τ = 1 or an exit at τ = 0 changes no sign).
bool ellipsoid_crossing(const scene::SurfaceParams& p, const Vec3& A, const Vec3& B, double& tau) {
  const Vec3 inv{1.0 / p.a, 1.0 / p.b, 1.0 / p.c};
  const Vec3 As{A.x * inv.x, A.y * inv.y, A.z * inv.z};
  const Vec3 D = B - A;
  const Vec3 Ds{D.x * inv.x, D.y * inv.y, D.z * inv.z};
  const double alpha = dot(Ds, Ds), beta = dot(As, Ds), gamma = dot(As, As) - 1.0;
  if (!(alpha > 0.0)) return false;
  const double disc = beta * beta - alpha * gamma;
  if (!(disc > 0.0)) return false;  // no root or a tangent touch
  // Stable roots: q = −(β + sign(β)·√disc), roots q/α and γ/q.
  const double q = -(beta + std::copysign(std::sqrt(disc), beta));
  double r1 = q / alpha, r2 = q != 0.0 ? gamma / q : -r1;
  if (r1 > r2) std::swap(r1, r2);
  if (r1 >= 0.0 && r1 < 1.0) {
    tau = r1;
    return true;
  }
  if (r2 > 0.0 && r2 <= 1.0) {
    tau = r2;
    return true;
  }
  return false;
}

}  // namespace

bool ideal_piece(const SurfaceGeometry& g, const AzimuthBranch& branch, const Vec3& A,
                 const Vec3& B, int samples, double& tau, std::uint64_t* evaluations) {
  if (g.type() == SurfaceType::kEllipsoid) return ellipsoid_crossing(g.params(), A, B, tau);
  const Vec3 D = B - A;
  std::uint64_t evals = 0;
  const auto inside = [&](double t) {
    ++evals;
    return g.inside(A + D * t, branch);
  };
  bool found = false;
  bool prev = inside(0.0);
  for (int k = 1; k <= samples && !found; ++k) {
    const double t = static_cast<double>(k) / samples;
    const bool cur = inside(t);
    if (cur == prev) continue;
    // Bisection of the first bracket: inside(lo) == prev, inside(hi) != prev.
    double lo = static_cast<double>(k - 1) / samples, hi = t;
    while (hi - lo > kIdealBisectionTolerance) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (inside(mid) == prev ? lo : hi) = mid;
    }
    tau = 0.5 * (lo + hi);
    found = true;
  }
  if (evaluations) *evaluations += evals;
  return found;
}

int ideal_samples(double length, double radius) {
  const double step = radius / kIdealSamplesPerRadius;
  const double n = step > 0.0 ? std::ceil(length / step) : 0.0;
  return static_cast<int>(std::clamp(n, static_cast<double>(kIdealMinSamples), 1e7));
}

SurfaceRayHit trace_surface(const CompiledSurface& s, const SurfaceGeometry& g, const Vec3& eye,
                            const Vec3& v, Method method, const ref::HwParams& schedule,
                            SurfaceStats* stats) {
  SurfaceRayHit r;
  SurfaceStats local_stats;
  SurfaceStats& st = stats ? *stats : local_stats;
  ++st.pairs_tested;
  const Vec3 o = s.world_to_local(eye);
  const Vec3 d = s.to_local * v;
  double t1, t2;
  if (!surface_interval(s, o, d, t1, t2)) return r;
  std::array<SurfacePiece, scene::kMaxSurfacePieces> pieces;
  const int count = g.pieces(o, d, t1, t2, pieces);
  st.pieces += static_cast<std::uint64_t>(count);
  // Pieces are disjoint and ordered along the ray: the first one with a hit holds the nearest.
  for (int k = 0; k < count && !r.hit; ++k) {
    const SurfacePiece& pc = pieces[k];
    const Vec3 A = o + d * pc.t0, B = o + d * pc.t1;
    double tau = 0.0;
    const bool hit =
        method == Method::kIterative
            ? iterative_piece(g, pc.branch, A, B, schedule, tau, &st.evaluations)
            : ideal_piece(g, pc.branch, A, B, ideal_samples(length(B - A), s.local_radius), tau,
                          &st.evaluations);
    if (!hit) continue;
    r.hit = true;
    r.t = pc.t0 + (pc.t1 - pc.t0) * tau;
    r.local = A + (B - A) * tau;
  }
  if (r.hit) ++st.pairs_hit;
  return r;
}

SurfaceTracer::SurfaceTracer(const scene::CompiledScene& sc, Method method, int n, int n1,
                             int surf_n1_first)
    : sc_(&sc), method_(method) {
  schedule_.n = n;
  schedule_.n1 = n1;
  schedule_.surf_n1_first = surf_n1_first;
  geometry_.reserve(sc.surfaces.size());
  for (const CompiledSurface& s : sc.surfaces) geometry_.emplace_back(s.surface);
}

bool SurfaceTracer::trace_pixel(int i, int j, double& depth, std::int32_t& primitive,
                                SurfaceStats& stats) const {
  const scene::CameraFrame& cam = sc_->camera;
  const Vec3 v = cam.ray_direction(i, j);
  bool any = false;
  for (size_t k = 0; k < geometry_.size(); ++k) {
    const CompiledSurface& s = sc_->surfaces[k];
    const SurfaceRayHit r = trace_surface(s, geometry_[k], cam.eye, v, method_, schedule_, &stats);
    if (!r.hit) continue;
    const Vec3 X = cam.eye + v * r.t;
    const double c = dot(X - cam.eye, cam.W);  // depth (X − h)·W, as for curves
    if (!any || c < depth || (c == depth && s.primitive < primitive)) {
      depth = c;
      primitive = s.primitive;
      any = true;
    }
  }
  return any;
}

}  // namespace rpu::tracer
