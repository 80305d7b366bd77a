// The frame of the top-level testbenches (tb_rpu_top, tb_rpu_axi): NAME or NAME+OTHER+... of the
// demo scenes, the first one's camera with every scene's primitives (a frame that mixes curve,
// texture and surface items, so the order FIFO merges the result streams).
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cosim.h"
#include "tb_common.h"

namespace rpu::sim {

inline scene::Scene merged_demo_scene(const std::string& names) {
  scene::Scene scn;
  for (std::size_t at = 0, k = 0; at <= names.size(); ++k) {
    const std::size_t end = std::min(names.find('+', at), names.size());
    const scene::Scene part = demo_scene(names.substr(at, end - at));
    if (k == 0) {
      scn = part;
    } else {
      scn.curves.insert(scn.curves.end(), part.curves.begin(), part.curves.end());
      scn.textures.insert(scn.textures.end(), part.textures.begin(), part.textures.end());
      scn.surfaces.insert(scn.surfaces.end(), part.surfaces.begin(), part.surfaces.end());
      scn.patches.insert(scn.patches.end(), part.patches.begin(), part.patches.end());
    }
    at = end + 1;
  }
  return scn;
}

// The top-level testbenches' command line, MODE [--scene NAME[+NAME...]] [--size N] [--config
// NAME] [--x-seed S], and the frame it names: the configuration (an AXI one when `axi`), the
// scene at N × N, the model's quantised scene and the frame's schedule.
struct TopBench {
  std::string mode = "frame", scene = "curve12", config;
  int size = 64;
  std::uint64_t x_seed = 0;
  const RtlConfig* cfg = nullptr;
  ref::ModelScene model;
  FrameSchedule frame;
};

// Fills `b` (its fields hold the defaults); prints "FAILURE: ..." and returns false when the
// configuration is not in this build.
inline bool top_bench(int argc, char** argv, bool axi, TopBench& b) {
  for (int a = 1; a < argc; ++a) {
    const std::string s = argv[a];
    if (s == "--scene" && a + 1 < argc) b.scene = argv[++a];
    else if (s == "--size" && a + 1 < argc) b.size = std::atoi(argv[++a]);
    else if (s == "--x-seed" && a + 1 < argc) b.x_seed = std::strtoull(argv[++a], nullptr, 0);
    else if (s == "--config" && a + 1 < argc) b.config = argv[++a];
    else b.mode = s;
  }
  for (const auto& c : rtl_configs())
    if (c.name == b.config && c.axi == axi) b.cfg = &c;
  if (!b.cfg) {
    std::printf("FAILURE: no %sconfiguration %s in this build\n", axi ? "AXI " : "",
                b.config.c_str());
    return false;
  }
  scene::Scene scn = merged_demo_scene(b.scene);
  scn.camera.width = b.size;
  scn.camera.height = b.size;
  const scene::CompiledScene sc = scene::compile_scene(scn);
  b.model = ref::quantize_scene(sc, b.cfg->params);
  b.frame = schedule_frame(sc, b.model, ref::RefOptions{});
  return true;
}

}  // namespace rpu::sim
