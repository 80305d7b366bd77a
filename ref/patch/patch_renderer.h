// Ray tracing the patches of a scene (docs/algorithms.md §4, seed 003) with one of three methods:
//   kThesis  the thesis: preliminary value map (preliminary_map.h), then per pixel the refiner
//            of the patch's type — gradient descent for Bézier (eq 4), steepest descent with
//            golden-ratio step for B-spline (eq 9), Newton + Cramer on the projected homogeneous
//            form for NURBS (eqs 10–13); optionally random starts for Bézier (eq 3);
//   kNewton  the same map, Newton on (S_x, S_y) for every type (a control);
//   kMartin  the baseline, Martin et al. 2000 (martin_bvh.h).
// Depth test across patches (map methods): every patch present in the 3×3 map texels around
// the pixel's texel is refined from that texel's start; of the converged roots inside the
// domain and in front of the eye the nearest wins (ties: lower patch number). Silhouette rule:
// a start that does not converge (the ray passes the patch's edge or its outline: the
// tessellated map overlaps the true outline by up to a fraction of a texel) gives no hit; pixels
// whose own texel names a patch but where no start converged are counted, per stopping reason,
// in PatchRenderStats — never drawn with an unrefined value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/limits.h"
#include "patch/martin_bvh.h"
#include "patch/patch_surface.h"
#include "patch/preliminary_map.h"
#include "patch/refiners.h"
#include "patch/tessellated_reference.h"  // PatchPixel, PatchHitMap
#include "scene/camera.h"

namespace rpu::patch {

enum class PatchMethod { kThesis, kNewton, kMartin };
enum class PatchStart { kMap, kRandom };

// "thesis", "newton", "martin"; throws rpu::Error(where, ...) for anything else.
PatchMethod parse_patch_method(const std::string& text, const std::string& where);
const char* patch_method_name(PatchMethod m);

struct PatchRenderOptions {
  PatchMethod method = PatchMethod::kThesis;
  PatchStart start = PatchStart::kMap;  // kRandom: eq 3 for Bézier patches (thesis method)
  int random_samples = 64;              // N of eq 3
  double random_epsilon_pixels = 2.0;   // ε0 of eq 3 as a distance from the ray, in pixels
  int random_max_starts = 4;            // refine at most this many of M′ (the best first)
  MapOptions map;
  RefineOptions refine;                 // tolerance, iteration budgets of the thesis refiners
  bool newton_fallback = true;          // thesis: Newton from where a refiner ran out of budget
  std::optional<Refiner> refiner;       // overrides the per-type refiner (benchmarks, tests)
  MartinOptions martin;
  int threads = 0;                      // 0 = all cores
  // Budgets (limits.h): the memory of the rendering (patch_render_bytes) and, through map and
  // martin, the tessellation cells and the BVH; `where` names the scene in a refusal.
  long long max_bytes = limits::kMaxPatchRenderBytes;
  std::string where = "patches";
};

// Precision rule of render_patches (docs/patches.md, "Precision"): a pixel at the farthest
// control point must span at least this many units in the last place of the largest coordinate.
inline constexpr double kMinUlpsPerPixel = 4096;
// Memory accounted per leaf of Martin's BVH (the leaf, two nodes, the build's order and copy;
// the map's tessellation in flight: kMapChunkBytes, preliminary_map.h).
inline constexpr long long kMartinBytesPerLeaf = 200;
// The frame of the float backends (primitive and depth per pixel) and the image written from it
// (RGB floats and the 8-bit copy of the writer), per pixel: a render of a scene with patches
// holds them beside the patches' own buffers.
inline constexpr long long kFrameBytesPerPixel = 12 + 12 + 4;

// The memory a render of a scene with patches needs for this image and these options (the
// frame and the image, the hit map, the preliminary map or Martin's BVH at its budget), and
// the check of it against options.max_bytes: rpu::Error(options.where, ...) naming the budget.
// run_backend checks before the frame is allocated, render_patches again before its own buffers.
long long patch_render_bytes(const scene::CameraFrame& camera, const PatchRenderOptions& options);
void check_patch_render_bytes(const scene::CameraFrame& camera, const PatchRenderOptions& options);

struct PatchRenderStats {
  double map_seconds = 0;      // preliminary map (thesis, newton) or BVH build (martin)
  double refine_seconds = 0;   // per-pixel refinement or BVH traversal
  std::int64_t map_triangles = 0, bvh_leaves = 0, bvh_nodes = 0;
  std::int64_t hit_pixels = 0;
  std::int64_t starts = 0, converged = 0;            // refinements run, of which converged
  std::int64_t iterations = 0, evaluations = 0;      // summed over the starts
  std::int64_t silhouette_pixels = 0;  // own texel names a patch, no start converged
  // Of those, by the stopping reason of the pixel's own-texel start:
  std::int64_t silhouette_left_domain = 0, silhouette_stalled = 0, silhouette_iteration_limit = 0,
               silhouette_singular = 0;
  std::int64_t fallback_starts = 0, fallback_converged = 0;  // thesis: Newton after budget
  std::int64_t neighbour_hits = 0;  // hits at pixels whose own texel is empty (map cracks, outline)
  std::int64_t box_tests = 0;       // martin
};

struct PatchRender {
  PatchHitMap hits;
  PatchRenderStats stats;
};

// Surfaces prepared once per scene.
std::vector<PatchSurface> prepare_surfaces(const std::vector<scene::Patch>& patches);

// The map methods' second stage on a given map (benchmarks time the two stages apart).
PatchHitMap refine_with_map(const std::vector<PatchSurface>& surfaces, const PreliminaryMap& map,
                            const scene::CameraFrame& camera, const PatchRenderOptions& options,
                            PatchRenderStats& stats);

// Martin's traversal on a given BVH.
PatchHitMap trace_martin(const std::vector<PatchSurface>& surfaces, const MartinBvh& bvh,
                         const scene::CameraFrame& camera, int threads, PatchRenderStats& stats);

// The whole rendering: map (or BVH) and refinement (or traversal), with times. Runs in a frame
// centred on the eye and scaled by a power of two (the same image at every scale; depths in
// world units); refuses, with rpu::Error(options.where, ...), a scene past the precision rule or
// a budget: the memory, the map's cells, Martin's pieces, leaves and ray/leaf pairs, the random
// starts' ray/patch pairs (limits.h).
PatchRender render_patches(const std::vector<PatchSurface>& surfaces,
                           const scene::CameraFrame& camera, const PatchRenderOptions& options);

}  // namespace rpu::patch
