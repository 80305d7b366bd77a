// The keys a scene file may hold, object by object: the one table the scene reader
// (scene_json.cpp) accepts and docs/scene-format.md documents. Each object path is the heading of
// its section in that document with the backticks removed ("surfaces[*] type spiral"); the keys
// are in the order an "unknown key" error lists them. tests/test_scene_format_doc.cpp checks the
// document's tables against this table.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rpu::scene {

// One kind of object in a scene file and the keys it accepts.
struct ObjectKeys {
  std::string_view path;                   // "top level", "camera", "patches[*] type nurbs", ...
  std::span<const std::string_view> keys;  // accepted keys; any other key is refused
};

namespace scene_keys_detail {

using K = std::string_view;
inline constexpr K kTop[] = {"about", "camera", "background", "curves", "textures", "surfaces",
                             "patches"};
inline constexpr K kCamera[] = {"eye", "target", "up", "fov_deg", "width", "height"};
inline constexpr K kCurve[] = {"points", "normals", "closed", "smooth", "color"};
inline constexpr K kTexture[] = {"points", "normals", "closed", "smooth", "join", "half_width",
                                  "color"};
// Surfaces (seed 004): the placement and colour, then the type's own parameters.
inline constexpr K kEllipsoid[] = {"type", "position", "rotation_deg", "scale", "color",
                                   "a", "b", "c", "y_range"};
inline constexpr K kReliefEllipsoid[] = {"type", "position", "rotation_deg", "scale", "color",
                                         "a", "b", "c", "d", "e", "y_range"};
inline constexpr K kSpiral[] = {"type", "position", "rotation_deg", "scale", "color",
                                "R", "k", "a", "b", "c", "phi_max"};
inline constexpr K kSnail[] = {"type", "position", "rotation_deg", "scale", "color", "a",
                               "phi_max"};
inline constexpr K kRocket[] = {"type", "position", "rotation_deg", "scale", "color",
                                "a", "b", "c", "d", "e"};
// Patches (seed 003).
inline constexpr K kBezier[] = {"type", "degree", "control_points", "color"};
inline constexpr K kBezierSet[] = {"type", "degree", "patches", "color"};
inline constexpr K kBSpline[] = {"type", "degree", "size", "knots_u", "knots_v",
                                 "control_points", "color"};
inline constexpr K kNurbs[] = {"type", "degree", "size", "knots_u", "knots_v",
                               "control_points", "weights", "color"};

}  // namespace scene_keys_detail

// Every object of a scene file, in the order of docs/scene-format.md.
inline constexpr ObjectKeys kSceneKeys[] = {
    {"top level", scene_keys_detail::kTop},
    {"camera", scene_keys_detail::kCamera},
    {"curves[*]", scene_keys_detail::kCurve},
    {"textures[*]", scene_keys_detail::kTexture},
    {"surfaces[*] type ellipsoid", scene_keys_detail::kEllipsoid},
    {"surfaces[*] type relief_ellipsoid", scene_keys_detail::kReliefEllipsoid},
    {"surfaces[*] type spiral", scene_keys_detail::kSpiral},
    {"surfaces[*] type snail", scene_keys_detail::kSnail},
    {"surfaces[*] type rocket", scene_keys_detail::kRocket},
    {"patches[*] type bezier", scene_keys_detail::kBezier},
    {"patches[*] type bezier_set", scene_keys_detail::kBezierSet},
    {"patches[*] type bspline", scene_keys_detail::kBSpline},
    {"patches[*] type nurbs", scene_keys_detail::kNurbs},
};

// The keys accepted at `path` (a path of kSceneKeys). In a constant expression an unknown path
// does not compile; at run time it throws std::out_of_range.
constexpr std::span<const std::string_view> accepted_keys(std::string_view path) {
  for (const ObjectKeys& o : kSceneKeys)
    if (o.path == path) return o.keys;
  throw std::out_of_range("scene_keys: no object path '" + std::string(path) + "'");
}

}  // namespace rpu::scene
