// compile_surface (ref/scene/surface.cpp): the placement frame (Rz·Ry·Rx after a uniform scale)
// and the bounding sphere, checked against dense samples of each primitive's parametric surface
// R(φ, y) / R(φ, γ) written out here from seed 004's equations 2, 3, 5, 6 and 7.
#include "test_seed.h"
#include "scene/surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>

namespace rpu::scene {
namespace {

constexpr double kPi = std::numbers::pi;

// ---- The seed's parametric surfaces, in the local frame. ----

// Eq 2: R = (0, y, 0) + (a·sin φ·√(1 − y²/b²), 0, c·cos φ·√(1 − y²/b²)).
Vec3 ellipsoid_point(const SurfaceParams& p, double phi, double y) {
  const double s = std::sqrt(std::max(0.0, 1.0 - y * y / (p.b * p.b)));
  return {p.a * std::sin(phi) * s, y, p.c * std::cos(phi) * s};
}

// Eq 3: the ellipsoid's section scaled by k = d + e·sin(10φ)·cos(9y).
Vec3 relief_point(const SurfaceParams& p, double phi, double y) {
  const double k = p.d + p.e * std::sin(10.0 * phi) * std::cos(9.0 * y);
  const double s = std::sqrt(std::max(0.0, 1.0 - y * y / (p.b * p.b)));
  return {k * p.a * s * std::sin(phi), y, k * p.c * s * std::cos(phi)};
}

// Eq 5: axis ((R + aφ) sin φ, kφ, (R + aφ) cos φ) plus the rotating elliptic section.
Vec3 spiral_point(const SurfaceParams& p, double phi, double g) {
  const double axis = p.R + p.a * phi;
  const double radial =
      p.c * std::cos(g) * std::cos(4.0 * phi) + p.b * std::sin(g) * std::sin(4.0 * phi);
  return {axis * std::sin(phi) + std::sin(phi) * radial,
          p.k * phi + p.b * std::sin(g) * std::cos(4.0 * phi) - p.c * std::cos(g) * std::sin(4.0 * phi),
          axis * std::cos(phi) + std::cos(phi) * radial};
}

// Eq 6: R(φ) = aφ + 2a·Σ_{i=0}^{k(φ)−1} (2π·i + m(φ)), m = φ − 2πk, k = ⌊φ/2π⌋ (summed term by
// term, as written); the section is a circle of radius aφ in the meridian plane.
Vec3 snail_point(const SurfaceParams& p, double phi, double g) {
  const int k = static_cast<int>(std::floor(phi / (2.0 * kPi)));
  const double m = phi - 2.0 * kPi * k;
  double sum = 0.0;
  for (int i = 0; i < k; ++i) sum += 2.0 * kPi * i + m;
  const double r_axis = p.a * phi + 2.0 * p.a * sum;
  const double r = p.a * phi;
  return {r_axis * std::sin(phi) + r * std::sin(phi) * std::cos(g), r * std::sin(g),
          r_axis * std::cos(phi) + r * std::cos(phi) * std::cos(g)};
}

// Eq 7 with the cone read as a·(1 − (y − b)/e) (docs/algorithms.md §3).
Vec3 rocket_point(const SurfaceParams& p, double phi, double y) {
  double r = p.a;
  if (y <= 0.0) r = p.a + (std::sin(5.0 * phi) - 1.0) * y * p.d / p.c;
  else if (y >= p.b) r = p.a * (1.0 - (y - p.b) / p.e);
  return {r * std::sin(phi), y, r * std::cos(phi)};
}

// A type's parametric point and its parameter rectangle [0, φ_end] × [v_lo, v_hi].
struct Parametric {
  std::function<Vec3(double, double)> point;
  double phi_end, v_lo, v_hi;
};

Parametric parametric(const Surface& s) {
  const SurfaceParams& p = s.p;
  switch (s.type) {
    case SurfaceType::kEllipsoid:
      return {[p](double f, double y) { return ellipsoid_point(p, f, y); }, 2 * kPi, p.y_min, p.y_max};
    case SurfaceType::kReliefEllipsoid:
      return {[p](double f, double y) { return relief_point(p, f, y); }, 2 * kPi, p.y_min, p.y_max};
    case SurfaceType::kSpiral:
      return {[p](double f, double g) { return spiral_point(p, f, g); }, p.phi_max, 0, 2 * kPi};
    case SurfaceType::kSnail:
      return {[p](double f, double g) { return snail_point(p, f, g); }, p.phi_max, 0, 2 * kPi};
    case SurfaceType::kRocket:
      return {[p](double f, double y) { return rocket_point(p, f, y); }, 2 * kPi, -p.c, p.b + p.e};
  }
  return {};
}

// ---- Placement, written out independently of surface.cpp. ----

// world = position + Rz(γ)·Ry(β)·Rx(α)·(scale · local), angles in degrees.
Vec3 place(const Surface& s, const Vec3& local) {
  const double d = kPi / 180.0;
  Vec3 v = local * s.scale;
  const double ax = s.rotation_deg.x * d, ay = s.rotation_deg.y * d, az = s.rotation_deg.z * d;
  v = {v.x, std::cos(ax) * v.y - std::sin(ax) * v.z, std::sin(ax) * v.y + std::cos(ax) * v.z};
  v = {std::cos(ay) * v.x + std::sin(ay) * v.z, v.y, -std::sin(ay) * v.x + std::cos(ay) * v.z};
  v = {std::cos(az) * v.x - std::sin(az) * v.y, std::sin(az) * v.x + std::cos(az) * v.y, v.z};
  return s.position + v;
}

void expect_near(const Vec3& a, const Vec3& b, double tol, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

TEST(SurfaceCompile, TypeNames) {
  EXPECT_STREQ(surface_type_name(SurfaceType::kEllipsoid), "ellipsoid");
  EXPECT_STREQ(surface_type_name(SurfaceType::kReliefEllipsoid), "relief_ellipsoid");
  EXPECT_STREQ(surface_type_name(SurfaceType::kSpiral), "spiral");
  EXPECT_STREQ(surface_type_name(SurfaceType::kSnail), "snail");
  EXPECT_STREQ(surface_type_name(SurfaceType::kRocket), "rocket");
}

// The seed's figure captions (docs/scene-format.md).
TEST(SurfaceCompile, SeedDefaults) {
  const SurfaceParams el = default_surface_params(SurfaceType::kEllipsoid);
  EXPECT_EQ(std::vector<double>({el.a, el.b, el.c, el.y_min, el.y_max}),
            std::vector<double>({1, 2, 1, -2, 1}));
  const SurfaceParams re = default_surface_params(SurfaceType::kReliefEllipsoid);
  EXPECT_EQ(std::vector<double>({re.a, re.b, re.c, re.d, re.e, re.y_min, re.y_max}),
            std::vector<double>({1, 2, 1.3, 1, 0.4, -2, 2}));
  const SurfaceParams sp = default_surface_params(SurfaceType::kSpiral);
  EXPECT_EQ(std::vector<double>({sp.R, sp.k, sp.a, sp.b, sp.c, sp.phi_max}),
            std::vector<double>({0.7, 0.5, 0.2, 0.16, 0.64, 11}));
  const SurfaceParams sn = default_surface_params(SurfaceType::kSnail);
  EXPECT_EQ(sn.a, 0.01);
  EXPECT_DOUBLE_EQ(sn.phi_max, 10 * kPi);
  const SurfaceParams ro = default_surface_params(SurfaceType::kRocket);
  EXPECT_EQ(std::vector<double>({ro.a, ro.b, ro.c, ro.d, ro.e}),
            std::vector<double>({0.2, 1, 0.8, 0.2, 0.4}));
}

// Rotations about x, then y, then z: each axis alone, and the order told apart.
TEST(SurfaceCompile, RotationOrder) {
  const auto rotated = [](Vec3 deg, Vec3 v) {
    Surface s;
    s.rotation_deg = deg;
    return compile_surface(s, 0).rotation * v;
  };
  expect_near(rotated({0, 0, 90}, {1, 0, 0}), {0, 1, 0}, 1e-15, "Rz(90) x");
  expect_near(rotated({90, 0, 0}, {0, 1, 0}), {0, 0, 1}, 1e-15, "Rx(90) y");
  expect_near(rotated({0, 90, 0}, {0, 0, 1}), {1, 0, 0}, 1e-15, "Ry(90) z");
  // Rx first: y → z, then Ry: z → x. (Ry first would leave y alone, then Rx: y → z.)
  expect_near(rotated({90, 90, 0}, {0, 1, 0}), {1, 0, 0}, 1e-15, "Ry(90)·Rx(90) y");
  // Ry first: x → −z, then Rz leaves z alone. (Rz first: x → y, Ry leaves y alone.)
  expect_near(rotated({0, 90, 90}, {1, 0, 0}), {0, 0, -1}, 1e-15, "Rz(90)·Ry(90) x");
}

// A random valid surface of each type (the scene reader's rules), randomly placed.
Surface random_surface(SurfaceType t, std::mt19937_64& rng) {
  const auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  Surface s;
  s.type = t;
  SurfaceParams& p = s.p;
  p = default_surface_params(t);
  switch (t) {
    case SurfaceType::kEllipsoid:
    case SurfaceType::kReliefEllipsoid: {
      p.a = u(0.1, 3), p.b = u(0.1, 3), p.c = u(0.1, 3);
      const double lo = u(-1, 0.9), hi = u(lo + 0.05, 1);
      p.y_min = lo * p.b, p.y_max = hi * p.b;
      if (t == SurfaceType::kReliefEllipsoid) p.d = u(0.2, 2), p.e = u(-0.99, 0.99) * p.d;
      break;
    }
    case SurfaceType::kSpiral:
      p.a = u(0.01, 0.5), p.b = u(0.05, 1), p.c = u(0.05, 1);
      p.R = std::max(p.b, p.c) + u(0.01, 2), p.k = u(-1, 1), p.phi_max = u(0.1, 16 * kPi);
      break;
    case SurfaceType::kSnail:
      p.a = u(0.001, 0.1), p.phi_max = u(0.1, 16 * kPi);
      break;
    case SurfaceType::kRocket:
      p.a = u(0.05, 2), p.b = u(0.05, 2), p.c = u(0.05, 2), p.e = u(0.05, 2), p.d = u(0, 1);
      break;
  }
  s.position = {u(-100, 100), u(-100, 100), u(-100, 100)};
  s.rotation_deg = {u(-360, 360), u(-360, 360), u(-360, 360)};
  s.scale = std::exp(u(std::log(0.01), std::log(100.0)));
  return s;
}

// Every sample of the parametric surface lies in the world bounding sphere; the sphere is not
// wildly loose (the farthest sample reaches at least half its radius); the frame maps local to
// world as written above and back.
TEST(SurfaceCompile, BoundingSphereContainsTheSurface) {
  std::mt19937_64 rng(rpu::test::seed(20080610));
  for (const SurfaceType t : {SurfaceType::kEllipsoid, SurfaceType::kReliefEllipsoid,
                              SurfaceType::kSpiral, SurfaceType::kSnail, SurfaceType::kRocket}) {
    for (int trial = 0; trial < 16; ++trial) {
      // Trial 0: the seed's parameters, unplaced.
      const Surface s = trial == 0 ? Surface{t, default_surface_params(t)} : random_surface(t, rng);
      const std::string what = std::string(surface_type_name(t)) + " trial " + std::to_string(trial);
      const CompiledSurface c = compile_surface(s, 7);
      EXPECT_EQ(c.primitive, 7);
      ASSERT_GT(c.radius, 0.0) << what;
      EXPECT_NEAR(c.radius, c.local_radius * s.scale, 1e-12 * c.radius) << what;
      const Parametric f = parametric(s);
      // Dense in φ: 2049 samples over at most 8 turns (both ends included), 49 over the other
      // parameter (its range ends included).
      constexpr int kPhi = 2048, kV = 48;
      double farthest = 0.0;
      int outside = 0;
      for (int i = 0; i <= kPhi; ++i) {
        const double phi = f.phi_end * i / kPhi;
        for (int j = 0; j <= kV; ++j) {
          const double v = f.v_lo + (f.v_hi - f.v_lo) * j / kV;
          const Vec3 local = f.point(phi, v);
          const Vec3 world = place(s, local);
          const double dist = length(world - c.centre);
          farthest = std::max(farthest, dist);
          if (dist > c.radius) ++outside;
          if (i % 512 == 0 && j % 32 == 0) {
            const double tol = 1e-12 * (length(s.position) + c.radius + 1.0);
            expect_near(c.local_to_world(local), world, tol, what + " local_to_world");
            expect_near(c.world_to_local(world), local, tol / s.scale, what + " world_to_local");
          }
        }
      }
      EXPECT_EQ(outside, 0) << what << ": samples outside the sphere (radius " << c.radius << ")";
      EXPECT_GE(farthest, 0.5 * c.radius) << what << ": the sphere is loose";
    }
  }
}

// The bounds are the analytic ones of the brief, at the seed's parameters.
TEST(SurfaceCompile, SeedBounds) {
  const auto compiled = [](SurfaceType t) { return compile_surface({t, default_surface_params(t)}, 0); };
  const double slack = 1e-8;
  // Ellipsoid: box [−1, 1] × [−2, 1] × [−1, 1]: centre (0, −0.5, 0), half-diagonal √(1 + 2.25 + 1).
  const CompiledSurface el = compiled(SurfaceType::kEllipsoid);
  expect_near(el.local_centre, {0, -0.5, 0}, 1e-15, "ellipsoid centre");
  EXPECT_NEAR(el.local_radius, std::sqrt(4.25), slack);
  // Relief: radial (d + |e|)·(a, c) = (1.4, 1.82), y ∈ [−2, 2].
  const CompiledSurface re = compiled(SurfaceType::kReliefEllipsoid);
  EXPECT_NEAR(re.local_radius, std::sqrt(1.4 * 1.4 + 4 + 1.82 * 1.82), slack);
  // Spiral: ρ ≤ 0.7 + 0.2·11 + 0.64 = 3.54, y ∈ [−0.64, 5.5 + 0.64].
  const CompiledSurface sp = compiled(SurfaceType::kSpiral);
  expect_near(sp.local_centre, {0, 2.75, 0}, 1e-12, "spiral centre");
  EXPECT_NEAR(sp.local_radius, std::sqrt(2 * 3.54 * 3.54 + 3.39 * 3.39), slack);
  // Snail: R(10π) = 2πa·5² = 50πa, section aφ = 10πa; ρ ≤ 60πa, |y| ≤ 10πa.
  const CompiledSurface sn = compiled(SurfaceType::kSnail);
  const double rho = 60 * kPi * 0.01, y = 10 * kPi * 0.01;
  EXPECT_NEAR(sn.local_radius, std::sqrt(2 * rho * rho + y * y), slack);
  // Rocket: ρ ≤ a + 2d = 0.6, y ∈ [−0.8, 1.4].
  const CompiledSurface ro = compiled(SurfaceType::kRocket);
  expect_near(ro.local_centre, {0, 0.3, 0}, 1e-15, "rocket centre");
  EXPECT_NEAR(ro.local_radius, std::sqrt(2 * 0.36 + 1.1 * 1.1), slack);
}

}  // namespace
}  // namespace rpu::scene
