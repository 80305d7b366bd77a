// `--backend ref`: the bit-accurate model renders a frame, all cores. The work items (pixel,
// segment) are those the host would stream into the hardware: curve segments from the screen
// bins, texture segments from the classification grid at the ray/plane unit's point p0, and
// every surface (docs/algorithms.md §3) as up to three piece work items (rpu_surface_top.h).
#pragma once

#include <cstdint>

#include "image/frame.h"
#include "model/descriptors.h"
#include "scene/compiled_scene.h"

namespace rpu::ref {

struct RefStats {
  std::uint64_t curve_pairs = 0;    // curve work items
  std::uint64_t texture_pairs = 0;  // texture work items
  std::uint64_t surface_pairs = 0;  // (pixel, surface) pairs: the host issues 1 or 3 piece
                                    // work items each (surface_piece_items)
  std::uint64_t surface_pieces = 0; // piece work items that were valid (searched by the IP)
  std::uint64_t overflow_pairs = 0; // work items in which some value saturated
};

struct RefOptions {
  int threads = 0;       // 0 = all hardware threads
  bool binning = true;   // screen bins for curve work items (never changes the image)
  bool grid = true;      // classification grid for texture work items (never changes the image)
};

image::Frame render_ref(const scene::CompiledScene& scene, const ModelScene& model,
                        const RefOptions& options, RefStats* stats = nullptr);

}  // namespace rpu::ref
