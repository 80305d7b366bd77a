// The scene compiler's output (host side of the hardware): camera constants, per-segment
// constants of every curve and texture, the texture classification grid, and the placed
// vector-described surfaces.
#pragma once

#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/classification_grid.h"
#include "scene/scene.h"
#include "scene/segment.h"
#include "scene/surface.h"

namespace rpu::scene {

// A primitive is one curve, texture, surface or patch; its id orders equal-depth hits (lower
// wins) and indexes the colour table. Curves come first (ids 0..C-1), then textures, then
// surfaces (from first_surface_primitive), then patches (from first_patch_primitive).
struct Primitive {
  enum class Kind { kCurve, kTexture, kSurface, kPatch };
  Kind kind = Kind::kCurve;
  int index = 0;  // index within scene.curves, .textures, .surfaces or .patches
  Color color{};
};

struct CompiledSegment {
  Segment geom;
  int primitive = 0;  // id in CompiledScene::primitives
  int index = 0;      // segment number within its curve or texture (from point `index`)
  double half_width = 0.0;  // w_0 (textures only)
  bool round_join = false;  // textures: "join": "round" (Texture::round_join)
};

struct CompiledScene {
  std::string source;
  CameraFrame camera;
  Color background{};
  std::vector<Primitive> primitives;
  std::vector<CompiledSegment> curve_segments;
  std::vector<CompiledSegment> texture_segments;
  ClassificationGrid texture_grid;  // over texture_segments
  // Vector-described surfaces (docs/algorithms.md §3), primitive ids first_surface_primitive + k,
  // in the order of scene.surfaces: frame and bounding sphere (scene/surface.h).
  std::vector<CompiledSurface> surfaces;
  int first_surface_primitive = 0;
  // Parametric patches (docs/algorithms.md §4), primitive ids first_patch_primitive + k; the float
  // backends only (ref/patch/), the fixed-point model and the RTL refuse them.
  std::vector<Patch> patches;
  int first_patch_primitive = 0;
};

// Derives missing normals, builds every segment's constants and the classification grid.
// Throws rpu::Error naming the source and JSON path on degenerate geometry: repeated
// consecutive points, a normal parallel to its segment, a zero normal.
CompiledScene compile_scene(const Scene& scene);

// The ray/surface pairs a render of the surfaces can meet: for every surface the pixels inside
// the screen rectangle of its world bounding sphere (every pixel when the sphere reaches the
// eye plane), summed. An upper bound on the pairs whose ray meets a bounding sphere.
long long surface_screen_pairs(const CompiledScene& sc);

// Refuses (rpu::Error naming the scene's surfaces) a scene whose surface_screen_pairs exceed
// the budget of limits.h: kSurfacePairsPerPixel per pixel on average, at least kMinPairBudget.
// The float tracers and the model check it before rendering (docs/surfaces.md, "Budgets").
void check_surface_budget(const CompiledScene& sc);

}  // namespace rpu::scene
