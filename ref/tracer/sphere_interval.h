// The ray/sphere interval both float tracers search (curves: the interpolation sphere,
// docs/algorithms.md §1.2 steps 1–2; surfaces: the bounding sphere, docs/surfaces.md).
#pragma once

#include <algorithm>
#include <cmath>

#include "common/vec3.h"

namespace rpu::tracer {

// The roots t1 ≤ t2 of |o + v·t − centre| = radius, t1 clamped to 0 when o is inside. False when
// the ray misses the sphere, meets it only behind o, or v is zero. pred_1 without division:
// (v·q)² ≥ |v|²·(|q|² − R²).
inline bool sphere_interval(const Vec3& o, const Vec3& v, const Vec3& centre, double radius,
                            double& t1, double& t2) {
  const Vec3 q = centre - o;
  const double vq = dot(v, q), vv = dot(v, v);
  if (!(vv > 0.0)) return false;
  const double disc = vq * vq - vv * (dot(q, q) - radius * radius);
  if (disc < 0.0) return false;
  const double root = std::sqrt(disc);
  t2 = (vq + root) / vv;
  if (!(t2 > 0.0)) return false;  // the sphere is behind o
  t1 = std::max(0.0, (vq - root) / vv);
  return true;
}

}  // namespace rpu::tracer
