// The tessellated triangle reference of patch ray tracing (ref/patch/tessellated_reference.h)
// against analytic ray intersections: a flat square (exact plane) and the Bézier sphere (the
// true sphere bounds it; Newton on the polynomial surface pins the hit and its parameters).
#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "patch/patch_surface.h"
#include "patch/tessellated_reference.h"
#include "scene/camera.h"
#include "scene/scene_json.h"

namespace rpu::patch {
namespace {

// A bicubic Bézier square [-1, 1]² at z = 0 with a linear parametrisation: x = 2u - 1, y = 2v - 1.
scene::Patch flat_square() {
  scene::Patch p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.control_points.push_back({-1 + 2.0 * i / 3, -1 + 2.0 * j / 3, 0});
  return p;
}

scene::Camera camera(Vec3 eye, int size) {
  scene::Camera c;
  c.eye = eye;
  c.target = {0, 0, 0};
  c.up = {0, 0, 1};
  c.fov_deg = 40;
  c.width = c.height = size;
  return c;
}

TEST(TessellatedReference, FlatSquareMatchesRayPlane) {
  const scene::Camera cam = camera({1.5, -2.0, 4.0}, 96);
  const scene::CameraFrame frame = scene::make_camera_frame(cam, "test");
  TessellationStats stats;
  const PatchHitMap map = render_tessellated_reference({flat_square()}, cam, "test", {}, &stats);
  ASSERT_EQ(map.width, 96);
  EXPECT_GT(stats.triangles, 0);
  int hits = 0, checked = 0;
  for (int j = 0; j < 96; ++j)
    for (int i = 0; i < 96; ++i) {
      const Vec3 d = frame.ray_direction(i, j);
      const double t = -frame.eye.z / d.z;
      const Vec3 x = frame.eye + d * t;
      const double margin = std::max(std::abs(x.x), std::abs(x.y)) - 1;
      if (std::abs(margin) < 1e-9) continue;  // exactly on the border: either answer is right
      ++checked;
      const PatchPixel& p = map.at(i, j);
      ASSERT_EQ(p.hit, margin < 0) << "pixel " << i << "," << j;
      if (!p.hit) continue;
      ++hits;
      EXPECT_EQ(p.patch, 0);
      EXPECT_NEAR(p.u, (x.x + 1) / 2, 1e-9);
      EXPECT_NEAR(p.v, (x.y + 1) / 2, 1e-9);
      EXPECT_NEAR(p.depth, t, 1e-9 * t);
    }
  EXPECT_GT(hits, 500);              // the square fills a good part of the image
  EXPECT_LT(hits, checked - 500);    // and misses too
}

// Newton on S(u, v) = eye + t·d (3 × 3, Cramer's rule) from the reference's answer.
bool polish(const PatchSurface& s, const Vec3& eye, const Vec3& d, double& u, double& v,
            double& t) {
  for (int it = 0; it < 30; ++it) {
    const SurfacePoint sp = s.evaluate(u, v);
    const Vec3 f = sp.p - eye - d * t;
    const Vec3 c0 = sp.du, c1 = sp.dv, c2 = -d;
    const double det = dot(c0, cross(c1, c2));
    if (det == 0) return false;
    const double du = dot(f, cross(c1, c2)) / det;
    const double dv = dot(c0, cross(f, c2)) / det;
    const double dt = dot(c0, cross(c1, f)) / det;
    u -= du, v -= dv, t -= dt;
    if (std::abs(du) + std::abs(dv) + std::abs(dt) < 1e-14) return true;
  }
  return false;
}

TEST(TessellatedReference, BezierSphereAgainstAnalyticSphereAndNewton) {
  const scene::Scene sc =
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/bezier_sphere.json");
  ASSERT_EQ(sc.patches.size(), 8u);
  const scene::Camera cam = camera({3.2, -4.2, 2.6}, 128);
  const scene::CameraFrame frame = scene::make_camera_frame(cam, "test");
  const TessellatedPatches tess(sc.patches, frame);
  const PatchHitMap map = tess.trace(frame);
  std::vector<PatchSurface> surfaces;
  for (const auto& p : sc.patches) surfaces.emplace_back(p);
  // The Bézier sphere lies between the radii 1 and 1.0006 (quarter arcs with k = 4(√2 - 1)/3):
  // rays passing the centre closer than 0.999 must hit, farther than 1.002 must miss.
  int hits = 0, polished = 0;
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const Vec3 d = frame.ray_direction(i, j);
      const double tc = -dot(frame.eye, d) / dot(d, d);
      const double miss_distance = length(frame.eye + d * tc);
      const PatchPixel& p = map.at(i, j);
      if (miss_distance < 0.999) ASSERT_TRUE(p.hit) << i << "," << j;
      if (miss_distance > 1.002) ASSERT_FALSE(p.hit) << i << "," << j;
      if (!p.hit) continue;
      ++hits;
      // Analytic sphere of radius 1: the near root.
      const double a = dot(d, d), b = dot(frame.eye, d), c = dot(frame.eye, frame.eye) - 1;
      const double disc = b * b - a * c;
      if (disc > 0.01) {
        const double t_sphere = (-b - std::sqrt(disc)) / a;
        EXPECT_NEAR(p.depth, t_sphere, 2e-3 * t_sphere);
      }
      // The exact polynomial surface: Newton from the reference's (u, v, t) must land close. The
      // tessellation is cut so that its chord error stays below 0.01 pixel (an estimate, so
      // allow twice that); along a ray meeting the surface at angle θ to the normal, that becomes
      // chord / cos θ in distance.
      if (miss_distance > 0.98) continue;  // grazing rays: Newton is ill-conditioned
      double u = p.u, v = p.v, t = p.depth;
      if (!polish(surfaces[p.patch], frame.eye, d, u, v, t)) continue;
      if (u < 0 || u > 1 || v < 0 || v > 1) continue;  // converged onto a neighbour's domain
      ++polished;
      const SurfacePoint exact = surfaces[p.patch].evaluate(u, v);
      const double cos_theta =
          std::abs(dot(normalize(cross(exact.du, exact.dv)), normalize(d)));
      const double chord = 2 * 0.01 * frame.sigma * t;  // world units at this depth
      const double distance_bound = chord / cos_theta;
      EXPECT_NEAR(p.depth * length(d), t * length(d), distance_bound) << i << "," << j;
      // The interpolated parameters name a surface point as close to the exact hit.
      EXPECT_LE(length(surfaces[p.patch].point(p.u, p.v) - exact.p), 2 * distance_bound)
          << i << "," << j << " u " << p.u << " v " << p.v << " newton " << u << "," << v;
      // And the parameters themselves, within that distance divided by the surface's speed
      // (large near the collapsed poles, where u is ill-defined).
      EXPECT_NEAR(p.u, u, 2 * distance_bound / length(exact.du)) << i << "," << j;
      EXPECT_NEAR(p.v, v, 2 * distance_bound / length(exact.dv)) << i << "," << j;
    }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(polished, hits / 2);
}

TEST(TessellatedReference, IntersectDirectRays) {
  scene::Camera cam = camera({0, 0, 5}, 8);
  cam.up = {0, 1, 0};
  const scene::CameraFrame frame = scene::make_camera_frame(cam, "test");
  TessellationOptions o;
  o.grid = 8;
  const TessellatedPatches tess({flat_square()}, frame, o);
  EXPECT_EQ(tess.stats().triangles, 2 * 8 * 8);
  const PatchPixel p = tess.intersect({0.5, 0.25, 3}, {0, 0, -1});
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.u, 0.75, 1e-12);
  EXPECT_NEAR(p.v, 0.625, 1e-12);
  EXPECT_NEAR(p.depth, 3, 1e-12);
  EXPECT_FALSE(tess.intersect({0.5, 0.25, 3}, {0, 0, 1}).hit);   // pointing away
  EXPECT_FALSE(tess.intersect({1.5, 0.25, 3}, {0, 0, -1}).hit);  // beside the square
}

TEST(TessellatedReference, CompareHitMaps) {
  PatchHitMap r, m;
  r.width = m.width = 4;
  r.height = m.height = 1;
  r.pixels.resize(4);
  m.pixels.resize(4);
  r.pixels[0] = {true, 0, 0.5, 0.5, 2.0};
  m.pixels[0] = {true, 0, 0.6, 0.3, 2.2};
  r.pixels[1] = {true, 1, 0.1, 0.1, 4.0};
  m.pixels[1] = {true, 2, 0.9, 0.9, 4.0};
  r.pixels[2] = {true, 0, 0.1, 0.1, 1.0};
  m.pixels[3] = {true, 0, 0.1, 0.1, 1.0};
  const HitMapComparison c = compare_hit_maps(r, m);
  EXPECT_EQ(c.union_hits, 4);
  EXPECT_EQ(c.both_hit, 2);
  EXPECT_EQ(c.only_reference, 1);
  EXPECT_EQ(c.only_method, 1);
  EXPECT_EQ(c.same_patch, 1);
  EXPECT_DOUBLE_EQ(c.agreement_percent, 50.0);
  EXPECT_NEAR(c.mean_abs_du, 0.1, 1e-15);
  EXPECT_NEAR(c.mean_abs_dv, 0.2, 1e-15);
  EXPECT_NEAR(c.mean_rel_depth_error, 0.05, 1e-15);
  EXPECT_NEAR(c.max_rel_depth_error, 0.1, 1e-15);
  m.width = 2;
  EXPECT_THROW(compare_hit_maps(r, m), Error);
}

}  // namespace
}  // namespace rpu::patch
