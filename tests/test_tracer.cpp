// The float tracer: ideal vs iterative process, binning and classification-grid invariance,
// degenerate geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "common/error.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tracer/float_tracer.h"

namespace rpu::tracer {
namespace {

using scene::CompiledScene;
using scene::Scene;

Scene demo(const std::string& name) {
  return scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json");
}

image::Frame render(const CompiledScene& sc, Method m, int n = 16, int n1 = 2, bool binning = true,
                    bool grid = true) {
  FloatOptions o;
  o.method = m;
  o.n = n;
  o.n1 = n1;
  o.binning = binning;
  o.grid = grid;
  return render_float(sc, o);
}

void expect_sane(const image::Frame& f, int primitives) {
  for (size_t k = 0; k < f.primitive.size(); ++k) {
    ASSERT_GE(f.primitive[k], image::kBackground);
    ASSERT_LT(f.primitive[k], primitives);
    ASSERT_TRUE(std::isfinite(f.depth[k])) << "pixel " << k;
  }
}

// ---- the iterative process against the ideal tracer ----

// Documented bound (docs/float-tracer.md): on the demo curve the iterative process differs from
// the ideal tracer in at most this fraction of the ideal's curve pixels, for every (n, n1)
// tested with n ≥ 12. Smaller n leaves τ too coarse to land inside the pixel pyramid.
constexpr double kIpDifferBound = 0.05;

TEST(IterativeProcess, AgreesWithIdealOnDemoCurve) {
  const CompiledScene sc = scene::compile_scene(demo("curve12"));
  const image::Frame ideal = render(sc, Method::kIdeal);
  const size_t curve_pixels = ideal.hit_pixels();
  ASSERT_GT(curve_pixels, 500u);
  struct Config { int n, n1; };
  for (const Config c : {Config{16, 1}, Config{16, 2}, Config{16, 4}, Config{12, 2}, Config{12, 3},
                         Config{20, 4}, Config{24, 2}}) {
    const image::Frame ip = render(sc, Method::kIterative, c.n, c.n1);
    const size_t differ = image::count_differing_pixels(ideal, ip);
    const double fraction = static_cast<double>(differ) / curve_pixels;
    std::printf("n=%d n1=%d: %zu differing / %zu curve pixels = %.2f %%\n", c.n, c.n1, differ,
                curve_pixels, 100.0 * fraction);
    EXPECT_LE(fraction, kIpDifferBound) << "n=" << c.n << " n1=" << c.n1;
  }
}

TEST(IterativeProcess, TooFewBitsMissTheCurve) {
  // The comparison can fail: with n = 4 the final interval is far wider than a pixel's pyramid.
  const CompiledScene sc = scene::compile_scene(demo("curve12"));
  const image::Frame ideal = render(sc, Method::kIdeal);
  const image::Frame ip = render(sc, Method::kIterative, 4, 2);
  EXPECT_GT(image::count_differing_pixels(ideal, ip), ideal.hit_pixels() / 4);
}

TEST(IterativeProcess, LowestIndexWinsTies) {
  // A straight segment seen end-on: every candidate has the same distance sum along the ray
  // (the ray is the chord itself), so η = 0 in every step and τ_K = 0.
  Scene s;
  s.source = "tie";
  s.camera = {{0, -5, 0}, {0, 0, 0}, {0, 0, 1}, 30.0, 5, 5};
  const CompiledScene sc = [&] {
    Scene t = s;
    t.curves.push_back({{{0, -1, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 0, 0}}, false, {1, 1, 1}});
    return scene::compile_scene(t);
  }();
  double tau = -1;
  const PairResult r = iterative_pair(sc.camera, sc.curve_segments[0].geom, 2, 2, 16, 2, &tau);
  EXPECT_EQ(tau, 0.0);
  EXPECT_TRUE(r.hit);
  EXPECT_DOUBLE_EQ(r.depth, 4.0);  // the near end p1 = (0, -1, 0)
}

// ---- acceleration structures never change the image ----

TEST(Binning, OnAndOffGiveIdenticalCurveImages) {
  for (const char* name : {"curve12"}) {
    const CompiledScene sc = scene::compile_scene(demo(name));
    for (Method m : {Method::kIdeal, Method::kIterative}) {
      const image::Frame on = render(sc, m, 16, 2, true);
      const image::Frame off = render(sc, m, 16, 2, false);
      EXPECT_GT(on.hit_pixels(), 0u);
      EXPECT_EQ(image::count_differing_pixels(on, off), 0u) << name;
      EXPECT_EQ(on.depth, off.depth);
    }
  }
}

TEST(ClassificationGrid, OnAndOffGiveIdenticalTextureImages) {
  for (const char* name : {"ellipse6", "polyline9", "airfield"}) {
    const CompiledScene sc = scene::compile_scene(demo(name));
    const image::Frame on = render(sc, Method::kIdeal, 16, 2, true, true);
    const image::Frame off = render(sc, Method::kIdeal, 16, 2, true, false);
    EXPECT_GT(on.hit_pixels(), 100u) << name;
    EXPECT_EQ(image::count_differing_pixels(on, off), 0u) << name;
  }
}

TEST(Textures, IdealAndIterativeAgreeExactly) {
  for (const char* name : {"ellipse6", "polyline9", "airfield"}) {
    const CompiledScene sc = scene::compile_scene(demo(name));
    EXPECT_EQ(image::count_differing_pixels(render(sc, Method::kIdeal),
                                            render(sc, Method::kIterative)), 0u) << name;
  }
}

// ---- degenerate geometry: a clean error or a correct image ----

Scene single_curve(std::vector<Vec3> pts, Vec3 eye = {0, -6, 2}, int size = 48) {
  Scene s;
  s.source = "test.json";
  s.camera = {eye, {0, 0, 0}, {0, 0, 1}, 45.0, size, size};
  s.curves.push_back({std::move(pts), {}, false, {1, 1, 1}});
  return s;
}

TEST(Degenerate, CollinearPointsRenderAStraightLine) {
  Scene s = single_curve({{-2, 0, 0}, {-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  const CompiledScene sc = scene::compile_scene(s);
  for (const auto& seg : sc.curve_segments)
    EXPECT_TRUE(seg.geom.guide[0].straight && seg.geom.guide[1].straight);
  for (Method m : {Method::kIdeal, Method::kIterative}) {
    const image::Frame f = render(sc, m);
    expect_sane(f, 1);
    // A horizontal line through the image centre: every hit pixel is in the middle rows.
    EXPECT_GT(f.hit_pixels(), 20u);
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i)
        if (f.primitive[f.index(i, j)] != image::kBackground) {
          int pi, pj;
          ASSERT_TRUE(scene::project_to_pixel(sc.camera, {0, 0, 0}, pi, pj));
          EXPECT_LE(std::abs(j - pj), 1) << "pixel " << i << "," << j;
        }
  }
}

Scene scaled(const Scene& s, double k) {
  Scene t = s;
  t.camera.eye = t.camera.eye * k;
  t.camera.target = t.camera.target * k;
  for (auto& c : t.curves)
    for (auto& p : c.points) p = p * k;
  for (auto& x : t.textures) {
    for (auto& p : x.points) p = p * k;
    x.half_width *= k;
  }
  return t;
}

TEST(Degenerate, HugeAndTinyScalesGiveTheSameImage) {
  const Scene base = demo("curve12");
  const Scene tex = demo("polyline9");
  for (const Scene* s : {&base, &tex}) {
    const CompiledScene sc = scene::compile_scene(*s);
    for (Method m : {Method::kIdeal, Method::kIterative}) {
      const image::Frame ref = render(sc, m);
      // Powers of two scale every intermediate exactly: the image must be identical.
      for (double k : {0x1p-40, 0x1p40}) {
        const image::Frame f = render(scene::compile_scene(scaled(*s, k)), m);
        EXPECT_EQ(image::count_differing_pixels(ref, f), 0u) << "scale " << k;
      }
      // Other scales only move rounding: a handful of edge pixels at most.
      for (double k : {1e-6, 1e6}) {
        const image::Frame f = render(scene::compile_scene(scaled(*s, k)), m);
        expect_sane(f, static_cast<int>(sc.primitives.size()));
        EXPECT_LE(image::count_differing_pixels(ref, f), ref.hit_pixels() / 100 + 2)
            << "scale " << k;
      }
    }
  }
}

TEST(Degenerate, CurveBehindTheEyeIsBackground) {
  Scene s = single_curve({{-1, -9, 0}, {0, -8, 1}, {1, -9, 0}});
  for (Method m : {Method::kIdeal, Method::kIterative}) {
    const image::Frame f = render(scene::compile_scene(s), m);
    EXPECT_EQ(f.hit_pixels(), 0u);
  }
}

TEST(Degenerate, EyeInsideAnInterpolationSphere) {
  // The eye sits on the chord's midpoint of a big segment: every ray starts inside its sphere.
  Scene s = single_curve({{-3, 0, 0}, {0, 0, 2}, {3, 0, 0}, {0, 0, -2}}, {0, 0, 0.2});
  s.curves[0].closed = true;
  s.camera.target = {0, 5, 0.2};
  const CompiledScene sc = scene::compile_scene(s);
  for (Method m : {Method::kIdeal, Method::kIterative}) {
    const image::Frame f = render(sc, m);
    expect_sane(f, 1);
  }
  // And a curve crossing the view in front of an eye inside its sphere is still drawn.
  Scene t = single_curve({{-4, 1, -0.5}, {4, 1, 0.5}}, {0, 0, 0});
  t.camera.target = {0, 1, 0};
  t.curves[0].normals = {{0, -1, 0}, {0, -1, 0}};
  const CompiledScene tc = scene::compile_scene(t);
  ASSERT_LT(length(tc.curve_segments[0].geom.c0 - t.camera.eye), tc.curve_segments[0].geom.R);
  for (Method m : {Method::kIdeal, Method::kIterative}) {
    const image::Frame f = render(tc, m);
    expect_sane(f, 1);
    EXPECT_GT(f.hit_pixels(), 10u);
  }
}

TEST(Degenerate, NormalParallelToSegmentIsRejectedWithItsPath) {
  Scene s = single_curve({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  s.curves[0].normals = {{0, 1, 0}, {1, 0, 0}, {-1, 0, 0}};
  try {
    scene::compile_scene(s);
    FAIL() << "expected an error";
  } catch (const rpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: curves[0].normals[1]"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("parallel"), std::string::npos) << e.what();
  }
}

TEST(Parameters, InvalidIterativeParametersAreRefused) {
  EXPECT_THROW(check_ip_parameters(16, 3), rpu::Error);
  EXPECT_THROW(check_ip_parameters(16, 0), rpu::Error);
  EXPECT_THROW(check_ip_parameters(0, 1), rpu::Error);
  EXPECT_THROW(check_ip_parameters(64, 2), rpu::Error);
  EXPECT_THROW(check_ip_parameters(18, 9), rpu::Error);
  EXPECT_NO_THROW(check_ip_parameters(16, 4));
}

}  // namespace
}  // namespace rpu::tracer
