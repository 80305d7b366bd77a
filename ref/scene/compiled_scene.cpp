#include "scene/compiled_scene.h"

#include <fmt/format.h>

#include <cmath>

#include "common/error.h"
#include "scene/normals.h"

namespace rpu::scene {
namespace {

// Builds the segments of one polyline; `kind` is "curves" or "textures" for error paths.
template <class Polyline>
void compile_polyline(const Polyline& line, const char* kind, int index, int primitive,
                      double half_width, const std::string& source,
                      std::vector<CompiledSegment>& out) {
  const bool planar = std::string_view(kind) == "textures";
  const std::vector<Vec3> normals =
      line.normals.empty() ? derive_normals(line.points, line.closed, planar) : line.normals;
  const size_t n = line.points.size();
  const size_t segments = line.closed ? n : n - 1;
  for (size_t s = 0; s < segments; ++s) {
    const size_t a = s, b = (s + 1) % n;
    SegmentDefect defect;
    int end = 0;
    const auto seg = make_segment(line.points[a], line.points[b], normals[a], normals[b], defect, end);
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
    out.push_back({*seg, primitive, static_cast<int>(s), half_width});
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
    compile_polyline(scene.curves[c], "curves", static_cast<int>(c), id, 0.0, scene.source,
                     out.curve_segments);
  }
  for (size_t t = 0; t < scene.textures.size(); ++t) {
    const auto& tex = scene.textures[t];
    const int id = static_cast<int>(out.primitives.size());
    out.primitives.push_back({Primitive::Kind::kTexture, static_cast<int>(t), tex.color});
    compile_polyline(tex, "textures", static_cast<int>(t), id, tex.half_width, scene.source,
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

}  // namespace rpu::scene
