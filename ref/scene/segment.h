// Per-segment constants and the curve point s(t) of spherical interpolation (docs/algorithms.md
// §1).
#pragma once

#include <optional>
#include <string>

#include "common/vec3.h"

namespace rpu::scene {

// One end's guide: the offset of the curve from the chord is u * g(t) with
// g(t) = sqrt(h² + L²·t·(1-t)) - h (closed form of docs/algorithms.md §1). `straight` means the
// reference sphere's centre is at infinity (n_k·d ≈ 0) and g ≡ 0.
struct Guide {
  Vec3 u;             // u_k = vo_k / |vo_k|, unit, perpendicular to d
  double h = 0.0;     // guide_height h_k = |vo_k| = |c_0 - o_k|
  bool straight = false;
};

struct Segment {
  Vec3 p1, p2;        // end points
  Vec3 n1, n2;        // unit normals at the end points
  Vec3 d;             // p2 - p1
  double L = 0.0;     // |d|
  double L2 = 0.0;    // L²
  Vec3 c0;            // chord midpoint = centre of the interpolation sphere
  double R = 0.0;     // radius of the interpolation sphere, L/2
  Guide guide[2];     // guides of the ends p1 and p2
  Vec3 o[2];          // reference sphere centres (meaningless where straight)
  double Rref[2]{};   // reference sphere radii R_1, R_2 (infinite where straight)
};

// Why a segment cannot be built; the compiler turns these into errors with a JSON path.
// kLengthOutOfRange: the two points differ, but the chord's squared length under- or overflows
// a double (points a few 1e-162 apart), so no segment constant can be computed.
enum class SegmentDefect {
  kNone, kRepeatedPoint, kNormalParallelToChord, kZeroNormal, kLengthOutOfRange };

// The unit vector along v, or std::nullopt when v is zero or not finite. Exactly v / |v| where
// |v|² is an ordinary double; otherwise v is first divided by its largest component, so that
// directions with tiny (subnormal) or huge components keep their direction instead of being
// taken for zero or infinite.
std::optional<Vec3> unit_direction(const Vec3& v);

// |cos| between a normal and the chord below which the reference sphere's centre is taken to be
// at infinity and that end's guide is straight.
inline constexpr double kStraightCosine = 1e-12;
// |sin| between a normal and the chord below which the normal counts as parallel to it (the
// arc plane is undefined): such scenes are rejected.
inline constexpr double kParallelSine = 1e-9;

// Builds the constants of segment (p1, p2) with normals n1, n2 (need not be unit). On a defect
// returns std::nullopt and sets `defect` and `defect_end` (0 for p1, 1 for p2).
std::optional<Segment> make_segment(const Vec3& p1, const Vec3& p2, const Vec3& n1,
                                    const Vec3& n2, SegmentDefect& defect, int& defect_end);

// g_k(t) in the cancellation-free form L²t(1-t) / (sqrt(h² + L²t(1-t)) + h); the argument of the
// square root is clamped at 0 so that t slightly outside [0, 1] (rounding) never yields NaN.
double guide_offset(const Guide& g, double L2, double t);

// s(t) = p(t) + s_11(t)·(1 - t) + s_21(t)·t with s_k1(t) = u_k·g_k(t)  (seed 000, eq 13).
Vec3 curve_point(const Segment& s, double t);

// ds/dt, with g_k'(t) = L²(1 - 2t) / (2·sqrt(h² + L²t(1-t))).
Vec3 curve_tangent(const Segment& s, double t);

// The chord parameter of the plane through x perpendicular to d: (x - p1)·d / L².
inline double chord_parameter(const Segment& s, const Vec3& x) { return dot(x - s.p1, s.d) / s.L2; }

}  // namespace rpu::scene
