#include "scene/compiled_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/limits.h"
#include "scene/normals.h"

namespace rpu::scene {
namespace {

// Builds the segments of one polyline; `kind` is "curves" or "textures" for error paths.
template <class Polyline>
void compile_polyline(const Polyline& line, const char* kind, int index, int primitive,
                      double half_width, bool round_join, const std::string& source,
                      std::vector<CompiledSegment>& out) {
  const bool planar = std::string_view(kind) == "textures";
  // A straight polyline ("smooth": false) takes no normals: each segment gets, at both ends, a
  // normal perpendicular to its own chord, which makes both guides straight (docs/algorithms.md
  // §1: the reference sphere's centre at infinity).
  const std::vector<Vec3> normals =
      !line.smooth ? std::vector<Vec3>{}
      : line.normals.empty() ? derive_normals(line.points, line.closed, planar) : line.normals;
  const size_t n = line.points.size();
  const size_t segments = line.closed ? n : n - 1;
  for (size_t s = 0; s < segments; ++s) {
    const size_t a = s, b = (s + 1) % n;
    SegmentDefect defect;
    int end = 0;
    Vec3 na, nb;
    if (line.smooth) {
      na = normals[a];
      nb = normals[b];
    } else {
      na = nb = chord_perpendicular(line.points[b] - line.points[a], planar);
    }
    const auto seg = make_segment(line.points[a], line.points[b], na, nb, defect, end);
    if (!seg) {
      const size_t at = end == 0 ? a : b;
      switch (defect) {
        case SegmentDefect::kRepeatedPoint:
          throw Error(fmt::format("{}: {}[{}].points[{}]", source, kind, index, b),
                      fmt::format("repeated consecutive point (same as points[{}]); the segment "
                                  "would have zero length", a));
        case SegmentDefect::kLengthOutOfRange: {
          const Vec3 d = line.points[b] - line.points[a];
          const double m = std::fmax(std::fabs(d.x), std::fmax(std::fabs(d.y), std::fabs(d.z)));
          throw Error(fmt::format("{}: {}[{}].points[{}]", source, kind, index, b),
                      fmt::format("the segment from points[{}] is too short to compute with "
                                  "(length about {:.3g}; its squared length underflows a double); "
                                  "scale the scene up", a, m));
        }
        case SegmentDefect::kNormalParallelToChord:
          throw Error(fmt::format("{}: {}[{}].normals[{}]", source, kind, index, at),
                      fmt::format("normal is parallel to segment points[{}]→points[{}]; the arc "
                                  "plane is undefined{}", a, b,
                                  line.normals.empty() ? " (derived normal)" : ""));
        case SegmentDefect::kZeroNormal:
        case SegmentDefect::kNone:
          throw Error(fmt::format("{}: {}[{}].normals[{}]", source, kind, index, at),
                      "normal has zero length");
      }
    }
    out.push_back({*seg, primitive, static_cast<int>(s), half_width, round_join});
  }
}

}  // namespace

CompiledScene compile_scene(const Scene& scene) {
  CompiledScene out;
  out.source = scene.source;
  out.camera = make_camera_frame(scene.camera, scene.source);
  out.background = scene.background;
  for (size_t c = 0; c < scene.curves.size(); ++c) {
    const int id = static_cast<int>(out.primitives.size());
    out.primitives.push_back({Primitive::Kind::kCurve, static_cast<int>(c), scene.curves[c].color});
    compile_polyline(scene.curves[c], "curves", static_cast<int>(c), id, 0.0, false, scene.source,
                     out.curve_segments);
  }
  for (size_t t = 0; t < scene.textures.size(); ++t) {
    const auto& tex = scene.textures[t];
    const int id = static_cast<int>(out.primitives.size());
    out.primitives.push_back({Primitive::Kind::kTexture, static_cast<int>(t), tex.color});
    compile_polyline(tex, "textures", static_cast<int>(t), id, tex.half_width, tex.round_join,
                     scene.source,
                     out.texture_segments);
  }
  out.texture_grid = ClassificationGrid::build(out.texture_segments);
  // Surfaces (docs/algorithms.md §3) follow the textures; the scene reader has validated them.
  out.first_surface_primitive = static_cast<int>(out.primitives.size());
  for (size_t k = 0; k < scene.surfaces.size(); ++k) {
    const int id = static_cast<int>(out.primitives.size());
    out.primitives.push_back({Primitive::Kind::kSurface, static_cast<int>(k), scene.surfaces[k].color});
    out.surfaces.push_back(compile_surface(scene.surfaces[k], id));
  }
  // Patches (docs/algorithms.md §4) follow the surfaces; only the float backends trace them.
  out.first_patch_primitive = static_cast<int>(out.primitives.size());
  for (size_t k = 0; k < scene.patches.size(); ++k)
    out.primitives.push_back({Primitive::Kind::kPatch, static_cast<int>(k), scene.patches[k].color});
  out.patches = scene.patches;
  return out;
}

long long surface_screen_pairs(const CompiledScene& sc) {
  const CameraFrame& cam = sc.camera;
  const long long all = static_cast<long long>(cam.width) * cam.height;
  long long pairs = 0;
  for (const CompiledSurface& s : sc.surfaces) {
    const Vec3 q = s.centre - cam.eye;
    const double a = dot(cam.U, q), b = dot(cam.V, q), c = dot(cam.W, q), r = s.radius;
    if (!(c - r > 0.0)) {  // the sphere reaches the eye plane: every pixel
      pairs += all;
      continue;
    }
    // The box [a ± r] × [b ± r] × [c ± r] holds the sphere; a/c and b/c over it are extreme at
    // its corners.
    const double x0 = std::min((a - r) / (c - r), (a - r) / (c + r));
    const double x1 = std::max((a + r) / (c - r), (a + r) / (c + r));
    const double y0 = std::min((b - r) / (c - r), (b - r) / (c + r));
    const double y1 = std::max((b + r) / (c - r), (b + r) / (c + r));
    // Screen columns: x = (i + 0.5 − width/2)·σ; rows: y = (height/2 − j − 0.5)·σ.
    const double i0 = std::floor(x0 / cam.sigma + 0.5 * cam.width - 0.5);
    const double i1 = std::ceil(x1 / cam.sigma + 0.5 * cam.width - 0.5);
    const double j0 = std::floor(0.5 * cam.height - 0.5 - y1 / cam.sigma);
    const double j1 = std::ceil(0.5 * cam.height - 0.5 - y0 / cam.sigma);
    const double w = std::clamp(std::min(i1, cam.width - 1.0) - std::max(i0, 0.0) + 1, 0.0, double(cam.width));
    const double h = std::clamp(std::min(j1, cam.height - 1.0) - std::max(j0, 0.0) + 1, 0.0, double(cam.height));
    pairs += static_cast<long long>(w) * static_cast<long long>(h);
  }
  return pairs;
}

void check_surface_budget(const CompiledScene& sc) {
  if (sc.surfaces.empty()) return;
  const long long pixels = static_cast<long long>(sc.camera.width) * sc.camera.height;
  const long long budget = std::max(limits::kMinPairBudget, limits::kSurfacePairsPerPixel * pixels);
  const long long pairs = surface_screen_pairs(sc);
  if (pairs > budget)
    throw Error(sc.source + ": surfaces", fmt::format(
        "the {} surfaces cover up to {} ray/surface pairs ({:.1f} per pixel at {}x{}); at most {} "
        "(README, \"Limits\"); use fewer or smaller overlapping surfaces", sc.surfaces.size(),
        pairs, double(pairs) / double(pixels), sc.camera.width, sc.camera.height, budget));
}

}  // namespace rpu::scene
