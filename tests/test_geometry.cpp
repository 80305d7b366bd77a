// Geometry of spherical interpolation (docs/algorithms.md §1), the PVP capture test (§1.1),
// normals, the classification grid and screen bins.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_seed.h"
#include "common/error.h"
#include "scene/camera.h"
#include "scene/classification_grid.h"
#include "scene/compiled_scene.h"
#include "scene/normals.h"
#include "scene/screen_bins.h"
#include "scene/segment.h"
#include "tracer/float_tracer.h"

namespace rpu::scene {
namespace {

constexpr unsigned kSeed = 20261121;

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3 v{g(rng), g(rng), g(rng)};
    if (length(v) > 1e-3) return normalize(v);
  }
}

Segment must_make(const Vec3& p1, const Vec3& p2, const Vec3& n1, const Vec3& n2) {
  SegmentDefect defect;
  int end;
  auto s = make_segment(p1, p2, n1, n2, defect, end);
  EXPECT_TRUE(s.has_value());
  return *s;
}

// The seed's construction (seed 000 / seed 001 eqs 11–23): reference sphere through the end
// points centred on the normal line, guide line p(t) + vo·s, root on the minor arc. The
// quadratic is solved in its cancellation-free form.
Vec3 seed_guide_offset(const Vec3& p1, const Vec3& p2, const Vec3& pk, const Vec3& nk, double t) {
  const Vec3 d = p2 - p1, c0 = (p1 + p2) * 0.5;
  const double sigma = dot(c0 - pk, d) / dot(nk, d);
  const Vec3 o = pk + nk * sigma;
  const double R2 = length_squared(pk - o);
  const Vec3 vo = c0 - o;
  const Vec3 pt = p1 + d * t;
  // |pt + vo·s - o|² = R²:  a s² + b s + c = 0.
  const Vec3 w = pt - o;
  const double a = dot(vo, vo), b = 2.0 * dot(vo, w), c = dot(w, w) - R2;
  const double disc = std::sqrt(std::max(0.0, b * b - 4 * a * c));
  const double qq = -0.5 * (b + std::copysign(disc, b));
  const double r1 = qq / a, r2 = c / qq;
  return vo * std::max(r1, r2);  // the larger root lies on the minor arc
}

TEST(Guide, ClosedFormEqualsSeedConstruction) {
  std::mt19937_64 rng(rpu::test::seed(kSeed));
  std::printf("seed %u\n", kSeed);
  std::uniform_real_distribution<double> coord(-10.0, 10.0), tdist(0.01, 0.99);
  int checked = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const Vec3 p1{coord(rng), coord(rng), coord(rng)}, p2{coord(rng), coord(rng), coord(rng)};
    const Vec3 dhat = normalize(p2 - p1);
    Vec3 n[2] = {random_unit(rng), random_unit(rng)};
    // Keep the reference spheres finite and the normals away from the chord.
    if (std::fabs(dot(n[0], dhat)) < 0.01 || std::fabs(dot(n[1], dhat)) < 0.01) continue;
    if (std::fabs(dot(n[0], dhat)) > 0.99 || std::fabs(dot(n[1], dhat)) > 0.99) continue;
    const Segment s = must_make(p1, p2, n[0], n[1]);
    for (int k = 0; k < 2; ++k) {
      const double t = tdist(rng);
      const Vec3 expected = seed_guide_offset(p1, p2, k == 0 ? p1 : p2, n[k], t);
      const Vec3 actual = s.guide[k].u * guide_offset(s.guide[k], s.L2, t);
      const double err = length(actual - expected) / length(expected);
      ASSERT_LE(err, 1e-9) << "trial " << trial << " end " << k << " t " << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
}

TEST(Guide, EndPointsAreExact) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 1));
  std::uniform_real_distribution<double> coord(-1e3, 1e3);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 p1{coord(rng), coord(rng), coord(rng)}, p2{coord(rng), coord(rng), coord(rng)};
    const Segment s = must_make(p1, p2, random_unit(rng), random_unit(rng));
    EXPECT_EQ(curve_point(s, 0.0), p1);
    EXPECT_EQ(curve_point(s, 1.0), p2);
  }
}

TEST(Guide, EndTangentIsPerpendicularToNormal) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 2));
  std::uniform_real_distribution<double> coord(-5, 5);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 p1{coord(rng), coord(rng), coord(rng)}, p2{coord(rng), coord(rng), coord(rng)};
    const Segment s = must_make(p1, p2, random_unit(rng), random_unit(rng));
    EXPECT_LE(std::fabs(dot(normalize(curve_tangent(s, 0.0)), s.n1)), 1e-9);
    EXPECT_LE(std::fabs(dot(normalize(curve_tangent(s, 1.0)), s.n2)), 1e-9);
  }
}

TEST(Guide, TangentDirectionContinuousAtJoints) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 3));
  std::printf("seed %u\n", kSeed + 3);
  std::uniform_real_distribution<double> coord(-3, 3);
  double worst = 0.0;
  int joints = 0, hairpins = 0;
  for (int curve = 0; curve < 300; ++curve) {
    const bool closed = curve % 2 == 0;
    std::vector<Vec3> pts;
    for (int k = 0; k < 12; ++k) pts.push_back({coord(rng), coord(rng), coord(rng)});
    const auto normals = derive_normals(pts, closed, false);
    const size_t n = pts.size(), segs = closed ? n : n - 1;
    std::vector<Segment> s;
    for (size_t k = 0; k < segs; ++k)
      s.push_back(must_make(pts[k], pts[(k + 1) % n], normals[k], normals[(k + 1) % n]));
    for (size_t k = 0; k + 1 < segs + (closed ? 1 : 0); ++k) {
      const Segment& a = s[k];
      const Segment& b = s[(k + 1) % segs];
      // At a hairpin ((p_{i+1} - p_{i-1})·d ≤ 0 for an adjacent chord) no minor arc of either
      // segment can leave along T: the method reverses there by construction. Elsewhere the
      // direction must be continuous.
      const Vec3 T = a.d + b.d;
      if (dot(T, a.d) <= 0.0 || dot(T, b.d) <= 0.0) {
        ++hairpins;
        continue;
      }
      const Vec3 in = normalize(curve_tangent(a, 1.0));
      const Vec3 out = normalize(curve_tangent(b, 0.0));
      const double angle = std::atan2(length(cross(in, out)), dot(in, out));
      worst = std::max(worst, angle);
      ++joints;
      ASSERT_LE(angle, 1e-6) << "curve " << curve << " joint " << k + 1;
    }
  }
  EXPECT_GT(joints, 2000);
  std::printf("%d joints, worst angle %.3g rad (%d hairpin joints skipped)\n", joints, worst,
              hairpins);
}

TEST(Guide, DegenerateSegments) {
  SegmentDefect defect;
  int end = -1;
  const Vec3 a{0, 0, 0}, b{1, 0, 0};
  EXPECT_FALSE(make_segment(a, a, {0, 1, 0}, {0, 1, 0}, defect, end));
  EXPECT_EQ(defect, SegmentDefect::kRepeatedPoint);
  EXPECT_FALSE(make_segment(a, b, {0, 1, 0}, {1, 0, 0}, defect, end));
  EXPECT_EQ(defect, SegmentDefect::kNormalParallelToChord);
  EXPECT_EQ(end, 1);
  EXPECT_FALSE(make_segment(a, b, {0, 0, 0}, {0, 1, 0}, defect, end));
  EXPECT_EQ(defect, SegmentDefect::kZeroNormal);
  EXPECT_EQ(end, 0);
  // n·d = 0: centre at infinity, straight guide, the curve is the chord.
  auto s = make_segment(a, b, {0, 1, 0}, {0, 0, 1}, defect, end);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->guide[0].straight && s->guide[1].straight);
  EXPECT_EQ(curve_point(*s, 0.25), (Vec3{0.25, 0, 0}));
  // Normal nearly along the chord: a half circle, finite everywhere.
  s = make_segment(a, b, normalize(Vec3{1, 1e-6, 0}), normalize(Vec3{-1, 1e-6, 0}), defect, end);
  ASSERT_TRUE(s);
  EXPECT_NEAR(length(curve_point(*s, 0.5) - s->c0), 0.5, 1e-5);
}

TEST(Guide, CurveStaysInsideInterpolationSphere) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 4));
  std::uniform_real_distribution<double> coord(-5, 5), tdist(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 p1{coord(rng), coord(rng), coord(rng)}, p2{coord(rng), coord(rng), coord(rng)};
    const Segment s = must_make(p1, p2, random_unit(rng), random_unit(rng));
    for (int k = 0; k < 8; ++k)
      EXPECT_LE(length(curve_point(s, tdist(rng)) - s.c0), s.R * (1 + 1e-12));
  }
}

TEST(Normals, DerivedNormalsPointToConcaveSideAndHandleStraightRuns) {
  // A square's corners: each normal points to the centre.
  const std::vector<Vec3> sq = {{1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  const auto n = derive_normals(sq, true, true);
  for (size_t k = 0; k < sq.size(); ++k) EXPECT_NEAR(dot(n[k], normalize(-sq[k])), 1.0, 1e-12);
  // Collinear points: a deterministic perpendicular, in the plane for textures.
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {3, 3, 0}};
  const auto nl = derive_normals(line, false, true);
  for (const auto& v : nl) {
    EXPECT_NEAR(length(v), 1.0, 1e-12);
    EXPECT_NEAR(dot(v, normalize(Vec3{1, 1, 0})), 0.0, 1e-12);
    EXPECT_EQ(v.z, 0.0);
  }
  const auto n3 = derive_normals({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}}, false, false);
  for (const auto& v : n3) EXPECT_NEAR(v.z, 0.0, 1e-12);
}

// ---- PVP capture test (docs/algorithms.md §1.1) ----

CameraFrame dyadic_camera() {
  CameraFrame cam;
  cam.eye = {0, 0, 0};
  cam.W = {0, 1, 0};
  cam.U = {1, 0, 0};
  cam.V = {0, 0, 1};
  cam.half = 1.0;
  cam.width = 8;
  cam.height = 6;
  cam.sigma = 0.25;
  return cam;
}

// Which pixels capture X, by the sign test over the whole image.
std::vector<std::pair<int, int>> capturing_pixels(const CameraFrame& cam, const Vec3& X) {
  std::vector<std::pair<int, int>> out;
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      double depth;
      if (capture_test(cam, i, j, X, depth)) out.push_back({i, j});
    }
  return out;
}

TEST(Capture, SignTestEqualsProjectionIncludingPixelEdges) {
  const CameraFrame cam = dyadic_camera();
  int on_edges = 0, total = 0;
  // Screen coordinates on a lattice of σ/4 (every pixel edge included, and beyond the image),
  // depths powers of two so that a = x·c and b = y·c are exact.
  for (double c : {0.5, 1.0, 4.0, 1024.0})
    for (int xi = -20; xi <= 20; ++xi)
      for (int yi = -16; yi <= 16; ++yi) {
        const double x = xi * cam.sigma / 4, y = yi * cam.sigma / 4;
        const Vec3 X{x * c, c, y * c};
        int pi = -1, pj = -1;
        const bool inside = project_to_pixel(cam, X, pi, pj);
        const auto got = capturing_pixels(cam, X);
        ++total;
        on_edges += (xi % 4 == 0) || (yi % 4 == 0);
        if (inside) {
          ASSERT_EQ(got.size(), 1u) << "x " << x << " y " << y << " c " << c;
          EXPECT_EQ(got[0], std::make_pair(pi, pj)) << "x " << x << " y " << y;
        } else {
          EXPECT_TRUE(got.empty()) << "x " << x << " y " << y;
        }
      }
  EXPECT_GT(on_edges, 1000);
  // Edge conventions spelled out: the left and top edges belong to the pixel.
  double depth;
  EXPECT_TRUE(capture_test(cam, 4, 3, {0.0, 1.0, 0.0}, depth));     // x = x_4, y = y_3
  EXPECT_FALSE(capture_test(cam, 3, 3, {0.0, 1.0, 0.0}, depth));    // right edge of pixel 3
  EXPECT_FALSE(capture_test(cam, 4, 2, {0.0, 1.0, 0.0}, depth));    // bottom edge of row 2
  // Behind the eye or in the eye plane: never captured.
  EXPECT_TRUE(capturing_pixels(cam, {0.1, -1.0, 0.1}).empty());
  EXPECT_TRUE(capturing_pixels(cam, {0.0, 0.0, 0.0}).empty());
  std::printf("%d points, %d on pixel edges\n", total, on_edges);
}

TEST(Capture, SignTestEqualsProjectionForRandomCameras) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 5));
  std::uniform_real_distribution<double> coord(-5, 5);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Camera c{{coord(rng), coord(rng), coord(rng)}, {0, 0, 0}, {0, 0, 1}, 50.0, 16, 12};
    const CameraFrame cam = make_camera_frame(c, "test");
    for (int k = 0; k < 100; ++k) {
      const Vec3 X{coord(rng) * 0.4, coord(rng) * 0.4, coord(rng) * 0.4};
      const Vec3 q = X - cam.eye;
      const double cc = dot(q, cam.W);
      if (cc <= 0) continue;
      // Skip points within rounding of an edge (the dyadic test covers edges exactly).
      const double x = dot(q, cam.U) / cc, y = dot(q, cam.V) / cc;
      const double fx = (x - cam.x_edge(0)) / cam.sigma, fy = (cam.y_edge(0) - y) / cam.sigma;
      if (std::fabs(fx - std::round(fx)) < 1e-9 || std::fabs(fy - std::round(fy)) < 1e-9) continue;
      int pi = -1, pj = -1;
      const bool inside = project_to_pixel(cam, X, pi, pj);
      const auto got = capturing_pixels(cam, X);
      ASSERT_EQ(got.size(), inside ? 1u : 0u);
      if (inside) {
        EXPECT_EQ(got[0], std::make_pair(pi, pj));
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
}

TEST(Camera, DegenerateCamerasAreRejected) {
  EXPECT_THROW(make_camera_frame({{0, 0, 0}, {0, 0, 0}, {0, 0, 1}, 40, 8, 8}, "s"), rpu::Error);
  EXPECT_THROW(make_camera_frame({{0, 0, 5}, {0, 0, 0}, {0, 0, 1}, 40, 8, 8}, "s"), rpu::Error);
  try {
    make_camera_frame({{0, 0, 5}, {0, 0, 0}, {0, 0, 1}, 40, 8, 8}, "s.json");
  } catch (const rpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: camera.up"), std::string::npos) << e.what();
  }
}

// ---- classification grid and screen bins are conservative ----

TEST(ClassificationGrid, ListsEveryCoveringSegment) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 6));
  std::uniform_real_distribution<double> coord(-50, 50), step(-4, 4), unit(0, 1);
  std::vector<CompiledSegment> segs;
  for (int line = 0; line < 40; ++line) {
    std::vector<Vec3> pts{{coord(rng), coord(rng), 0}};
    for (int k = 0; k < 8; ++k) pts.push_back(pts.back() + Vec3{step(rng), step(rng), 0});
    const auto normals = derive_normals(pts, false, true);
    for (size_t k = 0; k + 1 < pts.size(); ++k) {
      SegmentDefect defect;
      int end;
      auto s = make_segment(pts[k], pts[k + 1], normals[k], normals[k + 1], defect, end);
      if (s) segs.push_back({*s, line, static_cast<int>(k), 0.3 + unit(rng)});
    }
  }
  const auto grid = ClassificationGrid::build(segs);
  int covered = 0;
  for (int k = 0; k < 200000; ++k) {
    const Vec3 p{coord(rng) * 1.2, coord(rng) * 1.2, 0};
    const auto span = grid.lookup(p.x, p.y);
    for (size_t s = 0; s < segs.size(); ++s) {
      if (!tracer::texture_covers(segs[s], p)) continue;
      ++covered;
      ASSERT_NE(std::find(span.begin(), span.end(), static_cast<std::uint32_t>(s)), span.end())
          << "point (" << p.x << ", " << p.y << ") segment " << s;
    }
  }
  EXPECT_GT(covered, 1000);
  std::printf("grid %dx%d, cell %.3g, %zu entries for %zu segments\n", grid.columns(), grid.rows(),
              grid.cell_size(), grid.total_entries(), segs.size());
}

TEST(ScreenBins, SphereBoundsContainEveryProjectedPoint) {
  std::mt19937_64 rng(rpu::test::seed(kSeed + 7));
  std::uniform_real_distribution<double> coord(-3, 3);
  const Camera c{{0, -8, 3}, {0, 0, 0}, {0, 0, 1}, 60.0, 64, 48};
  const CameraFrame cam = make_camera_frame(c, "test");
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 centre{coord(rng), coord(rng) * 2, coord(rng)};
    const double r = 0.05 + std::fabs(coord(rng)) * 0.5;
    int i0, i1, j0, j1;
    const bool any = sphere_screen_bounds(cam, centre, r, i0, i1, j0, j1);
    for (int k = 0; k < 50; ++k) {
      std::mt19937_64 local(rng());
      const Vec3 X = centre + random_unit(local) * (r * std::uniform_real_distribution<double>(0, 1)(local));
      int i, j;
      if (!project_to_pixel(cam, X, i, j)) continue;
      ASSERT_TRUE(any);
      EXPECT_TRUE(i >= i0 && i <= i1 && j >= j0 && j <= j1) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace rpu::scene
