// The preliminary value map of docs/algorithms.md §4 (seed 003, eqs 5–8): the patches rasterised
// once (tessellated, z-buffered) into a map holding, per texel, the number of the front patch and
// its parameters (u, v) — the start of every pixel's refinement. The thesis codes the map as an RGB
// image: R = patch number + 1 (0: no surface, eq 5), G, B = round(255·u), round(255·v) on the
// normalised domain (eqs 6–8). Here the patch number is an int (no 254-patch limit); u, v are
// quantised to 8 bits as the thesis does, or kept at full precision (`quantised` false).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/limits.h"
#include "patch/patch_surface.h"
#include "scene/camera.h"

namespace rpu::patch {

struct MapOptions {
  int width = 0, height = 0;      // map resolution; 0 = the image's
  bool quantised = true;          // u, v to 8 bits (eqs 6–8); false: full precision
  int grid = 0;                   // tessellation cells per patch side; 0 = automatic (per knot span)
  double max_chord_pixels = 0.25; // automatic grid: chord error below this, in map texels
  int max_grid = 256;             // automatic grid: cells per knot span
  // Cells of one patch per direction (more knot spans than this: the direction is tessellated
  // as one span) and cells of all patches together (limits.h; past it build_preliminary_map
  // throws rpu::Error(where, ...) before tessellating).
  int max_cells_per_side = limits::kMaxMapCellsPerSide;
  long long max_cells = limits::kMaxMapCells;
  std::string where = "patches";  // names the scene in a refusal
  int threads = 0;                // 0 = all cores
};

struct MapTexel {
  std::int32_t patch = -1;  // −1: no surface (R = 0)
  float u = 0, v = 0;       // start parameters (quantised when MapOptions::quantised)
  float depth = 0;          // c of the tessellated surface (z-buffer)
};

struct PreliminaryMap {
  int width = 0, height = 0;
  int image_width = 0, image_height = 0;  // the image the map serves
  std::vector<MapTexel> texels;           // row-major
  std::int64_t triangles = 0;
  std::vector<int> grid_per_patch;

  const MapTexel& at(int a, int b) const { return texels[static_cast<size_t>(b) * width + a]; }
  // The texel under the centre of image pixel (i, j).
  int map_x(int i) const { return static_cast<int>((i + 0.5) * width / image_width); }
  int map_y(int j) const { return static_cast<int>((j + 0.5) * height / image_height); }
};

// 8-bit parameter code of eqs 6–8: round(255·t) / 255.
inline double quantise_parameter(double t) {
  const double q = static_cast<double>(static_cast<int>(t * 255.0 + 0.5)) / 255.0;
  return q < 0.0 ? 0.0 : (q > 1.0 ? 1.0 : q);
}

// The tessellation's cell counts per patch, in both directions (the knot lines and the cells per
// span of the automatic grid), without tessellating. Their sum is what the budget bounds.
struct MapGrid {
  std::vector<std::vector<double>> us, vs;  // per patch: the parameter lines in u and in v
  long long cells = 0;                      // Σ (|us| − 1)·(|vs| − 1)
};
MapGrid preliminary_map_grid(const std::vector<PatchSurface>& patches,
                             const scene::CameraFrame& camera, const MapOptions& options);

// Builds the map. Triangles are clipped at a near plane 1e-6 of the patches' extent in front of
// the eye (a triangle reaching behind the eye keeps its part in front), tessellated and
// rasterised in chunks of bounded size (kChunkCells cells), so the memory in flight does not
// grow with the number of patches. Throws rpu::Error(options.where, ...) when the cells exceed
// options.max_cells.
inline constexpr long long kChunkCells = 1LL << 17;
// The memory of one chunk in flight, at most (checked at compile time against the triangles' size).
inline constexpr long long kMapChunkBytes = 64LL << 20;
PreliminaryMap build_preliminary_map(const std::vector<PatchSurface>& patches,
                                     const scene::CameraFrame& camera, const MapOptions& options);

}  // namespace rpu::patch
