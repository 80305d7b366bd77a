// The tessellated triangle reference for patch ray tracing (issue 13, "correctness independent
// of the method"): every patch is sampled on a fine uniform grid of its normalised [0, 1]² domain
// (rpu::patch::PatchSurface), split into triangles, and a bounding-volume hierarchy over all
// triangles answers the pixel-centre rays of the float tracer (CameraFrame::ray_direction).
// It knows nothing of the thesis's methods, so it can judge them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/scene.h"

namespace rpu::patch {

// One pixel of a patch rendering: what a method found along the pixel-centre ray.
struct PatchPixel {
  bool hit = false;
  int patch = -1;      // index into the scene's patch list
  double u = 0, v = 0;  // normalised patch parameters of the hit, in [0, 1]
  double depth = 0;    // c: coordinate of the hit point along the camera's forward axis W
                       // (= ray parameter t of eye + t·ray_direction(i, j), as capture_test)
};

// Per-pixel results of one rendering, row-major: pixel (i, j) is pixels[j * width + i].
struct PatchHitMap {
  int width = 0, height = 0;
  std::vector<PatchPixel> pixels;
  const PatchPixel& at(int i, int j) const { return pixels[static_cast<size_t>(j) * width + i]; }
  PatchPixel& at(int i, int j) { return pixels[static_cast<size_t>(j) * width + i]; }
};

struct TessellationOptions {
  // Grid cells per patch side (n × n quads, 2·n² triangles per patch). 0 = automatic: the
  // smallest n whose estimated chord error (from second differences of a probe grid) is below
  // `max_chord_error_pixels` of a pixel at the nearest depth of the patch, clamped to
  // [8, max_grid]; the largest n over the patches is used for all of them, so that patches
  // sharing an edge are cut at the same parameters (no cracks between them), lowered if needed
  // to keep the whole tessellation within 4 million triangles.
  int grid = 0;
  int max_grid = 512;
  double max_chord_error_pixels = 0.01;
  int threads = 0;  // 0 = all hardware threads (ref/common/parallel.h)
};

struct TessellationStats {
  std::int64_t triangles = 0;
  std::int64_t bvh_nodes = 0;
  std::vector<int> grid_per_patch;  // the n chosen for every patch
  double build_seconds = 0;         // tessellation + BVH
  double trace_seconds = 0;         // all pixel rays (render_tessellated_reference only)
};

// A tessellated scene, built once; trace() answers pixel rays against it. Copyable value type.
class TessellatedPatches {
 public:
  // Throws rpu::Error when a patch has no finite surface (non-finite samples).
  TessellatedPatches(const std::vector<scene::Patch>& patches, const scene::CameraFrame& camera,
                     const TessellationOptions& options = {});

  // The nearest hit along the ray eye + t·dir, t > t_min; `hit` false when there is none.
  // `depth` of the result is the ray parameter t (= c for the pixel rays of trace()).
  PatchPixel intersect(const Vec3& eye, const Vec3& dir, double t_min = 1e-9) const;

  // Every pixel of `camera` (its pixel-centre rays), rows spread over all cores; `seconds`
  // (optional) receives the wall time.
  PatchHitMap trace(const scene::CameraFrame& camera, int threads = 0,
                    double* seconds = nullptr) const;

  const TessellationStats& stats() const { return stats_; }

  struct Triangle {
    Vec3 p0, e1, e2;        // p0 and the two edges (p1 - p0, p2 - p0)
    double u0, v0;          // parameters of p0
    double du1, dv1;        // parameters of p1 minus those of p0
    double du2, dv2;        // parameters of p2 minus those of p0
    int patch;
  };
  struct Node {
    Vec3 lo, hi;     // bounding box
    int first = 0;   // leaf: first triangle index; inner: index of the left child
    int count = 0;   // leaf: number of triangles (> 0); inner: 0 (right child = left + 1)
  };

 private:
  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
  TessellationStats stats_;
};

// Convenience: tessellate and trace in one call (stats optional).
PatchHitMap render_tessellated_reference(const std::vector<scene::Patch>& patches,
                                         const scene::Camera& camera, const std::string& source,
                                         const TessellationOptions& options = {},
                                         TessellationStats* stats = nullptr);

// Agreement of a method's rendering with the reference (both the same size, else rpu::Error).
struct HitMapComparison {
  std::int64_t union_hits = 0;       // pixels hit in either map
  std::int64_t both_hit = 0;         // pixels hit in both
  std::int64_t only_reference = 0;   // hit in the reference only
  std::int64_t only_method = 0;      // hit in the method only
  std::int64_t same_patch = 0;       // both hit and the same patch index
  double agreement_percent = 100.0;  // 100 · both_hit / union_hits (100 when the union is empty)
  // Over pixels hit in both with the same patch:
  double mean_abs_du = 0, mean_abs_dv = 0, max_abs_du = 0, max_abs_dv = 0;
  // Over pixels hit in both (any patch): |depth_method - depth_ref| / depth_ref.
  double mean_rel_depth_error = 0, max_rel_depth_error = 0;
};
HitMapComparison compare_hit_maps(const PatchHitMap& reference, const PatchHitMap& method);

}  // namespace rpu::patch
