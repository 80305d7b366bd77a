// Modelling with patches (seed 003): Coons → Bézier (eqs 14-17) and the volume of closed Bézier
// models (eqs 18-27): exact, graphical integration, slices; closedness and orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "test_seed.h"
#include "common/error.h"
#include "patch/coons.h"
#include "patch/patch_surface.h"
#include "patch/volume.h"
#include "scene/scene_json.h"

namespace rpu::patch {
namespace {

std::vector<scene::Patch> bezier_sphere() {
  return scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/bezier_sphere.json").patches;
}

// The volume of the 8-patch Bézier sphere, derived independently of the code under test: the
// model is a tensor product of the quarter arc c(u) (control points (1,0), (1,k), (k,1), (0,1),
// k = 4(√2 − 1)/3) around z and the same arc as meridian (r(v), z(v)), so every section z(v) is the
// arc-bounded region scaled by r(v): V = 2 · 4·A_q · ∫₀¹ r(v)² z'(v) dv with
// A_q = ½ ∫₀¹ (c_x c_y' − c_y c_x') du. Both integrals of polynomials, done symbolically (sympy):
// V = (5168·√2 − 5108) / 525.
const double kBezierSphereVolume = (5168.0 * std::sqrt(2.0) - 5108.0) / 525.0;

// A face of the unit cube [0,1]³ as a bicubic Bézier patch with a bilinear (uniform) control net
// from corner o along a and b; S_u × S_v = a × b must point outward.
scene::Patch face(Vec3 o, Vec3 a, Vec3 b) {
  scene::Patch p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.control_points.push_back(o + a * (i / 3.0) + b * (j / 3.0));
  return p;
}
std::vector<scene::Patch> unit_cube() {
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1}, o{0, 0, 0};
  return {face(o, y, x), face(z, x, y),   // bottom (normal −z), top (+z)
          face(o, z, y), face(x, y, z),   // x = 0 (−x), x = 1 (+x)
          face(o, x, z), face(y, z, x)};  // y = 0 (−y), y = 1 (+y)
}
scene::Patch flipped(scene::Patch p) {  // swap u and v: reverses the normal
  scene::Patch q = p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) q.control_points[i * 4 + j] = p.control_points[j * 4 + i];
  return q;
}

TEST(Volume, BezierSphereExact) {
  const auto sphere = bezier_sphere();
  const double exact = exact_volume(sphere);
  EXPECT_NEAR(exact, kBezierSphereVolume, 1e-12 * kBezierSphereVolume);
  EXPECT_NEAR(exact_volume_gauss(sphere), kBezierSphereVolume, 1e-12 * kBezierSphereVolume);
  // It is not the unit sphere: slightly bigger (the arcs bulge outward by up to 2.7e-4).
  EXPECT_GT(exact, 4.0 / 3.0 * M_PI);
  EXPECT_LT(exact, 4.0 / 3.0 * M_PI * 1.002);
}

TEST(Volume, GraphicalIntegrationConverges) {
  const auto sphere = bezier_sphere();
  const double v = kBezierSphereVolume;
  const double e10 = std::abs(graphical_volume(sphere, 10, 10) - v) / v;
  const double e100 = std::abs(graphical_volume(sphere, 100, 100) - v) / v;
  EXPECT_GT(e10, 1e-5);  // not exact: a quadrature
  EXPECT_LT(e10, 1e-2);
  EXPECT_NEAR(e10 / e100, 100.0, 10.0);  // midpoint rule: O(1/n²)
  // The nodes exactly as eqs 23-24 print them (i/(n − 1), weight 1/n): only O(1/n).
  const double t10 = std::abs(graphical_volume(sphere, 10, 10, GraphicalNodes::kThesisEq24) - v) / v;
  const double t100 =
      std::abs(graphical_volume(sphere, 100, 100, GraphicalNodes::kThesisEq24) - v) / v;
  EXPECT_GT(t10, e10);
  EXPECT_NEAR(t10 / t100, 10.0, 2.0);
}

TEST(Volume, SlicesReportTheirError) {
  const auto sphere = bezier_sphere();
  const double v = kBezierSphereVolume;
  const SliceVolume s10 = slice_volume(sphere, 10);
  const SliceVolume s40 = slice_volume(sphere, 40);
  EXPECT_NEAR(s10.z_min, -1, 1e-12);
  EXPECT_NEAR(s10.z_max, 1, 1e-12);
  const double trap10 = (s10.trapezoid - v) / v, trap40 = (s40.trapezoid - v) / v;
  const double cav10 = (s10.cavalieri - v) / v, cav40 = (s40.cavalieri - v) / v;
  // The section area of a ball is concave in z: the trapezoid underestimates, the midpoint
  // (Cavalieri) overestimates, each by about 1/K² of the volume.
  EXPECT_LT(trap10, -0.002);
  EXPECT_GT(trap10, -0.03);
  EXPECT_GT(cav10, 0.001);
  EXPECT_LT(cav10, 0.02);
  EXPECT_NEAR(trap10 / trap40, 16.0, 2.0);
  EXPECT_NEAR(cav10 / cav40, 16.0, 2.0);
}

// Issue 24: the slice areas are sampled row by row in two passes and summed in blocks of patches
// in patch order; the result does not depend on the grid's storage: a model split into more
// patches along the same surface gives the same slices to rounding, and repeated runs give the
// same bits.
TEST(Volume, SlicesAreDeterministicAndBounded) {
  const auto sphere = bezier_sphere();
  const SliceVolume a = slice_volume(sphere, 10, 64), b = slice_volume(sphere, 10, 64);
  EXPECT_EQ(a.trapezoid, b.trapezoid);
  EXPECT_EQ(a.cavalieri, b.cavalieri);
  // The grid refines the tessellation: 64 → 256 changes the trapezoid estimate by less than the
  // method's own error, and 256 is what the table of docs/patches.md used.
  const SliceVolume c = slice_volume(sphere, 10, 256);
  EXPECT_NEAR(a.trapezoid, c.trapezoid, 1e-3 * c.trapezoid);
  EXPECT_NEAR(c.trapezoid, 4.149428589739, 1e-11);
}

// The work estimate of rpu volume (limits::kMaxVolumeWork): grows with the grid squared and
// linearly with the patches.
TEST(Volume, WorkEstimate) {
  const auto sphere = bezier_sphere();
  std::vector<scene::Patch> twice = sphere;
  twice.insert(twice.end(), sphere.begin(), sphere.end());
  EXPECT_EQ(volume_work(twice, 256), 2 * volume_work(sphere, 256));
  EXPECT_GT(volume_work(sphere, 512), 3 * volume_work(sphere, 256));
  EXPECT_GT(volume_work(sphere, 256, 1000), volume_work(sphere, 256, 10));
  EXPECT_LT(volume_work(sphere, 256), 1LL << 30);  // the default fits the budget
  EXPECT_GT(volume_work(sphere, 4096), 1LL << 30);  // the issue's --slice-grid 4096 does not
}

TEST(Volume, UnitCubeAndOrientation) {
  auto cube = unit_cube();
  EXPECT_NEAR(exact_volume(cube), 1.0, 1e-14);
  EXPECT_NEAR(exact_volume_gauss(cube), 1.0, 1e-14);
  EXPECT_NEAR(graphical_volume(cube, 10, 10), 1.0, 1e-14);  // bilinear: the rule is exact
  const SliceVolume s = slice_volume(cube, 7, 8);
  EXPECT_NEAR(s.trapezoid, 1.0, 1e-8);  // flat caps counted (planes nudged inside)
  EXPECT_NEAR(s.cavalieri, 1.0, 1e-12);
  ClosureReport c = check_closed_surface(cube);
  EXPECT_TRUE(c.closed && c.consistent) << c.problem;

  // Every face flipped: the same body, inward normals, negative volume, still consistent.
  std::vector<scene::Patch> inward;
  for (const auto& p : cube) inward.push_back(flipped(p));
  EXPECT_NEAR(exact_volume(inward), -1.0, 1e-14);
  EXPECT_NEAR(exact_volume_gauss(inward), -1.0, 1e-14);
  EXPECT_NEAR(slice_volume(inward, 5, 4).cavalieri, -1.0, 1e-12);
  c = check_closed_surface(inward);
  EXPECT_TRUE(c.closed && c.consistent) << c.problem;

  // One face flipped: inconsistent, named.
  auto mixed = cube;
  mixed[3] = flipped(mixed[3]);
  c = check_closed_surface(mixed);
  EXPECT_TRUE(c.closed);
  EXPECT_FALSE(c.consistent);
  EXPECT_NE(c.problem.find("oriented inconsistently"), std::string::npos) << c.problem;

  // One face missing: open, named.
  auto open = cube;
  open.pop_back();
  c = check_closed_surface(open);
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.open_edges, 4);
  EXPECT_NE(c.problem.find("do not close a volume"), std::string::npos) << c.problem;
  // Open: the two exact forms no longer agree (the divergence theorem needs a closed surface).
  EXPECT_GT(std::abs(exact_volume(open) - exact_volume_gauss(open)), 0.1);
}

TEST(Volume, PlanarOpeningsNeedNoCapInEq21) {
  // The cube without its top face: open, but the opening lies in the plane z = 1. Eq 21's field
  // (x, y, 0)/2 has no flux through that plane, so the thesis's form still gives 1; the (x,y,z)/3
  // form needs the cap's ⅓·z·area = ⅓.
  auto cube = unit_cube();
  cube.erase(cube.begin() + 1);
  EXPECT_FALSE(check_closed_surface(cube).closed);
  const ClosureReport c = check_closed_surface(cube, 1e-9, true);
  EXPECT_TRUE(c.closed && c.consistent) << c.problem;
  ASSERT_EQ(c.z_planar_openings.size(), 4u);
  EXPECT_NEAR(exact_volume(cube), 1.0, 1e-14);
  EXPECT_NEAR(exact_volume_gauss(cube), 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(cap_volume_term(cube, c.z_planar_openings), 1.0 / 3.0, 1e-14);
  // A side face missing is not planar in z: still refused.
  auto side = unit_cube();
  side.erase(side.begin() + 3);
  const ClosureReport s = check_closed_surface(side, 1e-9, true);
  EXPECT_FALSE(s.closed);
  EXPECT_NE(s.problem.find("does not lie in a plane z = const"), std::string::npos) << s.problem;
}

TEST(Volume, TeapotBodyCappedByItsLidGap) {
  // The Newell teapot without handle and spout (patches 0-11, 20-31) is closed except for the
  // flat annulus at z = 2.4 between the rim (radius 1.4) and the lid (radius 1.3), both made of
  // quarter arcs with k = 0.56. The area inside such an arc of radius 1 is
  // A_q(k) = (10 + 12k − 3k²)/20 (a polynomial integral, by hand), so the cap adds
  // ⅓ · 2.4 · 4·A_q(0.56)·(1.4² − 1.3²) to the (x,y,z)/3 form, and nothing to eq 21.
  const auto all =
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/teapot.json").patches;
  ASSERT_EQ(all.size(), 32u);
  std::vector<scene::Patch> body;
  for (int k = 0; k < 32; ++k)
    if (k < 12 || k >= 20) body.push_back(all[k]);
  EXPECT_FALSE(check_closed_surface(all, 1e-9, true).closed);  // handle and spout stay open
  const ClosureReport c = check_closed_surface(body, 1e-9, true);
  ASSERT_TRUE(c.closed && c.consistent) << c.problem;
  EXPECT_EQ(c.z_planar_openings.size(), 8u);
  const double k = 0.56, cap = 2.4 / 3 * 4 * (10 + 12 * k - 3 * k * k) / 20 * (1.4 * 1.4 - 1.3 * 1.3);
  const double oz = exact_volume(body), third = exact_volume_gauss(body);
  EXPECT_LT(oz, 0);  // the teapot's patches face inward
  EXPECT_NEAR(cap_volume_term(body, c.z_planar_openings), -cap, 1e-12);
  EXPECT_NEAR(third - cap, oz, 1e-12 * std::abs(oz));
}

TEST(Volume, BumpedCubeTopMatchesBernsteinMeans) {
  // Lift the top face's control points by h_ij: over the linear (x, y) = (u, v) parametrisation
  // the height is Σ h_ij B_i(u) B_j(v), whose mean is Σ h_ij / 16 (each cubic Bernstein
  // polynomial integrates to 1/4). Only interior points move, so the edges stay closed.
  auto cube = unit_cube();
  const double h[4] = {0.3, -0.2, 0.45, 0.1};
  const int inner[4] = {5, 6, 9, 10};
  double expected = 1.0;
  for (int k = 0; k < 4; ++k) {
    cube[1].control_points[inner[k]].z += h[k];
    expected += h[k] / 16;
  }
  EXPECT_TRUE(check_closed_surface(cube).closed);
  EXPECT_NEAR(exact_volume(cube), expected, 1e-14);
  EXPECT_NEAR(exact_volume_gauss(cube), expected, 1e-14);
  EXPECT_NEAR(slice_volume(cube, 400, 128).cavalieri, expected, 2e-4);
}

TEST(Volume, TranslationInvariantAndRequiresBezier) {
  auto sphere = bezier_sphere();
  for (auto& p : sphere)
    for (auto& c : p.control_points) c += Vec3{3.5, -2.0, 7.25};
  EXPECT_NEAR(exact_volume(sphere), kBezierSphereVolume, 1e-11);
  EXPECT_NEAR(exact_volume_gauss(sphere), kBezierSphereVolume, 1e-11);
  EXPECT_THROW(require_bezier({}, "x.json"), Error);
  scene::Patch b = sphere[0];
  b.type = scene::PatchType::kBSpline;
  try {
    require_bezier({sphere[0], b}, "x.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "x.json: patches[1]");
    EXPECT_NE(e.problem().find("B-spline"), std::string::npos);
  }
}

// ---- Coons → Bézier ----

TEST(Coons, BezierReproducesHermiteEverywhere) {
  std::mt19937 rng(rpu::test::seed(13));
  std::uniform_real_distribution<double> d(-1, 1);
  auto rv = [&] { return Vec3{d(rng), d(rng), d(rng)}; };
  for (int trial = 0; trial < 50; ++trial) {
    CoonsPatch c;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        c.p[a][b] = rv() * 10.0;
        c.pu[a][b] = rv() * 5.0;
        c.pv[a][b] = rv() * 5.0;
        c.puv[a][b] = rv() * 3.0;
      }
    const PatchSurface bez(coons_to_bezier_patch(c));
    double size = 0;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) size = std::max(size, length(c.p[a][b] - c.p[0][0]));
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const double u = i / 20.0, v = j / 20.0;
        ASSERT_LE(length(bez.point(u, v) - evaluate_coons(c, u, v)), 1e-12 * size)
            << "trial " << trial << " at " << u << "," << v;
      }
    // Corner tangents and twist of the Bézier form are those of the Hermite data.
    const SurfacePoint s = bez.evaluate(0, 0);
    EXPECT_LE(length(s.du - c.pu[0][0]), 1e-12 * size);
    EXPECT_LE(length(s.dv - c.pv[0][0]), 1e-12 * size);
  }
}

TEST(Coons, HermiteInterpolatesItsData) {
  CoonsPatch c;
  c.p = {{{Vec3{0, 0, 0}, Vec3{0, 1, 0.5}}, {Vec3{1, 0, 0.2}, Vec3{1, 1, 1}}}};
  c.pu = {{{Vec3{1, 0, 0}, Vec3{1, 0, 0.3}}, {Vec3{1, 0.1, 0}, Vec3{1, 0, 0}}}};
  c.pv = {{{Vec3{0, 1, 0}, Vec3{0, 1, 0}}, {Vec3{0, 1, 0.4}, Vec3{0, 1, 0}}}};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      EXPECT_LE(length(evaluate_coons(c, a, b) - c.p[a][b]), 1e-15);
      const double e = 1e-6;
      const double u = a ? 1 - e : e, v = b ? 1 - e : e;
      const Vec3 du = (evaluate_coons(c, u + e, v) - evaluate_coons(c, u - e, v)) / (2 * e);
      EXPECT_LE(length(du - c.pu[a][b]), 1e-5);
    }
}

// The thesis's modelling pipeline end to end: points on the unit sphere on a latitude/longitude
// grid (closed around z, poles as collapsed rows), Coons patches with eq 15 tangents and eq 16
// twists, converted to Bézier, then the volume.
TEST(Coons, GridOfSpherePointsIsAClosedModel) {
  const int rows = 16, cols = 9;  // 16 meridians (u, closed), 9 parallels from pole to pole (v)
  std::vector<Vec3> pts;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double lon = 2 * M_PI * i / rows, lat = -M_PI / 2 + M_PI * j / (cols - 1);
      pts.push_back({std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
    }
  for (TwistRule twist : {TwistRule::kThesisCross, TwistRule::kZero, TwistRule::kCentralDifference}) {
    CoonsGridOptions o;
    o.closed_u = true;
    o.twist = twist;
    const auto model = coons_grid_bezier(pts, rows, cols, o);
    ASSERT_EQ(model.size(), static_cast<size_t>(rows * (cols - 1)));
    // Every grid point is interpolated.
    const PatchSurface first(model[0]);
    EXPECT_LE(length(first.point(1, 1) - pts[1 * cols + 1]), 1e-14);
    const ClosureReport c = check_closed_surface(model);
    EXPECT_TRUE(c.closed && c.consistent) << c.problem;
    const double v = exact_volume(model);
    EXPECT_NEAR(exact_volume_gauss(model), v, 1e-12 * v);
    EXPECT_NEAR(v, 4.0 / 3.0 * M_PI, 0.03 * 4.0 / 3.0 * M_PI);
    // The numbers of docs/patches.md ("Modelling and volumes"), printed for the record.
    const double g10 = graphical_volume(model, 10, 10), g100 = graphical_volume(model, 100, 100);
    const SliceVolume s10 = slice_volume(model, 10, 32);  // 128 small patches: 32² cells each
    EXPECT_LT(std::abs(g100 - v), std::abs(g10 - v));
    std::printf("coons sphere 16x9, twist %s: exact %.12f, graphical 10x10 %+.3e %%, 100x100 "
                "%+.3e %%, slices 10 trapezoid %+.3e %%, Cavalieri %+.3e %%\n",
                twist == TwistRule::kThesisCross ? "eq 16"
                : twist == TwistRule::kZero      ? "zero"
                                                 : "central difference",
                v, 100 * (g10 - v) / v, 100 * (g100 - v) / v, 100 * (s10.trapezoid - v) / v,
                100 * (s10.cavalieri - v) / v);
  }
}

TEST(Coons, GridErrors) {
  EXPECT_THROW(coons_grid({{0, 0, 0}, {1, 0, 0}}, 1, 2), Error);
  EXPECT_THROW(coons_grid({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2, 2), Error);
  EXPECT_THROW(coons_grid({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, NAN}}, 2, 2), Error);
  const std::vector<Vec3> square{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  CoonsGridOptions o;
  o.twist = TwistRule::kZero;
  const auto flat = coons_grid(square, 2, 2, o);
  ASSERT_EQ(flat.size(), 1u);
  // A flat bilinear grid, one-sided tangents, no twist: the patch is the plane square itself.
  const PatchSurface s(coons_to_bezier_patch(flat[0]));
  EXPECT_LE(length(s.point(0.3, 0.6) - Vec3{0.3, 0.6, 0}), 1e-15);
  // Eq 16's twist P^u × P^v = (1,0,0) × (0,1,0) = e_z at every corner lifts the square by
  // (h10(u) + h11(u)) · (h10(v) + h11(v)) (Hermite tangent functions).
  const PatchSurface t(coons_to_bezier_patch(coons_grid(square, 2, 2)[0]));
  auto h = [](double x) { return (x * x * x - 2 * x * x + x) + (x * x * x - x * x); };
  EXPECT_NEAR(t.point(0.3, 0.6).z, h(0.3) * h(0.6), 1e-15);
  EXPECT_NEAR(h(0.3) * h(0.6), -0.004032, 1e-15);
}

}  // namespace
}  // namespace rpu::patch
