// The scene as written in a scene file (docs/scene-format.md), after validation, before
// compilation.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/limits.h"
#include "common/vec3.h"
#include "scene/surface.h"

namespace rpu::scene {

using Color = std::array<double, 3>;  // linear RGB, each in [0, 1]

struct Camera {
  Vec3 eye;
  Vec3 target;
  Vec3 up;
  double fov_deg = 40.0;  // full horizontal field of view, in (0, 180)
  int width = 0;
  int height = 0;
};

// A spatial curve (docs/algorithms.md §1): a polyline smoothed by spherical interpolation.
struct Curve {
  std::vector<Vec3> points;
  std::vector<Vec3> normals;  // empty when the file gives none (derived, docs/algorithms.md §1)
  bool closed = false;
  Color color{1.0, 1.0, 1.0};
  bool smooth = true;  // false: straight segments (every guide straight), the corners kept
};

// A vector texture on the plane z = 0 (docs/algorithms.md §2). Points and normals have z = 0.
struct Texture {
  std::vector<Vec3> points;
  std::vector<Vec3> normals;  // empty when the file gives none
  bool closed = false;
  double half_width = 0.0;  // w_0
  Color color{1.0, 1.0, 1.0};
  bool smooth = true;  // false: straight segments, as for curves
  // Joins: the seed's rule covers a point only inside some segment's slab (eq 25,
  // pr1 ∧ (pr2 ∨ pr3)), which leaves a notch outside each bend; round: (pr1 ∧ pr3) ∨ pr2, so
  // every point's round cap counts (docs/algorithms.md §2).
  bool round_join = false;
};

// A parametric patch of docs/algorithms.md §4 (seed 003). A `bezier_set` in the file becomes one
// Patch per member (same colour). Control points are row-major with rows of constant u index: point
// (iu, iv) is control_points[iu * size_v + iv].
enum class PatchType { kBezier, kBSpline, kNurbs };
struct Patch {
  PatchType type = PatchType::kBezier;
  int degree_u = 3, degree_v = 3;
  int size_u = 4, size_v = 4;        // control grid (nu, nv); Bézier: degree + 1
  std::vector<Vec3> control_points;  // size_u · size_v
  std::vector<double> knots_u;       // size_u + degree_u + 1 values (empty for Bézier)
  std::vector<double> knots_v;       // size_v + degree_v + 1 values (empty for Bézier)
  std::vector<double> weights;       // size_u · size_v, > 0 (NURBS only; empty otherwise)
  Color color{1.0, 1.0, 1.0};
};

struct Scene {
  std::string source;  // file name (or "<name>" for embedded scenes), for error messages
  Camera camera;
  Color background{0.0, 0.0, 0.0};
  std::vector<Curve> curves;
  std::vector<Texture> textures;
  std::vector<Surface> surfaces;  // docs/algorithms.md §3 (seed 004), scene/surface.h
  std::vector<Patch> patches;  // docs/algorithms.md §4; float backend only (no fixed-point path)
  std::string about;  // the file's free one-line description ("about"), "" when it has none
};

// Largest accepted image side and pixel count: bigger requests are refused, not attempted
// (common/limits.h holds every limit).
inline constexpr int kMaxImageSide = limits::kMaxImageSide;
inline constexpr long long kMaxImagePixels = limits::kMaxImagePixels;

}  // namespace rpu::scene
