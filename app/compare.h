// `rpu compare SCENE --out DIR` (README "Command line"): every backend on one scene, the RTL
// checked against the model work item by work item, and the report (compare_report.h).
#pragma once

#include <string>

#include "backends.h"
#include "scene/scene.h"

namespace rpu::app {

struct CompareOptions {
  std::string out_dir;
  std::string input_file;  // the scene file ("" for builtin:NAME); compare never overwrites it
  BackendOptions backends;
  bool skip_rtl = false;   // --no-rtl: the three software backends only
  bool quiet = false;
  std::string command;     // the command line, for the report's record (run_record.h)
};

// Exit status: 0 when the RTL equals the model on every pixel (and every work item), or when the
// RTL was skipped (--no-rtl) and the software backends ran; 2 when the RTL differs from the
// model; errors throw rpu::Error. A ref vs float-ip difference beyond kRefVsFloatIpBound prints
// "rpu: warning: <scene>: ..." on stderr (even when quiet) and leaves the status unchanged.
int run_compare(const std::string& scene_arg, const scene::Scene& scene,
                const CompareOptions& o, nlohmann::json* metrics_out = nullptr);

}  // namespace rpu::app
