#include "scene/normals.h"

#include <cmath>
#include <optional>

#include "scene/segment.h"

namespace rpu::scene {
namespace {

Vec3 any_perpendicular(const Vec3& T, bool planar) {
  if (planar) return normalize(Vec3{-T.y, T.x, 0.0});
  const double ax = std::fabs(T.x), ay = std::fabs(T.y), az = std::fabs(T.z);
  Vec3 e{1, 0, 0};
  if (ay < ax && ay <= az) e = {0, 1, 0};
  else if (az < ax && az < ay) e = {0, 0, 1};
  return normalize(cross(T, e));
}

}  // namespace

Vec3 chord_perpendicular(const Vec3& d, bool planar) {
  // The chord's direction first, so that tiny or huge chords keep theirs (segment.h).
  const std::optional<Vec3> t = unit_direction(d);
  return t ? any_perpendicular(*t, planar) : Vec3{};
}

std::vector<Vec3> derive_normals(const std::vector<Vec3>& p, bool closed, bool planar) {
  const size_t n = p.size();
  std::vector<Vec3> normals(n);
  for (size_t i = 0; i < n; ++i) {
    Vec3 prev, next;
    if (closed) {
      prev = p[(i + n - 1) % n];
      next = p[(i + 1) % n];
    } else {
      prev = i > 0 ? p[i - 1] : 2.0 * p[0] - p[1];
      next = i + 1 < n ? p[i + 1] : 2.0 * p[n - 1] - p[n - 2];
    }
    const Vec3 T = next - prev;
    const Vec3 bend = (next - p[i]) + (prev - p[i]);
    const double tt = length_squared(T);
    Vec3 perp = tt > 0.0 ? bend - T * (dot(bend, T) / tt) : bend;
    if (planar) perp.z = 0.0;
    const double scale = std::sqrt(length_squared(next - p[i]) + length_squared(prev - p[i]));
    if (tt > 0.0 && length(perp) > 1e-12 * scale) {
      normals[i] = normalize(perp);
    } else if (tt > 0.0) {
      normals[i] = any_perpendicular(T, planar);
    } else {
      // Degenerate (e.g. a two-point closed curve): fall back to a perpendicular of the chord.
      normals[i] = any_perpendicular(next - p[i], planar);
    }
  }
  return normals;
}

}  // namespace rpu::scene
