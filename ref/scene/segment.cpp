#include "scene/segment.h"

#include <cmath>
#include <limits>

namespace rpu::scene {

std::optional<Vec3> unit_direction(const Vec3& v) {
  if (!is_finite(v) || v == Vec3{}) return std::nullopt;
  const double len = length(v);
  if (len > 1e-150 && len < 1e150) return v / len;  // the ordinary case, unchanged
  const double m = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
  const Vec3 w = v / m;
  return w / length(w);
}

std::optional<Segment> make_segment(const Vec3& p1, const Vec3& p2, const Vec3& n1_in,
                                    const Vec3& n2_in, SegmentDefect& defect, int& defect_end) {
  defect = SegmentDefect::kNone;
  defect_end = 0;
  Segment s;
  s.p1 = p1;
  s.p2 = p2;
  s.d = p2 - p1;
  s.L2 = length_squared(s.d);
  s.L = std::sqrt(s.L2);
  if (p1 == p2) {
    defect = SegmentDefect::kRepeatedPoint;
    defect_end = 1;
    return std::nullopt;
  }
  if (!(s.L2 >= std::numeric_limits<double>::min()) || !std::isfinite(s.L2)) {
    defect = SegmentDefect::kLengthOutOfRange;
    defect_end = 1;
    return std::nullopt;
  }
  s.c0 = (p1 + p2) * 0.5;
  s.R = 0.5 * s.L;
  const Vec3 dhat = s.d / s.L;
  const Vec3 normals_in[2] = {n1_in, n2_in};
  const Vec3 ends[2] = {p1, p2};
  for (int k = 0; k < 2; ++k) {
    const std::optional<Vec3> unit = unit_direction(normals_in[k]);
    if (!unit) {
      defect = SegmentDefect::kZeroNormal;
      defect_end = k;
      return std::nullopt;
    }
    const Vec3 n = *unit;
    (k == 0 ? s.n1 : s.n2) = n;
    const double cosine = dot(n, dhat);
    const double sine = length(cross(n, dhat));
    if (sine < kParallelSine) {
      defect = SegmentDefect::kNormalParallelToChord;
      defect_end = k;
      return std::nullopt;
    }
    Guide& g = s.guide[k];
    if (std::fabs(cosine) < kStraightCosine) {
      g.straight = true;
      g.h = std::numeric_limits<double>::infinity();
      s.o[k] = ends[k];
      s.Rref[k] = std::numeric_limits<double>::infinity();
      continue;
    }
    // Centre o_k: the line ends[k] + n·σ meets the bisector plane (r - c0)·d = 0.
    const double sigma = dot(s.c0 - ends[k], s.d) / dot(n, s.d);
    s.o[k] = ends[k] + n * sigma;
    s.Rref[k] = std::fabs(sigma);
    const Vec3 vo = s.c0 - s.o[k];
    // vo is perpendicular to d by construction; remove the rounding residue along d.
    const Vec3 vo_perp = vo - dhat * dot(vo, dhat);
    g.h = length(vo_perp);
    if (!(g.h > 0.0) || !std::isfinite(g.h)) {
      g.straight = true;
      g.h = std::numeric_limits<double>::infinity();
      continue;
    }
    g.u = vo_perp / g.h;
  }
  return s;
}

double guide_offset(const Guide& g, double L2, double t) {
  if (g.straight) return 0.0;
  const double q = std::fmax(0.0, L2 * t * (1.0 - t));
  return q / (std::sqrt(g.h * g.h + q) + g.h);
}

Vec3 curve_point(const Segment& s, double t) {
  const double g1 = guide_offset(s.guide[0], s.L2, t);
  const double g2 = guide_offset(s.guide[1], s.L2, t);
  // p(t) as p1·(1-t) + p2·t so that s(0) = p1 and s(1) = p2 exactly.
  return s.p1 * (1.0 - t) + s.p2 * t + s.guide[0].u * (g1 * (1.0 - t)) + s.guide[1].u * (g2 * t);
}

Vec3 curve_tangent(const Segment& s, double t) {
  Vec3 tangent = s.d;
  const double w[2] = {1.0 - t, t}, dw[2] = {-1.0, 1.0};
  for (int k = 0; k < 2; ++k) {
    const Guide& g = s.guide[k];
    if (g.straight) continue;
    const double q = std::fmax(0.0, s.L2 * t * (1.0 - t));
    const double dg = s.L2 * (1.0 - 2.0 * t) / (2.0 * std::sqrt(g.h * g.h + q));
    tangent += g.u * (dg * w[k] + guide_offset(g, s.L2, t) * dw[k]);
  }
  return tangent;
}

}  // namespace rpu::scene
