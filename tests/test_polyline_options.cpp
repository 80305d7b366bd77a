// The polyline options beyond the seeds (docs/scene-format.md):
// - "smooth": false, a polyline of straight segments. Every guide of such a curve or texture is
//   straight, so the curve is its chords and a star keeps its points, and the fixed-point model
//   traces it as float-ip does;
// - "join": "round" on a texture: (pr1 ∧ pr3) ∨ pr2 instead of the seed's pr1 ∧ (pr2 ∨ pr3), so
//   the end caps count outside the segment's slab and a bend has no notch.
// The RTL is checked on tests/scenes/star_joins.json, which uses both, by the co-simulation tests
// (rtl_compare_star_joins).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "image/frame.h"
#include "model/descriptors.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tracer/float_tracer.h"

namespace rpu {
namespace {

// A 10-point star (20 points at radii 1 and 0.4) in the plane z = 0 as a curve, and the same
// points as a texture, each smoothed or not.
std::string star(bool curve, bool smooth) {
  std::string pts;
  for (int k = 0; k < 20; ++k) {
    const double r = k % 2 == 0 ? 1.0 : 0.4, a = M_PI / 2 + k * M_PI / 10;
    pts += (k ? ", [" : "[") + std::to_string(r * std::cos(a)) + ", " + std::to_string(r * std::sin(a)) +
           (curve ? ", 0]" : "]");
  }
  const std::string camera = R"("camera": {"eye": [0, -0.5, 4], "target": [0, 0, 0], "up": [0, 1, 0],
      "fov_deg": 40, "width": 128, "height": 128})";
  const std::string smooth_key = smooth ? "" : R"(, "smooth": false)";
  if (curve)
    return "{" + camera + R"(, "curves": [{"points": [)" + pts + R"(], "closed": true)" + smooth_key + "}]}";
  return "{" + camera + R"(, "textures": [{"points": [)" + pts + R"(], "closed": true, "half_width": 0.02)" +
         smooth_key + "}]}";
}

scene::CompiledScene compile(const std::string& json) {
  return scene::compile_scene(scene::parse_scene(json, "star.json"));
}

TEST(StraightPolyline, EveryGuideIsStraightAndTheCurveIsItsChord) {
  for (const bool curve : {true, false}) {
    const scene::CompiledScene straight = compile(star(curve, false));
    const scene::CompiledScene smooth = compile(star(curve, true));
    const auto& segs = curve ? straight.curve_segments : straight.texture_segments;
    const auto& smooth_segs = curve ? smooth.curve_segments : smooth.texture_segments;
    ASSERT_EQ(segs.size(), 20u);
    int curved = 0;
    for (size_t k = 0; k < segs.size(); ++k) {
      const scene::Segment& g = segs[k].geom;
      EXPECT_TRUE(g.guide[0].straight && g.guide[1].straight) << "segment " << k;
      for (const double t : {0.1, 0.5, 0.9}) {
        const Vec3 on_chord = g.p1 + g.d * t;
        EXPECT_LT(length(scene::curve_point(g, t) - on_chord), 1e-12) << "segment " << k;
      }
      curved += !smooth_segs[k].geom.guide[0].straight;
    }
    EXPECT_EQ(curved, 20) << "the smoothed star bends at every point";
  }
}

TEST(StraightPolyline, ModelTracesItAsFloatIpDoes) {
  for (const bool curve : {true, false}) {
    SCOPED_TRACE(curve ? "curve" : "texture");
    const scene::CompiledScene sc = compile(star(curve, false));
    tracer::FloatOptions fo;
    const image::Frame ideal = tracer::render_float(sc, fo);
    fo.method = tracer::Method::kIterative;
    const image::Frame ip = tracer::render_float(sc, fo);
    const ref::HwParams p;
    const image::Frame model = ref::render_ref(sc, ref::quantize_scene(sc, p), {});
    ASSERT_GT(ideal.hit_pixels(), 300u);
    EXPECT_EQ(image::count_differing_pixels(model, ip), 0u);
    // The straight star has no smoothing to miss: float-ip differs from float only where a
    // pixel pyramid grazes a chord (measured: 6 of 602 curve pixels).
    EXPECT_LE(image::count_differing_pixels(ip, ideal), ideal.hit_pixels() / 50);
    // The tips are drawn: the pixel of the top point (0, 1, 0) is hit.
    const Vec3 tip{0.0, 1.0, 0.0};
    const Vec3 q = tip - sc.camera.eye;
    const double c = dot(q, sc.camera.W);
    const int i = static_cast<int>(std::floor(dot(q, sc.camera.U) / (c * sc.camera.sigma) + 64.0));
    const int j = static_cast<int>(std::floor(64.0 - dot(q, sc.camera.V) / (c * sc.camera.sigma)));
    bool near_tip = false;  // the tip pixel or a neighbour (the tip is a point)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        near_tip |= model.primitive[model.index(i + di, j + dj)] != image::kBackground;
    EXPECT_TRUE(near_tip) << "pixel " << i << "," << j;
  }
}


// A bend of a thick texture: the seed's joins leave a notch outside it, the round join fills it.
// Every pixel the seed's rule covers, the round one covers too, and more; float, float-ip and ref
// agree on both.
TEST(RoundJoin, FillsTheNotchAtEveryBend) {
  const std::string base = R"({"camera": {"eye": [0, -4, 6], "target": [0, 0, 0], "up": [0, 0, 1],
      "fov_deg": 45, "width": 96, "height": 96},
    "textures": [{"points": [[-2, -0.5], [-1, 1], [0, -0.5], [1, 1], [2, -0.5]],
                  "half_width": 0.3, "smooth": false)";
  const scene::CompiledScene seed = compile(base + "}]}");
  const scene::CompiledScene round = compile(base + R"(, "join": "round"}]})");
  ASSERT_FALSE(seed.texture_segments[0].round_join);
  ASSERT_TRUE(round.texture_segments[0].round_join);
  const ref::HwParams p;
  tracer::FloatOptions fo;
  const image::Frame seed_f = tracer::render_float(seed, fo), round_f = tracer::render_float(round, fo);
  const image::Frame seed_r = ref::render_ref(seed, ref::quantize_scene(seed, p), {});
  const image::Frame round_r = ref::render_ref(round, ref::quantize_scene(round, p), {});
  fo.method = tracer::Method::kIterative;
  EXPECT_EQ(image::count_differing_pixels(round_f, tracer::render_float(round, fo)), 0u);
  EXPECT_EQ(image::count_differing_pixels(seed_r, seed_f), 0u);
  EXPECT_EQ(image::count_differing_pixels(round_r, round_f), 0u);
  size_t lost = 0, gained = 0;
  for (size_t k = 0; k < seed_f.primitive.size(); ++k) {
    const bool a = seed_f.primitive[k] != image::kBackground;
    const bool b = round_f.primitive[k] != image::kBackground;
    lost += a && !b;
    gained += b && !a;
  }
  std::printf("round join: %zu pixels more than the seed's %zu, %zu lost\n", gained,
              seed_f.hit_pixels(), lost);
  EXPECT_EQ(lost, 0u);
  EXPECT_GT(gained, 20u) << "the notches and the square ends are not filled";
}

}  // namespace
}  // namespace rpu
