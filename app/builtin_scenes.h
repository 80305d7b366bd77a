// The demo scenes of scenes/, embedded in the executable.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace rpu::app {

struct BuiltinScene {
  const char* name;  // file name without extension, e.g. "curve12"
  const char* json;
};

const std::vector<BuiltinScene>& builtin_scenes();

// Loads a scene given as a path or as "builtin:NAME". Throws rpu::Error.
scene::Scene load_scene_argument(const std::string& argument);

}  // namespace rpu::app
