// Patch evaluation (docs/algorithms.md §4): derivatives against central differences, partition of
// unity, NURBS with unit weights = B-spline, Bézier = clamped B-spline, clamped ends interpolate
// corners.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_seed.h"
#include "patch/patch_surface.h"

namespace rpu::patch {
namespace {

using scene::Patch;
using scene::PatchType;

std::vector<Vec3> random_grid(int nu, int nv, unsigned seed) {
  std::mt19937 rng(rpu::test::seed(seed));
  std::uniform_real_distribution<double> d(-2.0, 2.0);
  std::vector<Vec3> pts;
  for (int i = 0; i < nu * nv; ++i) pts.push_back({d(rng), d(rng), d(rng)});
  return pts;
}

Patch bezier(int du, int dv, unsigned seed) {
  Patch p;
  p.type = PatchType::kBezier;
  p.degree_u = du, p.degree_v = dv;
  p.size_u = du + 1, p.size_v = dv + 1;
  p.control_points = random_grid(p.size_u, p.size_v, seed);
  return p;
}

// A clamped knot vector with `size - degree - 1` interior knots, non-uniform, on [a, b].
std::vector<double> clamped_knots(int degree, int size, double a, double b, unsigned seed,
                                  bool repeat_interior = false) {
  std::mt19937 rng(rpu::test::seed(seed));
  std::uniform_real_distribution<double> d(a, b);
  std::vector<double> interior;
  for (int i = 0; i < size - degree - 1; ++i) interior.push_back(d(rng));
  std::sort(interior.begin(), interior.end());
  if (repeat_interior && interior.size() >= 2) interior[1] = interior[0];
  std::vector<double> k(static_cast<size_t>(degree + 1), a);
  k.insert(k.end(), interior.begin(), interior.end());
  k.insert(k.end(), static_cast<size_t>(degree + 1), b);
  return k;
}

Patch bspline(int du, int dv, int nu, int nv, unsigned seed, bool repeat_interior = false) {
  Patch p;
  p.type = PatchType::kBSpline;
  p.degree_u = du, p.degree_v = dv;
  p.size_u = nu, p.size_v = nv;
  p.control_points = random_grid(nu, nv, seed);
  p.knots_u = clamped_knots(du, nu, -1.0, 3.0, seed + 1, repeat_interior);
  p.knots_v = clamped_knots(dv, nv, 2.0, 2.5, seed + 2);
  return p;
}

Patch nurbs(int du, int dv, int nu, int nv, unsigned seed) {
  Patch p = bspline(du, dv, nu, nv, seed);
  p.type = PatchType::kNurbs;
  std::mt19937 rng(rpu::test::seed(seed + 7));
  std::uniform_real_distribution<double> d(0.2, 3.0);
  for (int i = 0; i < nu * nv; ++i) p.weights.push_back(d(rng));
  return p;
}

double dist(const Vec3& a, const Vec3& b) { return length(a - b); }

void expect_derivatives_match_differences(const PatchSurface& s) {
  const double h = 1e-6;
  // Stay off knots (derivatives may jump there) by sampling at irrational-ish offsets.
  for (double u : {0.0131, 0.2718, 0.5, 0.7071, 0.9859}) {
    for (double v : {0.0173, 0.3141, 0.6180, 0.9437}) {
      const SurfacePoint sp = s.evaluate(u, v);
      const Vec3 du = (s.point(u + h, v) - s.point(u - h, v)) / (2 * h);
      const Vec3 dv = (s.point(u, v + h) - s.point(u, v - h)) / (2 * h);
      const double scale = 1.0 + length(sp.du) + length(sp.dv);
      EXPECT_LT(dist(sp.du, du), 1e-6 * scale) << "u=" << u << " v=" << v;
      EXPECT_LT(dist(sp.dv, dv), 1e-6 * scale) << "u=" << u << " v=" << v;
      EXPECT_LT(dist(sp.p, s.point(u, v)), 1e-13 * (1.0 + length(sp.p)));  // point-only path
    }
  }
}

TEST(PatchSurface, BezierDerivativesMatchCentralDifferences) {
  for (int du = 1; du <= 5; ++du)
    for (int dv : {1, 3, 4}) expect_derivatives_match_differences(PatchSurface(bezier(du, dv, 10u * du + dv)));
  expect_derivatives_match_differences(PatchSurface(bezier(10, 10, 5)));
}

TEST(PatchSurface, BSplineDerivativesMatchCentralDifferences) {
  expect_derivatives_match_differences(PatchSurface(bspline(3, 3, 7, 5, 1)));
  expect_derivatives_match_differences(PatchSurface(bspline(2, 1, 6, 4, 2)));
  expect_derivatives_match_differences(PatchSurface(bspline(4, 3, 9, 8, 3, true)));
}

TEST(PatchSurface, NurbsDerivativesMatchCentralDifferences) {
  expect_derivatives_match_differences(PatchSurface(nurbs(3, 3, 6, 6, 4)));
  expect_derivatives_match_differences(PatchSurface(nurbs(2, 2, 3, 9, 5)));
  expect_derivatives_match_differences(PatchSurface(nurbs(1, 3, 4, 4, 6)));
}

TEST(PatchSurface, BasisIsPartitionOfUnity) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const int degree = 1 + static_cast<int>(seed % 5);
    const int size = degree + 1 + static_cast<int>(seed % 7);
    const std::vector<double> k = clamped_knots(degree, size, 0.0, 1.0, seed, seed % 2 == 0);
    for (int s = 0; s <= 200; ++s) {
      const double t = s / 200.0;
      const int span = find_knot_span(k, degree, size, t);
      ASSERT_GE(span, degree);
      ASSERT_LT(span, size);
      ASSERT_LE(k[static_cast<size_t>(span)], t);
      ASSERT_LT(k[static_cast<size_t>(span)], k[static_cast<size_t>(span) + 1]);
      double n[kMaxPatchDegree + 1], dn[kMaxPatchDegree + 1];
      bspline_basis(k, degree, span, t, n, dn);
      double sum = 0.0, dsum = 0.0;
      for (int r = 0; r <= degree; ++r) {
        EXPECT_GE(n[r], -1e-15);
        sum += n[r];
        dsum += dn[r];
      }
      EXPECT_NEAR(sum, 1.0, 1e-13) << "t=" << t;
      EXPECT_NEAR(dsum, 0.0, 1e-9) << "t=" << t;  // derivative of the constant 1
    }
  }
}

// Affine invariance follows from the partition of unity: translating every control point
// translates the surface (also for NURBS, whose rational basis sums to one).
TEST(PatchSurface, TranslatingControlPointsTranslatesSurface) {
  for (const Patch& p0 : {bezier(3, 2, 1), bspline(3, 3, 6, 5, 2), nurbs(2, 3, 5, 6, 3)}) {
    Patch p1 = p0;
    const Vec3 shift{0.5, -3.0, 7.25};
    for (Vec3& c : p1.control_points) c += shift;
    const PatchSurface a(p0), b(p1);
    for (double u : {0.0, 0.3, 1.0})
      for (double v : {0.0, 0.55, 1.0}) EXPECT_LT(dist(a.point(u, v) + shift, b.point(u, v)), 1e-12);
  }
}

TEST(PatchSurface, NurbsWithUnitWeightsEqualsBSpline) {
  const Patch b = bspline(3, 2, 7, 6, 9);
  Patch n = b;
  n.type = PatchType::kNurbs;
  n.weights.assign(static_cast<size_t>(b.size_u * b.size_v), 1.0);
  const PatchSurface sb(b), sn(n);
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double u = i / 20.0, v = j / 20.0;
      const SurfacePoint pb = sb.evaluate(u, v), pn = sn.evaluate(u, v);
      EXPECT_LT(dist(pb.p, pn.p), 1e-12);
      EXPECT_LT(dist(pb.du, pn.du), 1e-10);
      EXPECT_LT(dist(pb.dv, pn.dv), 1e-10);
    }
  // Scaling every weight by the same factor changes nothing either.
  Patch n2 = n;
  for (double& w : n2.weights) w = 3.5;
  const PatchSurface sn2(n2);
  EXPECT_LT(dist(sn2.point(0.37, 0.81), sb.point(0.37, 0.81)), 1e-12);
}

TEST(PatchSurface, BezierEqualsClampedBSpline) {
  for (int du = 1; du <= 6; ++du) {
    const Patch bz = bezier(du, 3, 40u + du);
    Patch bs = bz;
    bs.type = PatchType::kBSpline;
    bs.knots_u.assign(static_cast<size_t>(du + 1), 5.0);
    bs.knots_u.insert(bs.knots_u.end(), static_cast<size_t>(du + 1), 6.0);  // any interval
    bs.knots_v = {0, 0, 0, 0, 1, 1, 1, 1};
    const PatchSurface a(bz), b(bs);
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 16; ++j) {
        const double u = i / 16.0, v = j / 16.0;
        const SurfacePoint pa = a.evaluate(u, v), pb = b.evaluate(u, v);
        EXPECT_LT(dist(pa.p, pb.p), 1e-12);
        EXPECT_LT(dist(pa.du, pb.du), 1e-10);
        EXPECT_LT(dist(pa.dv, pb.dv), 1e-10);
      }
  }
}

// De Casteljau's construction written out independently (repeated linear interpolation of the
// control net) agrees with the Bernstein evaluation.
TEST(PatchSurface, BezierMatchesDeCasteljau) {
  const Patch p = bezier(3, 4, 77);
  const PatchSurface s(p);
  const auto casteljau = [](std::vector<Vec3> c, double t) {
    for (size_t r = c.size() - 1; r > 0; --r)
      for (size_t i = 0; i < r; ++i) c[i] = c[i] * (1 - t) + c[i + 1] * t;
    return c[0];
  };
  for (double u : {0.0, 0.2, 0.5, 0.9})
    for (double v : {0.1, 0.6, 1.0}) {
      std::vector<Vec3> rows;
      for (int i = 0; i < p.size_u; ++i) {
        std::vector<Vec3> row(p.control_points.begin() + i * p.size_v,
                              p.control_points.begin() + (i + 1) * p.size_v);
        rows.push_back(casteljau(row, v));
      }
      EXPECT_LT(dist(casteljau(rows, u), s.point(u, v)), 1e-13);
    }
}

TEST(PatchSurface, ClampedEndsInterpolateCornerPoints) {
  for (const Patch& p : {bezier(3, 3, 1), bezier(2, 5, 2), bspline(3, 3, 8, 6, 3),
                         bspline(2, 4, 5, 7, 4), nurbs(3, 2, 6, 4, 5)}) {
    const PatchSurface s(p);
    const auto cp = [&](int iu, int iv) { return p.control_points[static_cast<size_t>(iu * p.size_v + iv)]; };
    EXPECT_LT(dist(s.point(0, 0), cp(0, 0)), 1e-12);
    EXPECT_LT(dist(s.point(0, 1), cp(0, p.size_v - 1)), 1e-12);
    EXPECT_LT(dist(s.point(1, 0), cp(p.size_u - 1, 0)), 1e-12);
    EXPECT_LT(dist(s.point(1, 1), cp(p.size_u - 1, p.size_v - 1)), 1e-12);
    // Outside the domain the parameters are clamped.
    EXPECT_EQ(s.point(-0.5, 1.5), s.point(0, 1));
  }
}

// The homogeneous form projects to the Cartesian point and its derivatives (quotient rule).
TEST(PatchSurface, HomogeneousFormProjectsToSurface) {
  const PatchSurface s(nurbs(3, 3, 5, 5, 11));
  for (double u : {0.1, 0.45, 0.8})
    for (double v : {0.05, 0.5, 0.95}) {
      const HomogeneousPoint h = s.homogeneous(u, v);
      const SurfacePoint sp = s.evaluate(u, v);
      EXPECT_GT(h.w, 0.0);
      EXPECT_LT(dist(Vec3{h.hx, h.hy, h.hz} / h.w, sp.p), 1e-12);
      const Vec3 pu = (Vec3{h.hx_u, h.hy_u, h.hz_u} * h.w - Vec3{h.hx, h.hy, h.hz} * h.w_u) / (h.w * h.w);
      EXPECT_LT(dist(pu, sp.du), 1e-10);
    }
}

// A quarter circle as a rational quadratic (weights 1, √2/2, 1) is exact: |S| = 1 everywhere.
TEST(PatchSurface, NurbsQuarterCircleIsExact) {
  Patch p;
  p.type = PatchType::kNurbs;
  p.degree_u = 2, p.degree_v = 1;
  p.size_u = 3, p.size_v = 2;
  const double w = std::sqrt(0.5);
  p.control_points = {{1, 0, 0}, {1, 0, 1}, {1, 1, 0}, {1, 1, 1}, {0, 1, 0}, {0, 1, 1}};
  p.weights = {1, 1, w, w, 1, 1};
  p.knots_u = {0, 0, 0, 1, 1, 1};
  p.knots_v = {0, 0, 1, 1};
  const PatchSurface s(p);
  for (int i = 0; i <= 50; ++i) {
    const Vec3 q = s.point(i / 50.0, 0.3);
    EXPECT_NEAR(std::hypot(q.x, q.y), 1.0, 1e-14);
    EXPECT_NEAR(q.z, 0.3, 1e-14);
  }
}

}  // namespace
}  // namespace rpu::patch

namespace rpu::patch {
namespace {

// Closed directions: a torus-like ring closes in both directions; a collapsed row (a pole) or
// an open sheet does not.
TEST(PatchSurface, ClosedDirectionsAreDetected) {
  Patch ring;
  ring.type = PatchType::kBSpline;
  ring.degree_u = ring.degree_v = 2;
  ring.size_u = 3, ring.size_v = 5;
  ring.knots_u = {0, 0, 0, 1, 1, 1};
  ring.knots_v = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
  const Vec3 c[5] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 5; ++j) ring.control_points.push_back(c[j] * (1.0 + i) + Vec3{0, 0, double(i)});
  const PatchSurface s(ring);
  EXPECT_FALSE(s.closed_u());
  EXPECT_TRUE(s.closed_v());
  EXPECT_LT(length(s.point(0.3, 0.0) - s.point(0.3, 1.0)), 1e-12);

  Patch pole = bezier(3, 3, 3);
  for (int j = 0; j < 4; ++j) pole.control_points[static_cast<size_t>(j)] = {0, 0, 5};  // row 0 collapsed
  for (int j = 0; j < 4; ++j) pole.control_points[static_cast<size_t>(12 + j)] = {0, 0, 5};
  EXPECT_FALSE(PatchSurface(pole).closed_u());
  EXPECT_FALSE(PatchSurface(bezier(3, 3, 4)).closed_u());
  EXPECT_FALSE(PatchSurface(bezier(3, 3, 4)).closed_v());
}

}  // namespace
}  // namespace rpu::patch
