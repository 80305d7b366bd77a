// The frame of the top-level testbenches (tb_rpu_top, tb_rpu_axi): NAME or NAME+OTHER+... of the
// demo scenes, the first one's camera with every scene's primitives (a frame that mixes curve,
// texture and surface items, so the order FIFO merges the result streams).
#pragma once

#include <algorithm>
#include <string>

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

}  // namespace rpu::sim
