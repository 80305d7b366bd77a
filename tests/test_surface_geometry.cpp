// The surfaces' local geometry (ref/scene/surface_geometry.h, docs/surfaces.md): each indicator
// against the seed's parametric form R(φ, ·) (points pushed ±ε along the normal fall outside and
// inside), the pieces, and single rays of both float methods with analytic answers: the open
// ellipsoid seen through its cut, the rocket's joints, the spiral's gap and end plane, a camera
// inside the bounding sphere and inside the surface, float-ip against float where the IP cannot
// fail.
#include "test_seed.h"
#include "scene/surface_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "tracer/surface_tracer.h"

namespace rpu::scene {
namespace {

using tracer::Method;
using tracer::SurfaceRayHit;

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * kPi;

const SurfaceType kTypes[] = {SurfaceType::kEllipsoid, SurfaceType::kReliefEllipsoid,
                              SurfaceType::kSpiral, SurfaceType::kSnail, SurfaceType::kRocket};

Surface make(SurfaceType t) {
  Surface s;
  s.type = t;
  s.p = default_surface_params(t);
  return s;
}

// A random valid parameter set of each type (scene-reader rules: d > |e|, the spiral's section
// off the axis; here also turns apart, so that ±ε around one turn cannot enter another).
SurfaceParams random_params(SurfaceType t, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  SurfaceParams p = default_surface_params(t);
  switch (t) {
    case SurfaceType::kEllipsoid:
      p.a = 0.5 + u(rng), p.b = 0.5 + 2 * u(rng), p.c = 0.5 + u(rng);
      p.y_min = -p.b * (0.2 + 0.8 * u(rng)), p.y_max = p.b * (0.2 + 0.8 * u(rng));
      break;
    case SurfaceType::kReliefEllipsoid:
      p.a = 0.5 + u(rng), p.b = 1 + u(rng), p.c = 0.5 + u(rng);
      p.d = 0.8 + u(rng), p.e = (2 * u(rng) - 1) * 0.7 * p.d;
      p.y_min = -p.b, p.y_max = p.b;
      break;
    case SurfaceType::kSpiral:
      p.b = 0.1 + 0.3 * u(rng), p.c = 0.1 + 0.5 * u(rng);
      p.R = std::max(p.b, p.c) + 0.2 + u(rng), p.a = 0.3 * u(rng);
      p.k = (2 * std::max(p.b, p.c) + 0.2) / kTwoPi + 0.5 * u(rng);
      p.phi_max = 2 + 12 * u(rng);
      break;
    case SurfaceType::kSnail:
      p.a = 0.005 + 0.05 * u(rng), p.phi_max = 3 + 25 * u(rng);
      break;
    case SurfaceType::kRocket:
      p.a = 0.1 + 0.4 * u(rng), p.b = 0.3 + u(rng), p.c = 0.2 + u(rng), p.d = 0.05 + 0.3 * u(rng),
      p.e = 0.1 + 0.5 * u(rng);
      break;
  }
  return p;
}

// ---- indicators against the parametric form ----

// For n random (φ, v) within range, P = R(φ, v) with the unit normal n = ∂R/∂φ × ∂R/∂v turned
// away from the section centre: P + ε·n is outside, P − ε·n inside (ε relative to the section
// size), and the continuous indicator is ≈ 0 at P.
void check_normal_offsets(const SurfaceGeometry& g, int n, std::mt19937_64& rng,
                          const std::string& label) {
  const SurfaceParams& p = g.params();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int failures = 0;
  for (int k = 0; k < n && failures < 5; ++k) {
    double phi = 0.0, v = 0.0;
    switch (g.type()) {
      case SurfaceType::kEllipsoid:  // away from the pole y = −b (degenerate normal)
        phi = kTwoPi * u(rng);
        v = std::max(p.y_min, -0.97 * p.b) + (p.y_max - std::max(p.y_min, -0.97 * p.b)) * u(rng);
        break;
      case SurfaceType::kReliefEllipsoid:
        phi = kTwoPi * u(rng), v = p.b * (1.94 * u(rng) - 0.97);
        break;
      case SurfaceType::kSpiral:  // away from the open ends φ = 0 and φ = phi_max
        phi = 0.05 + (p.phi_max - 0.1) * u(rng), v = kTwoPi * u(rng);
        break;
      case SurfaceType::kSnail: {
        // Away from the ends, the turn seams φ = 2πk (the axis distance has a kink there) and the
        // points where neighbouring turns touch (γ = 0, π).
        do phi = 0.3 + (p.phi_max - 0.35) * u(rng);
        while (std::fabs(std::remainder(phi, kTwoPi)) < 0.01);
        v = (u(rng) < 0.5 ? 0.1 : kPi + 0.1) + (kPi - 0.2) * u(rng);
        break;
      }
      case SurfaceType::kRocket:
        phi = kTwoPi * u(rng), v = -p.c + (p.b + p.e + p.c) * (0.01 + 0.97 * u(rng));
        break;
    }
    const Vec3 P = g.point(phi, v);
    const double h = 1e-6;
    const Vec3 dphi = (g.point(phi + h, v) - g.point(phi - h, v)) / (2 * h);
    const Vec3 dv = (g.point(phi, v + h) - g.point(phi, v - h)) / (2 * h);
    Vec3 normal = cross(dphi, dv);
    if (length(normal) < 1e-9) continue;  // a degenerate parametrisation point (the cone apex)
    normal = normalize(normal);
    const Vec3 from_centre = P - g.section_centre(phi, v);
    if (dot(normal, from_centre) < 0) normal = -normal;
    const double eps = 1e-5 * std::max(length(from_centre), 1e-3);
    const bool out_ok = !g.inside(P + normal * eps);
    const bool in_ok = g.inside(P - normal * eps);
    if (!out_ok || !in_ok) {
      ++failures;
      ADD_FAILURE() << label << ": φ = " << phi << ", v = " << v << ": P + εn "
                    << (out_ok ? "outside" : "INSIDE") << ", P − εn "
                    << (in_ok ? "inside" : "OUTSIDE");
    }
  }
}

TEST(SurfaceIndicator, ParametricPointsOffsetAlongTheNormal) {
  std::mt19937_64 rng(rpu::test::seed(2008));
  for (SurfaceType t : kTypes) {
    const SurfaceGeometry seed(t, default_surface_params(t));
    check_normal_offsets(seed, 3000, rng, std::string(surface_type_name(t)) + " (seed)");
    for (int r = 0; r < 4; ++r) {
      const SurfaceGeometry g(t, random_params(t, rng));
      check_normal_offsets(g, 1000, rng, std::string(surface_type_name(t)) + " (random " +
                                             std::to_string(r) + ")");
    }
  }
}

TEST(SurfaceIndicator, ContinuousFormAgreesWithTheInsideTest) {
  // The gradient's F has the inside test's sign at random points of the bounding box.
  std::mt19937_64 rng(rpu::test::seed(4));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (SurfaceType t : kTypes) {
    const CompiledSurface cs = compile_surface(make(t), 0);
    const SurfaceGeometry g(cs.surface);
    int inside = 0;
    for (int k = 0; k < 20000; ++k) {
      const Vec3 p = cs.local_centre + Vec3{u(rng), u(rng), u(rng)} * cs.local_radius;
      const bool in = g.inside(p);
      inside += in;
      ASSERT_EQ(in, g.indicator(p) < 0.0) << surface_type_name(t) << " at " << p.x << ", " << p.y
                                          << ", " << p.z;
    }
    EXPECT_GT(inside, 20) << surface_type_name(t);
  }
}

TEST(SurfaceIndicator, WrongReadingsAreCaught) {
  // The offset check can fail: the seed's literal "ac" in the relief ellipsoid's x row (x scaled
  // by a·c instead of a) puts the parametric points of a = 1, c = 1.3 off the indicator.
  SurfaceParams p = default_surface_params(SurfaceType::kReliefEllipsoid);
  const SurfaceGeometry g(SurfaceType::kReliefEllipsoid, p);
  int wrong = 0;
  for (double phi = 0.1; phi < kTwoPi; phi += 0.1) {
    const Vec3 P = g.point(phi, 0.3);
    const Vec3 literal{P.x * p.c, P.y, P.z};  // a·c·k·s·sin φ
    wrong += g.inside(literal * 0.99999) != g.inside(P * 0.99999);
  }
  EXPECT_GT(wrong, 10);
}

TEST(SurfaceIndicator, SnailTurnsTouchAndTheFirstTurnMeetsTheAxis) {
  const SurfaceGeometry g(SurfaceType::kSnail, default_surface_params(SurfaceType::kSnail));
  const double a = g.params().a;
  // Outer point of turn m (γ = 0) = inner point of turn m + 1 (γ = π) at the same azimuth.
  for (double phi : {1.0, 3.0, 8.0, 14.0}) {
    const Vec3 outer = g.point(phi, 0.0), inner = g.point(phi + kTwoPi, kPi);
    EXPECT_NEAR(length(outer - inner), 0.0, 1e-12) << phi;
  }
  // The first turn's section is tangent to the axis at every azimuth (R_0 = r_0 = aψ): a point
  // just off the axis at y = 0 is inside; on the axis, outside (points on the surface are).
  const double psi = 2.0;
  EXPECT_TRUE(g.inside(Vec3{std::sin(psi), 0.0, std::cos(psi)} * (1e-3 * a * psi)));
  EXPECT_FALSE(g.inside(Vec3{0.0, 0.0, 0.0}));
}

TEST(SurfaceIndicator, PointsOnTheCutPlaneTakeTheLimitFromTheirPiece) {
  // A piece end on x = 0 (either zero, or a rounding error across) gets ψ = π or the piece's
  // limit 0 / 2π, never −π or 3π: the same inside bit as a point a hair into the piece.
  for (SurfaceType t : {SurfaceType::kSpiral, SurfaceType::kSnail}) {
    const SurfaceGeometry g(make(t));
    std::mt19937_64 rng(rpu::test::seed(9));
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (int k = 0; k < 20000; ++k) {
      const double y = t == SurfaceType::kSnail ? 0.1 * u(rng) : 2.0 * u(rng) + 2.5, z = u(rng);
      for (bool neg : {false, true}) {
        AzimuthBranch b = g.branch_at({neg ? -1e-3 : 1e-3, y, z});
        const bool inner = g.inside({neg ? -1e-12 : 1e-12, y, z}, b);
        for (double x : {0.0, -0.0, 1e-17, -1e-17})
          ASSERT_EQ(g.inside({x, y, z}, b), inner)
              << surface_type_name(t) << " x = " << x << " y = " << y << " z = " << z << " neg "
              << neg;
      }
    }
  }
}

// ---- pieces ----

TEST(SurfacePieces, SlabClip) {
  const SurfaceGeometry g(make(SurfaceType::kEllipsoid));  // y ∈ [−2, 1]
  std::array<SurfacePiece, kMaxSurfacePieces> pc;
  // Straight down from y = 5: one piece from y = 1 to y = −2.
  ASSERT_EQ(g.pieces({0.3, 5, 0}, {0, -1, 0}, 0.0, 10.0, pc), 1);
  EXPECT_DOUBLE_EQ(pc[0].t0, 4.0);
  EXPECT_DOUBLE_EQ(pc[0].t1, 7.0);
  // Horizontal above the slab: none. Horizontal within: the whole interval.
  EXPECT_EQ(g.pieces({-5, 1.5, 0}, {1, 0, 0}, 0.0, 10.0, pc), 0);
  ASSERT_EQ(g.pieces({-5, 0.5, 0}, {1, 0, 0}, 2.0, 8.0, pc), 1);
  EXPECT_EQ(pc[0].t0, 2.0);
  EXPECT_EQ(pc[0].t1, 8.0);
  // Rocket: y ∈ [−c, b + e] = [−0.8, 1.4].
  const SurfaceGeometry r(make(SurfaceType::kRocket));
  ASSERT_EQ(r.pieces({0, -5, 0}, {0, 1, 0}, 0.0, 10.0, pc), 1);
  EXPECT_NEAR(pc[0].t0, 4.2, 1e-15);
  EXPECT_NEAR(pc[0].t1, 6.4, 1e-15);
}

TEST(SurfacePieces, SpiralCutsAtTheStartAndEndPlanes) {
  const SurfaceGeometry g(make(SurfaceType::kSpiral));
  const double alpha = g.end_azimuth();
  EXPECT_NEAR(alpha, 11.0 - kTwoPi, 1e-12);
  std::mt19937_64 rng(rpu::test::seed(5));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int three = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 o{4 * u(rng), 3 * u(rng), 4 * u(rng)}, d{u(rng), 0.3 * u(rng), u(rng)};
    std::array<SurfacePiece, kMaxSurfacePieces> pc;
    const int n = g.pieces(o, d, 0.0, 20.0, pc);
    ASSERT_GE(n, 1);
    three += n == 3;
    EXPECT_EQ(pc[0].t0, 0.0);
    EXPECT_EQ(pc[n - 1].t1, 20.0);
    for (int i = 0; i < n; ++i) {
      if (i > 0) {
        EXPECT_EQ(pc[i].t0, pc[i - 1].t1);
      }
      // Inside a piece neither x nor the end plane's side changes, and the branch says so.
      const Vec3 nend{std::cos(alpha), 0.0, -std::sin(alpha)};
      const double span = pc[i].t1 - pc[i].t0;
      const Vec3 a = o + d * (pc[i].t0 + 1e-9 * span), b = o + d * (pc[i].t1 - 1e-9 * span);
      EXPECT_EQ(a.x < 0, b.x < 0);
      EXPECT_EQ(dot(a, nend) < 0, dot(b, nend) < 0);
      EXPECT_EQ(pc[i].branch.x_negative, a.x < 0);
      const double psi = azimuth(o + d * (0.5 * (pc[i].t0 + pc[i].t1)));
      EXPECT_EQ(pc[i].branch.top_turn, psi <= alpha ? 1 : 0) << psi;
    }
  }
  EXPECT_GT(three, 100);
}

TEST(SurfacePieces, SnailEndPlaneIsTheStartPlane) {
  // phi_max = 10π: five whole turns, the end plane is x = 0 (no second cut), four turns above
  // every azimuth but 0.
  const SurfaceGeometry g(make(SurfaceType::kSnail));
  EXPECT_EQ(g.end_azimuth(), 0.0);
  std::array<SurfacePiece, kMaxSurfacePieces> pc;
  ASSERT_EQ(g.pieces({-3, 0.1, 0.5}, {1, 0, 0.01}, 0.0, 6.0, pc), 2);
  EXPECT_TRUE(pc[0].branch.x_negative);
  EXPECT_FALSE(pc[1].branch.x_negative);
  EXPECT_EQ(pc[0].branch.top_turn, 4);
  EXPECT_EQ(pc[1].branch.top_turn, 4);
}

// ---- single rays, both methods ----

struct RayCase {
  Vec3 eye, dir;
};

SurfaceRayHit trace(const CompiledSurface& cs, const RayCase& r, Method m, int n = 24, int n1 = 4) {
  const SurfaceGeometry g(cs.surface);
  ref::HwParams schedule;  // the default first step, then n1 per step
  schedule.n = n;
  schedule.n1 = n1;
  return tracer::trace_surface(cs, g, r.eye, r.dir, m, schedule);
}

// The IP's hit is the start of its final interval: at most one final interval (2^−n of the
// piece) before the crossing. Pieces here are at most the bounding sphere's diameter.
void expect_hit_at(const CompiledSurface& cs, const RayCase& r, double t_expected,
                   const std::string& label, int n = 24, int n1 = 4) {
  const SurfaceRayHit ideal = trace(cs, r, Method::kIdeal);
  ASSERT_TRUE(ideal.hit) << label << " (float)";
  EXPECT_NEAR(ideal.t, t_expected, 1e-9 * (1 + t_expected)) << label << " (float)";
  const SurfaceRayHit ip = trace(cs, r, Method::kIterative, n, n1);
  ASSERT_TRUE(ip.hit) << label << " (float-ip)";
  const double final_interval = 2 * cs.radius / length(r.dir) * std::ldexp(1.0, -n);
  EXPECT_LE(ip.t, t_expected + 1e-9) << label << " (float-ip)";
  EXPECT_GE(ip.t, t_expected - final_interval - 1e-9) << label << " (float-ip)";
}

void expect_miss(const CompiledSurface& cs, const RayCase& r, const std::string& label) {
  EXPECT_FALSE(trace(cs, r, Method::kIdeal).hit) << label << " (float)";
  EXPECT_FALSE(trace(cs, r, Method::kIterative).hit) << label << " (float-ip)";
}

TEST(SurfaceRays, OpenEllipsoidSeenThroughItsCut) {
  const CompiledSurface cs = compile_surface(make(SurfaceType::kEllipsoid), 0);  // y ≤ 1
  // Straight down through the opening (radius √0.75 at y = 1): the piece starts inside, the
  // first change is the inner wall at the bottom, y = −b·√(1 − x²).
  for (double x : {0.0, 0.3, 0.8}) {
    const double y_wall = -2.0 * std::sqrt(1.0 - x * x);
    expect_hit_at(cs, {{x, 5, 0}, {0, -1, 0}}, 5 - y_wall, "down at x = " + std::to_string(x));
  }
  // Outside the opening the outer wall is hit from outside, at y = b·√(1 − x²) < 1.
  expect_hit_at(cs, {{0.95, 5, 0}, {0, -1, 0}}, 5 - 2.0 * std::sqrt(1 - 0.95 * 0.95), "x = 0.95");
  // Obliquely through the opening (it meets y = 1 at x = 0.2) onto the inner wall:
  // (x/1)² + (y/2)² = 1 on x = −0.4 + 0.3t, y = 3 − t is 0.34t² − 1.74t + 1.41 = 0. Its smaller
  // root lies above the cut (y > 1, the missing cap), the larger one is the inner wall.
  const Vec3 e{-0.4, 3.0, 0.0}, d{0.3, -1.0, 0.0};
  const double qa = 0.34, qb = -1.74, qc = 1.41;
  const double root = std::sqrt(qb * qb - 4 * qa * qc);
  const double t_cap = (-qb - root) / (2 * qa), t_wall = (-qb + root) / (2 * qa);
  ASSERT_GT(3.0 - t_cap, 1.0);
  expect_hit_at(cs, {e, d}, t_wall, "oblique through the cut");
  // Placed: scaled, rotated and moved, the same ray in world units hits the same wall point.
  Surface placed = make(SurfaceType::kEllipsoid);
  placed.scale = 1.7;
  placed.rotation_deg = {20, -35, 50};
  placed.position = {1, -2, 3};
  const CompiledSurface pcs = compile_surface(placed, 0);
  const Vec3 we = pcs.local_to_world(e), wd = pcs.local_to_world(e + d) - we;
  expect_hit_at(pcs, {we, wd}, t_wall, "placed, oblique through the cut");
}

TEST(SurfaceRays, RocketJoints) {
  const CompiledSurface cs = compile_surface(make(SurfaceType::kRocket), 0);
  const SurfaceParams& p = cs.surface.p;  // a 0.2, b 1, c 0.8, d 0.2, e 0.4
  // Down just inside the cylinder's radius: the cone is met a hair above the cone/cylinder joint.
  const double delta = 1e-3;
  expect_hit_at(cs, {{p.a - delta, 3, 0}, {0, -1, 0}}, 3 - (p.b + p.e * delta / p.a),
                "just inside the joint");
  // Just outside: at ψ = π/2, sin 5ψ = 1, no fin: nothing is hit.
  expect_miss(cs, {{p.a + delta, 3, 0}, {0, -1, 0}}, "just outside, between fins");
  // At ψ = 3π/2 (sin 5ψ = −1) the fin r = a − 2yd/c reaches a + 0.01 at y = −0.01·c/(2d).
  expect_hit_at(cs, {{-(p.a + 0.01), 3, 0}, {0, -1, 0}}, 3 + 0.01 * p.c / (2 * p.d), "fin tip");
  // Horizontal rays at the joint height y = b, grazing: the chord 2√(a² − z²) is short. The
  // ideal always sees it; the IP with 256 sub-intervals per step too (16 would be too coarse).
  for (double z : {0.15, 0.19, 0.199}) {
    const double half = std::sqrt(p.a * p.a - z * z);
    expect_hit_at(cs, {{-2, p.b, z}, {1, 0, 0}}, 2 - half, "grazing the joint", 24, 8);
  }
}

TEST(SurfaceRays, SpiralGapBetweenTurns) {
  const CompiledSurface cs = compile_surface(make(SurfaceType::kSpiral), 0);
  const SurfaceParams& p = cs.surface.p;  // R 0.7, k 0.5, a 0.2, b 0.16, c 0.64
  // At ψ0 = π/8, 4ψ0 = π/2: the section's c axis is vertical, its radial half-width is b.
  const double psi0 = kPi / 8;
  const Vec3 radial{std::sin(psi0), 0, std::cos(psi0)};
  const double rho0 = p.R + p.a * psi0, rho1 = rho0 + kTwoPi * p.a;  // turns 0 and 1
  const double y0 = p.k * psi0, y1 = y0 + kTwoPi * p.k;
  // Vertical rays at this azimuth: on turn 1's axis → its top; on turn 0's → its top (turn 1
  // is passed beside); halfway between the turns → nothing.
  expect_hit_at(cs, {radial * rho1 + Vec3{0, 8, 0}, {0, -1, 0}}, 8 - (y1 + p.c), "turn 1");
  expect_hit_at(cs, {radial * rho0 + Vec3{0, 8, 0}, {0, -1, 0}}, 8 - (y0 + p.c), "turn 0");
  expect_miss(cs, {radial * (0.5 * (rho0 + rho1)) + Vec3{0, 8, 0}, {0, -1, 0}}, "between");
  // Horizontally towards the axis at the height between the turns: passes between them at ψ0,
  // crosses the axis and meets turn 0 half a turn later (ψ0 + π: height k(ψ0 + π), the same) on
  // its inner side, radius R + a(ψ0 + π) − b.
  const double y_mid = 0.5 * (y0 + y1);
  const double far_inner = p.R + p.a * (psi0 + kPi) - p.b;
  expect_hit_at(cs, {radial * 4.0 + Vec3{0, y_mid, 0}, -radial}, 4.0 + far_inner,
                "between the turns, then the far side");
}

TEST(SurfaceRays, SpiralEndAndStartPlanesAreNotHits) {
  const CompiledSurface cs = compile_surface(make(SurfaceType::kSpiral), 0);
  const SurfaceGeometry g(cs.surface);
  const SurfaceParams& p = cs.surface.p;
  // The end section (φ = phi_max) and the direction of growing azimuth there.
  const double alpha = g.end_azimuth();
  const Vec3 centre = g.section_centre(p.phi_max, 0.0);
  const Vec3 tangent{std::cos(alpha), 0.0, -std::sin(alpha)};
  // From beyond the end (nothing there) back into the tube through its open end.
  const RayCase r{centre + tangent * 2.0, -tangent};
  const double t_plane = 2.0;
  for (Method m : {Method::kIdeal, Method::kIterative}) {
    const SurfaceRayHit h = trace(cs, r, m);
    ASSERT_TRUE(h.hit);  // the tube's wall, from inside
    EXPECT_GT(h.t, t_plane + 0.05) << (m == Method::kIdeal ? "float" : "float-ip");
    EXPECT_NEAR(g.indicator(h.local), 0.0, 1e-4);
  }
  // The start plane (φ = 0, azimuth 0, the plane x = 0): from x < 0, where ψ ≈ 2π and the
  // nearest turn is a whole pitch higher, into the open start of turn 0 at (0, 0, R).
  const RayCase start{{-2.0, 0.0, p.R}, {1.0, 0.0, 0.0}};
  for (Method m : {Method::kIdeal, Method::kIterative}) {
    const SurfaceRayHit h = trace(cs, start, m);
    ASSERT_TRUE(h.hit);
    EXPECT_GT(h.t, 2.0 + 0.01) << (m == Method::kIdeal ? "float" : "float-ip");
    EXPECT_NEAR(g.indicator(h.local), 0.0, 1e-4);
  }
  // Without the pieces the same sign search stops at the end plane: a single search from the
  // ray's start with ψ and the turns taken per point (what the pieces exist to prevent).
  const Vec3 A = r.eye, B = r.eye + r.dir * 4.0;
  double tau = 0.0;
  int first_change = -1;
  bool prev = g.inside(A);
  for (int k = 1; k <= 4096 && first_change < 0; ++k) {
    const bool cur = g.inside(A + (B - A) * (k / 4096.0));
    if (cur != prev) first_change = k;
    prev = cur;
  }
  tau = first_change / 4096.0;
  EXPECT_NEAR(4.0 * tau, t_plane, 2e-3);
}

TEST(SurfaceRays, EyeInsideTheBoundingSphere) {
  // Inside the ellipsoid (and its sphere): the first change is the wall from inside. Upward the
  // ray leaves through the opening at y = 1: nothing.
  const CompiledSurface el = compile_surface(make(SurfaceType::kEllipsoid), 0);
  expect_hit_at(el, {{0, 0, 0}, {1, 0, 0}}, 1.0, "ellipsoid +x");
  expect_hit_at(el, {{0, 0, 0}, {0, -1, 0}}, 2.0, "ellipsoid −y");
  expect_hit_at(el, {{0, 0, 0}, {0, 0, -0.5}}, 2.0, "ellipsoid −z, |v| = 0.5");
  expect_miss(el, {{0, 0, 0}, {0, 1, 0}}, "ellipsoid +y, through the opening");
  // Inside the relief ellipsoid on the z axis (φ = 0, k = d): the wall at z = c·d.
  const CompiledSurface rl = compile_surface(make(SurfaceType::kReliefEllipsoid), 0);
  expect_hit_at(rl, {{0, 0, 0}, {0, 0, 1}}, 1.3, "relief +z");
  // Inside the rocket's cylinder: the wall at ρ = a.
  const CompiledSurface rk = compile_surface(make(SurfaceType::kRocket), 0);
  expect_hit_at(rk, {{0, 0.5, 0}, {1, 0, 0}}, 0.2, "rocket +x");
  // Inside the spiral's bounding sphere, outside the surface: on the axis at the height of the
  // turn at ψ = π/2 (no section rotation there), outward: the section's inner side R + aπ/2 − c.
  const CompiledSurface sp = compile_surface(make(SurfaceType::kSpiral), 0);
  const SurfaceParams& q = sp.surface.p;
  ASSERT_LT(length(Vec3{0, q.k * kPi / 2, 0} - sp.local_centre), sp.local_radius);
  expect_hit_at(sp, {{0, q.k * kPi / 2, 0}, {1, 0, 0}}, q.R + q.a * kPi / 2 - q.c, "spiral axis");
}

TEST(SurfaceRays, DenseSearchMatchesTheAnalyticEllipsoid) {
  // A relief ellipsoid without relief (e = 0, d = 1) is the ellipsoid a, b, c: the dense
  // sampling plus bisection of `float` finds the analytic crossing, also from inside and on
  // grazing rays longer than a sample step.
  Surface el = make(SurfaceType::kEllipsoid), rl = make(SurfaceType::kReliefEllipsoid);
  el.p.a = rl.p.a = 1.0, el.p.b = rl.p.b = 2.0, el.p.c = rl.p.c = 1.3;
  el.p.y_min = rl.p.y_min = -2.0, el.p.y_max = rl.p.y_max = 2.0;
  rl.p.d = 1.0, rl.p.e = 0.0;
  const CompiledSurface ce = compile_surface(el, 0), cr = compile_surface(rl, 0);
  std::mt19937_64 rng(rpu::test::seed(77));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 from = k % 3 == 0 ? Vec3{0.5 * u(rng), u(rng), 0.5 * u(rng)}  // inside
                                 : normalize(Vec3{u(rng), u(rng), u(rng)}) * 6.0;
    const Vec3 target{1.3 * u(rng), 2.0 * u(rng), 1.3 * u(rng)};
    const RayCase r{from, target - from};
    const SurfaceRayHit a = trace(ce, r, Method::kIdeal), b = trace(cr, r, Method::kIdeal);
    ASSERT_EQ(a.hit, b.hit) << "ray " << k;
    if (!a.hit) continue;
    ++hits;
    EXPECT_NEAR(a.t, b.t, 1e-9) << "ray " << k;
  }
  EXPECT_GT(hits, 2000);
}

TEST(SurfaceRays, IterativeEqualsIdealWhereItCannotFail) {
  // Rays from outside aimed near the middle of a closed surface cross it with a chord longer
  // than a step-1 interval (n1 ≥ 4: at most 1/16 of the bounding diameter): the IP's τ_K is the
  // crossing's final interval exactly.
  std::mt19937_64 rng(rpu::test::seed(12));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  struct Case {
    SurfaceType type;
    double aim;  // aim within this distance of the local point `centre`
    Vec3 centre;
  };
  for (const Case c : {Case{SurfaceType::kEllipsoid, 0.3, {0, -0.5, 0}},
                       Case{SurfaceType::kReliefEllipsoid, 0.3, {0, 0, 0}},
                       Case{SurfaceType::kRocket, 0.08, {0, 0.5, 0}}}) {
    Surface s = make(c.type);
    if (c.type == SurfaceType::kEllipsoid) s.p.y_max = s.p.b;  // closed
    const CompiledSurface cs = compile_surface(s, 0);
    const SurfaceGeometry g(s);
    for (int k = 0; k < 300; ++k) {
      Vec3 from{u(rng), 0.3 * u(rng), u(rng)};
      from = normalize(from) * 5.0 + c.centre;
      const Vec3 target = c.centre + Vec3{u(rng), u(rng), u(rng)} * c.aim;
      const RayCase r{from, target - from};
      for (const auto& [n, n1] : {std::pair{16, 4}, std::pair{24, 4}, std::pair{24, 8}}) {
        const SurfaceRayHit ideal = trace(cs, r, Method::kIdeal);
        const SurfaceRayHit ip = trace(cs, r, Method::kIterative, n, n1);
        ASSERT_TRUE(ideal.hit && ip.hit) << surface_type_name(c.type) << " ray " << k;
        const double final_interval = 2 * cs.radius / length(r.dir) * std::ldexp(1.0, -n);
        EXPECT_LE(ip.t, ideal.t + 1e-9);
        EXPECT_GE(ip.t, ideal.t - final_interval - 1e-9) << surface_type_name(c.type) << " n=" << n;
      }
    }
  }
}

}  // namespace
}  // namespace rpu::scene
