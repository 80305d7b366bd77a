#include "scene/surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rpu::scene {
namespace {

constexpr double kPi = std::numbers::pi;

// Rotation about one axis by `deg` degrees (right-handed).
Mat3 rotation_x(double deg) {
  const double r = deg * kPi / 180.0, c = std::cos(r), s = std::sin(r);
  return {{1, 0, 0, 0, c, -s, 0, s, c}};
}
Mat3 rotation_y(double deg) {
  const double r = deg * kPi / 180.0, c = std::cos(r), s = std::sin(r);
  return {{c, 0, s, 0, 1, 0, -s, 0, c}};
}
Mat3 rotation_z(double deg) {
  const double r = deg * kPi / 180.0, c = std::cos(r), s = std::sin(r);
  return {{c, -s, 0, s, c, 0, 0, 0, 1}};
}

Mat3 product(const Mat3& a, const Mat3& b) {
  Mat3 p;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      p.m[r * 3 + c] = a.m[r * 3] * b.m[c] + a.m[r * 3 + 1] * b.m[3 + c] + a.m[r * 3 + 2] * b.m[6 + c];
  return p;
}

// An axis-aligned box in the local frame: [lo, hi] per axis.
struct Box {
  Vec3 lo, hi;
};

// Largest section scale √(1 − (y/b)²) over y ∈ [y_min, y_max] (eq 2, 3): 1 when the range
// contains the equator y = 0, else its value at the end nearest to it.
double max_section_scale(double b, double y_min, double y_max) {
  if (y_min <= 0.0 && y_max >= 0.0) return 1.0;
  const double y = std::min(std::fabs(y_min), std::fabs(y_max)) / b;
  return std::sqrt(std::max(0.0, 1.0 - y * y));
}

// Snail axis distance R(φ) of eq 6: aφ + 2a·Σ_{i<k}(2πi + m) = aφ + 2a(πk(k − 1) + k·m), with
// k = ⌊φ/2π⌋ and m = φ − 2πk. It is continuous and increasing in φ (R = 2πa·k² at φ = 2πk from
// both sides), so its largest value on [0, φ_max] is R(φ_max).
double snail_axis_distance(double a, double phi) {
  const double k = std::floor(phi / (2.0 * kPi));
  const double m = phi - 2.0 * kPi * k;
  return a * phi + 2.0 * a * (kPi * k * (k - 1.0) + k * m);
}

// Analytic local bounds of every point of the surface within its parameter ranges (and of every
// point its indicator calls inside, docs/surfaces.md).
Box local_bounds(const Surface& s) {
  const SurfaceParams& p = s.p;
  switch (s.type) {
    case SurfaceType::kEllipsoid: {
      // (a·s·sin φ, y, c·s·cos φ), s = √(1 − y²/b²) ≤ s_max (eq 2).
      const double sm = max_section_scale(p.b, p.y_min, p.y_max);
      return {{-p.a * sm, p.y_min, -p.c * sm}, {p.a * sm, p.y_max, p.c * sm}};
    }
    case SurfaceType::kReliefEllipsoid: {
      // (k·a·s·sin φ, y, k·c·s·cos φ) with 0 < k ≤ d + |e| (eq 3).
      const double sm = max_section_scale(p.b, p.y_min, p.y_max) * (std::fabs(p.d) + std::fabs(p.e));
      return {{-p.a * sm, p.y_min, -p.c * sm}, {p.a * sm, p.y_max, p.c * sm}};
    }
    case SurfaceType::kSpiral: {
      // Axis point (R + aφ) at azimuth φ, height kφ; the section offset (radial, axial) is the
      // ellipse point (c cos γ, b sin γ) rotated by −4φ, of length at most max(b, c) (eq 5).
      // R + aφ is linear in φ, so its extreme magnitude is at an end of [0, φ_max].
      const double section = std::max(std::fabs(p.b), std::fabs(p.c));
      const double rho = std::max(std::fabs(p.R), std::fabs(p.R + p.a * p.phi_max)) + section;
      const double y_end = p.k * p.phi_max;
      return {{-rho, std::min(0.0, y_end) - section, -rho},
              {rho, std::max(0.0, y_end) + section, rho}};
    }
    case SurfaceType::kSnail: {
      // Section circle of radius aφ centred at the axis distance R(φ) in the plane y = 0 (eq 6).
      const double r = std::fabs(p.a) * p.phi_max;
      const double rho = std::fabs(snail_axis_distance(p.a, p.phi_max)) + r;
      return {{-rho, -r, -rho}, {rho, r, rho}};
    }
    case SurfaceType::kRocket: {
      // Fins: a + (sin 5φ − 1)·y·d/c with y ∈ [−c, 0] lies in [a, a + 2d]; cylinder a; cone
      // a·(1 − (y − b)/e) ∈ [0, a] (eq 7). y ∈ [−c, b + e].
      const double rho = p.a + 2.0 * std::fabs(p.d);
      return {{-rho, -p.c, -rho}, {rho, p.b + p.e, rho}};
    }
  }
  return {};
}

}  // namespace

const char* surface_type_name(SurfaceType t) {
  switch (t) {
    case SurfaceType::kEllipsoid: return "ellipsoid";
    case SurfaceType::kReliefEllipsoid: return "relief_ellipsoid";
    case SurfaceType::kSpiral: return "spiral";
    case SurfaceType::kSnail: return "snail";
    case SurfaceType::kRocket: return "rocket";
  }
  return "?";
}

SurfaceParams default_surface_params(SurfaceType t) {
  SurfaceParams p;
  switch (t) {
    case SurfaceType::kEllipsoid:  // fig. 1: a = c = 1, b = 2, y ∈ [−b, 0.5·b]
      p.a = 1.0, p.b = 2.0, p.c = 1.0;
      p.y_min = -p.b, p.y_max = 0.5 * p.b;
      break;
    case SurfaceType::kReliefEllipsoid:  // fig. 2: a = 1, b = 2, c = 1.3, d = 1, e = 0.4, y ∈ [−2, 2]
      p.a = 1.0, p.b = 2.0, p.c = 1.3, p.d = 1.0, p.e = 0.4;
      p.y_min = -p.b, p.y_max = p.b;
      break;
    case SurfaceType::kSpiral:  // fig. 3: R = 0.7, k = 0.5, a = 0.2, b = 0.16, c = 0.64, φ ∈ [0, 11]
      p.R = 0.7, p.k = 0.5, p.a = 0.2, p.b = 0.16, p.c = 0.64, p.phi_max = 11.0;
      break;
    case SurfaceType::kSnail:  // fig. 4: a = 0.01, φ ∈ [0, 10π]
      p.a = 0.01, p.phi_max = 10.0 * kPi;
      break;
    case SurfaceType::kRocket:  // fig. 5: a = 0.2, b = 1, c = 0.8, d = 0.2, e = 0.4
      p.a = 0.2, p.b = 1.0, p.c = 0.8, p.d = 0.2, p.e = 0.4;
      break;
  }
  return p;
}

CompiledSurface compile_surface(const Surface& s, int primitive) {
  CompiledSurface c;
  c.surface = s;
  c.primitive = primitive;
  const Vec3& r = s.rotation_deg;
  c.rotation = product(rotation_z(r.z), product(rotation_y(r.y), rotation_x(r.x)));
  c.to_local = c.rotation.transposed();
  for (double& v : c.to_local.m) v /= s.scale;

  // The sphere around the local box: its centre and half-diagonal. The radius is widened by a
  // relative 1e-9 so that the rounding of the bounds and of the placement (a few ulps) cannot
  // leave a point of the surface outside.
  const Box box = local_bounds(s);
  c.local_centre = (box.lo + box.hi) * 0.5;
  c.local_radius = length(box.hi - box.lo) * 0.5 * (1.0 + 1e-9);
  c.centre = c.local_to_world(c.local_centre);
  c.radius = c.local_radius * s.scale;
  return c;
}

}  // namespace rpu::scene
