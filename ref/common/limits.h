// The project's input limits, in one place (README, "Limits"). Every entry point applies these:
// scene files, command-line flags and sweep files alike. A request past a limit is refused with
// one line naming where it came from, never attempted.
#pragma once

#include <cstdint>
#include <string>

namespace rpu::limits {

// Largest accepted image side and pixel count (2^26 = 67,108,864 pixels: a 64 Mpixel frame
// needs about 1.3 GB across the frame buffers of one backend).
inline constexpr int kMaxImageSide = 16384;
inline constexpr long long kMaxImagePixels = 1LL << 26;

// Largest input file read (scene files, sweep files): 64 MiB. Only regular files are read, so
// a FIFO, a device or /proc file is refused instead of blocking or growing without bound.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{64} << 20;

// Coordinate range of scene files: every position (points, camera eye and target), direction
// (normals, camera up) and half_width must be a finite number with |v| <= kMaxCoordinate world
// units. Larger values are refused as "out of range" at their JSON path: past this bound the
// geometry's squared lengths and cross products lose their meaning (1e154 squared overflows a
// double) long before the image could show anything. Every demo scene stays below 1e4.
inline constexpr double kMaxCoordinate = 1e9;

// Deepest nesting of arrays and objects in a scene or sweep file (their schemas need 4); deeper
// input is refused before it is built, so a file of a million '[' cannot exhaust the stack or
// memory.
inline constexpr int kMaxJsonDepth = 64;

// Highest degree of a parametric patch in either direction (docs/algorithms.md §4; the thesis uses
// 3). Evaluation keeps its basis functions in fixed arrays of kMaxPatchDegree + 1.
inline constexpr int kMaxPatchDegree = 10;

// ---- Patches, surfaces and volumes (issue 24; README "Limits", docs/patches.md and
// docs/surfaces.md, "Budgets"). Every budget below is checked from the scene and the image before
// the memory or the work is committed; past it, one error line names the budget and the flag or
// key to change.

// Patches per scene (a bezier_set counts each member) and surfaces per scene.
inline constexpr int kMaxPatches = 4096;
inline constexpr int kMaxSurfaces = 256;

// Widest field of view (camera.fov_deg) of a scene with patches: the map methods lose hits
// beyond it (docs/patches.md, "Precision").
inline constexpr double kMaxPatchFovDeg = 179.9;

// --patch-iterations: the budget of the thesis's gradient refiners (steps or directions); their
// evaluation budget is 4× this.
inline constexpr int kMaxPatchIterations = 1024;

// Memory of one render of a scene with patches: the frame and the image, the per-pixel hit map,
// the preliminary map and the tessellation in flight, or Martin's BVH at its leaf budget
// (patch::patch_render_bytes, ref/patch/patch_renderer.h).
inline constexpr long long kMaxPatchRenderBytes = 1LL << 30;

// Tessellation cells of the preliminary map, summed over the patches (each cell is a point
// evaluation and two triangles). A patch gets at most kMaxMapCellsPerSide cells per direction.
inline constexpr long long kMaxMapCells = 1LL << 21;
inline constexpr int kMaxMapCellsPerSide = 1024;

// Martin's BVH: Bézier pieces per patch after knot insertion, and sub-patch leaves in all.
inline constexpr long long kMaxMartinPiecesPerPatch = 1LL << 12;
inline constexpr long long kMaxMartinLeaves = 1LL << 20;

// Ray/primitive work that no per-pixel bound limits: texel/patch pairs of the preliminary map's
// rasterisation (its overdraw), ray/box pairs of Martin's traversal (a Newton start each),
// ray/patch pairs of random starts (eq 3: 64 evaluations and up to 4 descents each) and
// ray/surface pairs of the surface tracers (`float`: up to 2·kIdealSamplesPerRadius indicator
// evaluations per piece). The
// estimate counts the pixels (texels) inside the screen rectangle of each projected control net
// or box (every pixel for one reaching behind the eye). The budget is kPairsPerPixel pairs per
// pixel (texel) on average, and never below kMinPairBudget.
inline constexpr long long kMapPairsPerPixel = 64;
inline constexpr long long kMartinPairsPerPixel = 64;
inline constexpr long long kRandomStartPairsPerPixel = 16;
inline constexpr long long kSurfacePairsPerPixel = 4;
inline constexpr long long kMinPairBudget = 1LL << 16;

// rpu volume: work units (one unit: a control point visited by an evaluation, or a term of the
// exact Bernstein sums) over the exact sums, the Gauss–Legendre check, the graphical integration
// at 10×10 and 100×100 nodes and the slice samples at --slice-grid (patch::volume_work).
inline constexpr long long kMaxVolumeWork = 1LL << 30;

// Largest sweep grid (configurations after expansion) and largest worker count.
inline constexpr long long kMaxSweepConfigurations = 10000;
inline constexpr int kMaxThreads = 1024;

// Co-simulation: Verilated instances at once in one process (`--jobs`; each holds a whole model
// of rpu_top), and shares of one frame (`--shard I/N`, e.g. the tasks of a Slurm job array).
inline constexpr int kMaxCosimJobs = 64;
inline constexpr int kMaxShards = 100000;

// Throws rpu::Error(where, ...) unless 1 <= width, height <= kMaxImageSide and
// width * height <= kMaxImagePixels.
void check_image_size(const std::string& where, long long width, long long height);

// Throws rpu::Error(where, ...) unless 0 <= threads <= kMaxThreads (0 = all cores).
void check_threads(const std::string& where, long long threads);

}  // namespace rpu::limits
