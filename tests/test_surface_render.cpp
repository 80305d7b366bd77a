// Whole images of vector-described surfaces (docs/algorithms.md §3) through render_float: float-ip
// against float on the demo scenes (scenes/surf_*.json, here at 64×64), the nearest hit across
// curves, textures and surfaces, the statistics, and --shade's normals.
//
// The 256×256 measurement of docs/surfaces.md (the seed's search: mismatched pixels per (n, n1),
// times) is a disabled test, run by hand:
//   build/tests/test_surface_render --gtest_also_run_disabled_tests
//       --gtest_filter='DISABLED_SurfaceMeasure*'
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/error.h"
#include "image/frame.h"
#include "patch/patch_shading.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tracer/float_tracer.h"
#include "tracer/surface_shading.h"
#include "tracer/surface_tracer.h"

namespace rpu::tracer {
namespace {

using scene::CompiledScene;
using scene::Scene;

Scene demo(const std::string& name, int side) {
  Scene s = scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json");
  if (side > 0) s.camera.width = s.camera.height = side;
  return s;
}

image::Frame render(const CompiledScene& sc, Method m, int n = 16, int n1 = 2,
                    RenderStats* stats = nullptr, int surf_n1_first = FloatOptions{}.surf_n1_first) {
  FloatOptions o;
  o.method = m;
  o.n = n;
  o.n1 = n1;
  o.surf_n1_first = surf_n1_first;
  return render_float(sc, o, stats);
}

struct Difference {
  size_t ideal_hits = 0, ip_hits = 0;
  size_t differ = 0;    // pixels whose primitive differs
  size_t only_ip = 0;   // hit by float-ip, background in float
  size_t only_ideal = 0;
};

Difference compare(const image::Frame& ideal, const image::Frame& ip) {
  Difference d;
  d.ideal_hits = ideal.hit_pixels();
  d.ip_hits = ip.hit_pixels();
  d.differ = image::count_differing_pixels(ideal, ip);
  for (size_t k = 0; k < ideal.primitive.size(); ++k) {
    const bool a = ideal.primitive[k] != image::kBackground, b = ip.primitive[k] != image::kBackground;
    d.only_ip += b && !a;
    d.only_ideal += a && !b;
  }
  return d;
}

const char* const kDemos[] = {"surf_ellipsoid", "surf_relief", "surf_spiral", "surf_snail",
                              "surf_rocket"};

// ---- float-ip against float ----

TEST(SurfaceRender, IterativeAgainstIdealOnTheDemoScenes) {
  // The default search (a 7-bit first step) agrees with the ideal on ≥ 99 % of its hit pixels
  // (measured: at most 0.74 %, spiral; ref against float-ip: test_surface_model's
  // SurfaceModel.AgreesWithFloatIpOnTheDemoScenes). The seed's search (surf_n1_first = seed)
  // misses a piece when both crossings fall into one step-1 interval (2^−n1 of the
  // bounding-sphere chord): thin tubes (spiral, snail) lose much at n1 = 2, less at n1 = 4. Neither
  // hits where the ideal search sees nothing (up to the ideal's own sampling, rare).
  // Bounds: 64×64 (deterministic), the seed's measured fractions of the ideal's hit pixels plus
  // 3 percentage points, or 1.5× where that is less (docs/surfaces.md has 256×256); the default
  // search's 1 % plus a pixel.
  struct Bound {
    const char* scene;
    double n1_2, n1_4;  // the seed's search: differing / ideal hits at (16, 2) and (16, 4)
  };
  // Measured: ellipsoid 2.8 % / 0.2 %, relief 27.3 % / 7.2 %, spiral 61.1 % / 14.4 %, snail
  // 41.4 % / 0.8 %, rocket 27.0 % / 3.5 %.
  for (const Bound b : {Bound{"surf_ellipsoid", 0.058, 0.01}, Bound{"surf_relief", 0.303, 0.102},
                        Bound{"surf_spiral", 0.642, 0.174}, Bound{"surf_snail", 0.445, 0.03},
                        Bound{"surf_rocket", 0.30, 0.06}}) {
    const CompiledScene sc = scene::compile_scene(demo(b.scene, 64));
    const image::Frame ideal = render(sc, Method::kIdeal);
    ASSERT_GT(ideal.hit_pixels(), 150u) << b.scene;
    double previous = 2.0;
    for (const int n1 : {2, 4}) {
      const Difference d = compare(ideal, render(sc, Method::kIterative, 16, n1, nullptr, 0));
      const double fraction = static_cast<double>(d.differ) / d.ideal_hits;
      std::printf("%-15s n=16 n1=%d: %zu of %zu ideal hit pixels differ (%.2f %%), %zu only in "
                  "float-ip\n",
                  b.scene, n1, d.differ, d.ideal_hits, 100.0 * fraction, d.only_ip);
      EXPECT_LE(fraction, n1 == 2 ? b.n1_2 : b.n1_4) << b.scene << " n1=" << n1;
      EXPECT_LE(d.only_ip, d.ideal_hits / 200 + 1) << b.scene << " n1=" << n1;
      EXPECT_LE(fraction, previous) << b.scene << ": n1 = 4 worse than n1 = 2";
      previous = fraction;
    }
    const Difference d = compare(ideal, render(sc, Method::kIterative, 16, 2));
    std::printf("%-15s n=16 n1=2 default search: %zu of %zu ideal hit pixels differ (%.2f %%), "
                "%zu only in float-ip\n",
                b.scene, d.differ, d.ideal_hits, 100.0 * d.differ / d.ideal_hits, d.only_ip);
    EXPECT_LE(d.differ, d.ideal_hits / 100 + 1) << b.scene << " (default search)";
    EXPECT_LE(d.only_ip, d.ideal_hits / 200 + 1) << b.scene << " (default search)";
  }
}

TEST(SurfaceRender, IterativeWithEnoughCandidatesMatchesIdeal) {
  // 256 sub-intervals at every step (the seed's schedule at n1 = 8) over the ellipsoid and the
  // rocket: no chord is shorter than a step-1
  // interval except at silhouettes, so the images agree but for a few edge pixels.
  for (const char* name : {"surf_ellipsoid", "surf_rocket"}) {
    const CompiledScene sc = scene::compile_scene(demo(name, 64));
    const image::Frame ideal = render(sc, Method::kIdeal);
    const Difference d = compare(ideal, render(sc, Method::kIterative, 24, 8, nullptr, 0));
    std::printf("%-15s n=24 n1=8: %zu of %zu ideal hit pixels differ\n", name, d.differ,
                d.ideal_hits);
    EXPECT_LE(d.differ, d.ideal_hits / 100 + 2) << name;
  }
}

// ---- the nearest hit across kinds ----

TEST(SurfaceRender, NearestHitWinsAcrossCurvesTexturesAndSurfaces) {
  // surf_mix: a curve through and around a relief ellipsoid, a rocket, a texture loop under them.
  // Each pixel holds the nearer of the surface hit (traced alone, same ids) and what the curves
  // and textures give without the surfaces; equal depth goes to the lower id.
  for (const Method m : {Method::kIdeal, Method::kIterative}) {
    const Scene full = demo("surf_mix", 64);
    const CompiledScene sc = scene::compile_scene(full);
    Scene no_surfaces = full;
    no_surfaces.surfaces.clear();
    const CompiledScene rest = scene::compile_scene(no_surfaces);
    const image::Frame all = render(sc, m);
    const image::Frame others = render(rest, m);
    const SurfaceTracer tracer(sc, m, 16, 2, FloatOptions{}.surf_n1_first);
    size_t surface_won = 0, other_won = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) {
        const size_t k = all.index(i, j);
        double depth = 0.0;
        std::int32_t id = image::kBackground;
        SurfaceStats st;
        const bool surface = tracer.trace_pixel(i, j, depth, id, st);
        std::int32_t expect = others.primitive[k];
        if (surface && (expect == image::kBackground || depth < others.depth[k] ||
                        (depth == others.depth[k] && id < expect)))
          expect = id;
        ASSERT_EQ(all.primitive[k], expect) << "pixel " << i << ", " << j;
        if (expect == image::kBackground) continue;
        (expect >= sc.first_surface_primitive ? surface_won : other_won) += 1;
        if (surface && expect < sc.first_surface_primitive) {
          EXPECT_LE(all.depth[k], depth);
        }
      }
    // The scene is built so that both kinds win somewhere, also where both are hit.
    EXPECT_GT(surface_won, 100u);
    EXPECT_GT(other_won, 50u);
  }
}

// ---- statistics ----

TEST(SurfaceRender, StatisticsCountPairsPiecesAndHits) {
  const CompiledScene sc = scene::compile_scene(demo("surf_spiral", 48));
  RenderStats ip, ideal;
  const image::Frame f = render(sc, Method::kIterative, 16, 4, &ip);
  render(sc, Method::kIdeal, 16, 2, &ideal);
  EXPECT_EQ(ip.surface_pairs_tested, 48u * 48u);
  EXPECT_EQ(ip.surface_pairs_hit, f.hit_pixels());
  EXPECT_GE(ip.surface_pieces, ip.surface_pairs_hit);
  // float-ip: every piece it searched to a hit took the schedule's whole count of inside tests
  // (the default first step of 2^7, then 4, 4 and 1 bits: 2 + 127 + 15 + 15 + 1 = 160).
  ref::HwParams schedule;
  schedule.n = 16;
  schedule.n1 = 4;
  ASSERT_EQ(schedule.surface_evaluations(), 160);
  EXPECT_GE(ip.surface_evaluations, 160u * ip.surface_pairs_hit);
  // The pieces depend on the geometry only, not on the method.
  EXPECT_EQ(ideal.surface_pieces, ip.surface_pieces);
}

// ---- shading ----

// Issue 24: the budget on ray/surface pairs. Its estimate (the screen rectangles of the bounding
// spheres) bounds the pixel rays that really meet a bounding sphere; stacked copies past the
// budget are refused by float, float-ip and ref alike before any work, naming the surfaces.
TEST(SurfaceBudget, EstimateBoundsThePairsAndRefusesPastTheBudget) {
  for (const char* name : {"surf_mix", "surf_spiral", "surf_rocket"}) {
    const CompiledScene sc = scene::compile_scene(demo(name, 48));
    long long met = 0;
    for (const scene::CompiledSurface& s : sc.surfaces)
      for (int j = 0; j < sc.camera.height; ++j)
        for (int i = 0; i < sc.camera.width; ++i) {
          const Vec3 d = normalize(sc.camera.ray_direction(i, j));
          const Vec3 q = s.centre - sc.camera.eye;
          const double b = dot(q, d), c = dot(q, q) - s.radius * s.radius;
          met += b * b - c >= 0 && b + std::sqrt(std::max(0.0, b * b - c)) > 0;
        }
    EXPECT_GE(scene::surface_screen_pairs(sc), met) << name;
    EXPECT_GT(met, 0) << name;
    EXPECT_NO_THROW(scene::check_surface_budget(sc)) << name;
  }
  Scene many = demo("surf_spiral", 64);
  many.surfaces.assign(64, many.surfaces.front());  // 64 full-screen spirals: 64 pairs per pixel
  const CompiledScene sc = scene::compile_scene(many);
  EXPECT_GT(scene::surface_screen_pairs(sc), 4LL * 64 * 64);
  try {
    render(sc, Method::kIdeal);
    FAIL() << "64 stacked spirals rendered";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("surf_spiral.json: surfaces: the 64 surfaces cover up to"),
              std::string::npos) << e.what();
  }
  EXPECT_THROW(render(sc, Method::kIterative), Error);
}

TEST(SurfaceShading, NormalOfASphereIsRadialAndFacesTheEye) {
  scene::Surface s;
  s.type = scene::SurfaceType::kEllipsoid;
  s.p = scene::default_surface_params(s.type);
  s.p.a = s.p.b = s.p.c = 1.0;
  s.p.y_min = -1.0, s.p.y_max = 0.5;
  s.scale = 2.0;
  s.rotation_deg = {30, 40, 50};
  s.position = {1, 2, 3};
  const scene::CompiledSurface cs = scene::compile_surface(s, 0);
  for (const Vec3 dir : {Vec3{1, 0, 0}, Vec3{0.6, -0.8, 0}, Vec3{0, 0.3, -0.9}}) {
    const Vec3 u = normalize(dir);
    const Vec3 X = s.position + u * 2.0;  // on the sphere of radius 2 (placed)
    // Seen from outside (ray towards the centre) the normal points out; from inside, in.
    const Vec3 out = surface_normal(cs, X, -u), in = surface_normal(cs, X, u);
    EXPECT_NEAR(dot(out, u), 1.0, 1e-6);
    EXPECT_NEAR(dot(in, u), -1.0, 1e-6);
  }
}

TEST(SurfaceShading, LambertDarkensTowardsTheSilhouette) {
  const CompiledScene sc = scene::compile_scene(demo("surf_rocket", 64));
  const image::Frame f = render(sc, Method::kIdeal);
  std::vector<scene::Color> colors;
  for (const auto& p : sc.primitives) colors.push_back(p.color);
  const std::vector<float> flat = image::to_rgb(f, colors, sc.background);
  std::vector<float> shaded = flat;
  shade_surface_pixels(shaded, f, sc);
  double min_factor = 1.0, max_factor = 0.0;
  for (size_t k = 0; k < f.primitive.size(); ++k) {
    if (f.primitive[k] == image::kBackground) {
      ASSERT_EQ(shaded[3 * k], flat[3 * k]);
      continue;
    }
    const double factor = shaded[3 * k] / flat[3 * k];
    ASSERT_GE(factor, patch::kShadeAmbient - 1e-6);
    ASSERT_LE(factor, 1.0 + 1e-6);
    min_factor = std::min(min_factor, factor);
    max_factor = std::max(max_factor, factor);
  }
  EXPECT_GT(max_factor, 0.9);  // the cylinder facing the eye
  EXPECT_LT(min_factor, 0.5);  // grazing at the outline
}

// ---- the 256×256 measurement (disabled: about 15 s of ideal rendering on two cores) ----

TEST(DISABLED_SurfaceMeasure, IterativeAgainstIdeal256) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  // The seed's search (surf_n1_first = seed), per (n, n1): differing pixels (fraction of float's hit pixels; + only float-ip hits, − only
  // float hits), pixels both hit where float-ip is on a farther crossing, the largest relative
  // depth gap on the others, float-ip seconds.
  std::printf("| scene | float s | float hits | (16,2) | (16,4) | (24,2) | (24,4) |\n");
  for (const char* name : kDemos) {
    const CompiledScene sc = scene::compile_scene(demo(name, 256));
    auto t0 = Clock::now();
    RenderStats st;
    const image::Frame ideal = render(sc, Method::kIdeal, 16, 2, &st);
    const double t_ideal = seconds(t0);
    std::string cells;
    for (const auto& [n, n1] : {std::pair{16, 2}, std::pair{16, 4}, std::pair{24, 2},
                                std::pair{24, 4}}) {
      t0 = Clock::now();
      const image::Frame ip = render(sc, Method::kIterative, n, n1, nullptr, 0);  // the seed's
      const double t_ip = seconds(t0);
      const Difference d = compare(ideal, ip);
      // Pixels both hit: on another crossing (depth off by more than 1e-3 relative: the IP
      // skipped a nearer pair of crossings), else the largest relative depth gap.
      double gap = 0.0;
      size_t other_crossing = 0;
      for (size_t k = 0; k < ip.primitive.size(); ++k)
        if (ip.primitive[k] != image::kBackground && ideal.primitive[k] != image::kBackground) {
          const double rel = std::fabs(ideal.depth[k] - ip.depth[k]) / ideal.depth[k];
          if (rel > 1e-3) {
            ++other_crossing;
          } else {
            gap = std::max(gap, rel);
          }
        }
      char cell[192];
      std::snprintf(cell, sizeof cell, " %zu (%.1f %%; +%zu −%zu), %zu farther, gap %.0e, %.3f s |",
                    d.differ, 100.0 * d.differ / d.ideal_hits, d.only_ip, d.only_ideal,
                    other_crossing, gap, t_ip);
      cells += cell;
    }
    std::printf("| %s | %.2f | %zu |%s\n", name, t_ideal, ideal.hit_pixels(), cells.c_str());
  }
}

}  // namespace
}  // namespace rpu::tracer
