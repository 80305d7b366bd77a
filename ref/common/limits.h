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

// Largest sweep grid (configurations after expansion) and largest worker count.
inline constexpr long long kMaxSweepConfigurations = 10000;
inline constexpr int kMaxThreads = 1024;

// Throws rpu::Error(where, ...) unless 1 <= width, height <= kMaxImageSide and
// width * height <= kMaxImagePixels.
void check_image_size(const std::string& where, long long width, long long height);

// Throws rpu::Error(where, ...) unless 0 <= threads <= kMaxThreads (0 = all cores).
void check_threads(const std::string& where, long long threads);

}  // namespace rpu::limits
