// Reading and strictly validating scene files (docs/scene-format.md).
#pragma once

#include <string>

#include "scene/scene.h"

namespace rpu::scene {

// Parses `text` (the contents of a scene file called `source`) and validates it. Throws
// rpu::Error naming `source`, the JSON path (e.g. "curves[2].normals[5]") and the problem.
Scene parse_scene(const std::string& text, const std::string& source);

// Reads and parses the file at `path`.
Scene load_scene(const std::string& path);

}  // namespace rpu::scene
