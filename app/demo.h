// `rpu demo`: `rpu compare` on every built-in scene (every backend, the RTL checked against the
// model), with an index page and a summary table (summary.md, summary.json) across scenes.
#pragma once

#include <functional>
#include <string>

#include "compare.h"
#include "scene/scene.h"

namespace rpu::app {

// A scene argument (file or builtin:NAME) → the scene.
scene::Scene load_scene_argument(const std::string& argument);

struct DemoOptions {
  std::string out_dir = "out/demo";
  CompareOptions compare;  // backends, --no-rtl; out_dir is set per scene
  // Applies the size flags (--size, --max-side) to a loaded scene.
  std::function<scene::Scene(const std::string&)> load;
  // Scenes with surfaces are scaled down to at most this side (0: off) after the size flags: a
  // surface piece takes the search ring 142 cycles at the defaults, so a 256×256 surface frame is
  // 9 to 28 million simulated cycles (docs/cosim.md, "Speed").
  int surface_max_side = 48;
};

// Returns the process exit status: 0 when the RTL equals the model on every scene.
int run_demo(const DemoOptions& options);

}  // namespace rpu::app
