// The report of `rpu compare` (README "Command line"): the backends' images, their pairwise
// difference images, a disagreement heat map, metrics.json and a self-contained report.html.
// Rendering the images is the caller's business; this module only compares and writes.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/frame.h"
#include "scene/scene.h"

namespace rpu::app {

// One backend's image.
struct BackendRender {
  std::string name;    // "float", "float-ip", "ref", "rtl" (letters, digits, '-', '_' only)
  image::Frame frame;  // per pixel primitive id (image::kBackground = -1) and depth
  double seconds = 0;  // wall time of the render
  // World units per unit of frame.depth: 1 for the float backends; ref and rtl keep the model's
  // fixed-point depth c·S·2^(FE+14), whose scale S is that render's own normalisation.
  double depth_unit = 1.0;
};

// Everything the report shows.
struct CompareInput {
  std::string scene;                   // scene argument as given (file or builtin:NAME)
  std::string input_file;              // the scene file ("" for builtin:NAME): never overwritten
  std::vector<scene::Color> colors;    // per primitive id
  scene::Color background;
  std::vector<BackendRender> renders;  // any subset; rtl and ref normally present
  nlohmann::json config;               // effective hardware parameters (a table in the report)
  nlohmann::json rtl;  // co-simulation statistics: cycles, pairs, latency_cycles, stall_cycles,
                       // items_per_cycle, sim_seconds, harness ("c++"/"systemc"), ...; may be null
  std::vector<std::string> mismatch_lines;  // human-readable mismatch records (first few)
  // The engineering record (run_record.h: command, git commit, tool versions) and the whole
  // run's wall time; may be null.
  nlohmann::json record;
  // Per primitive id: true for a curve (the connectivity count follows curves).
  std::vector<bool> curve_primitive;
  nlohmann::json extra_metrics;  // merged into metrics.json at the top level (e.g. "patches",
                                 // "not_applicable"); may be null
};

struct CompareSummary {
  nlohmann::json metrics;  // what metrics.json holds
  bool rtl_equals_ref;     // both rtl and ref rendered and equal on every pixel; false otherwise
  std::string warning;     // ref_vs_float_ip_warning(metrics): "" within the bound
};

// The documented agreement of `ref` and `float-ip` (README, docs/fixed-point.md): at the default
// parameters they differ on at most this fraction (0.1 %) of the hit pixels (the larger of the
// two hit counts) of every demo scene. Beyond it compare warns (stderr, metrics.json, banner);
// the exit status is unchanged (2 is reserved for RTL != model).
inline constexpr double kRefVsFloatIpBound = 0.001;
// The report lists at most this many differing pixels (metrics.json "differing_pixels").
inline constexpr size_t kMaxPixelRecords = 100;
// A depth "agrees" within this relative difference (the depth statistics of ref vs float).
inline constexpr double kDepthAgreement = 1e-3;

// ... and never on this many differing pixels or fewer, whatever the frame: at 0.1 % a frame
// needs 1,000 hit pixels before one pixel may differ, and a pixel whose closest approach lies on
// a pixel edge to within the IP's resolution goes either way in any frame (docs/verification.md,
// "Fuzzing": the ambiguous pixels). One pixel of 295 is not a finding.
inline constexpr size_t kRefVsFloatIpSlackPixels = 2;

// The compared pairs, in report order: (a, b) gives diff_<a>_vs_<b>.png and the metrics key
// <a>_vs_<b>_mismatched_pixels ('-' written '_').
inline constexpr std::array<std::array<std::string_view, 2>, 4> kComparedPairs = {{
    {"rtl", "ref"}, {"ref", "float-ip"}, {"ref", "float"}, {"float-ip", "float"}}};

// Difference image colours (linear RGB, written to 8 bit as round(255·c)). Where a and b agree
// the difference image shows a at kAgreeBrightness of its colour.
inline constexpr float kAgreeBrightness = 0.25f;
inline constexpr scene::Color kHitOnlyInA = {1.0, 0.4, 0.0};         // orange
inline constexpr scene::Color kHitOnlyInB = {0.0, 0.6, 1.0};         // azure
inline constexpr scene::Color kDifferentPrimitive = {1.0, 0.0, 1.0}; // magenta

// The heat map shows, per pixel, heat_value(d, P) through this OpenImageIO colour map, where d is
// the number of compared pairs that disagree there and P the number of pairs compared (both
// renders present), encoded to sRGB so the PNG shows the map's published colours: near-black
// (#000004) where all agree, pale yellow (#fcffa4) where every pair disagrees.
inline constexpr std::string_view kHeatColorMap = "inferno";

// Where no pair disagrees 0; otherwise (d + 1) / (P + 1), which keeps a single disagreeing pair
// (0.4 of four) well clear of the map's near-black low end.
constexpr double heat_value(int d, int P) { return d == 0 ? 0.0 : (d + 1.0) / (P + 1.0); }

// Images whose larger side is below this are also written enlarged (nearest neighbour, integer
// factor k = max(2, 512 / side), file <name>_x<k>.png) and the report shows the enlarged copy.
inline constexpr int kEnlargeBelow = 256;
// Difference images up to this side are enlarged at least ×2 even from kEnlargeBelow on, so that
// a single differing pixel can be seen (a 256×256 demo image's differences are shown at 512×512).
inline constexpr int kDiffEnlargeUpTo = 1024;

// metrics.json (and CompareSummary::metrics) holds: scene, width, height, pixels;
// <a>_vs_<b>_mismatched_pixels for the four pairs (null when a render is missing); cycles, pairs,
// latency_cycles copied from `rtl` (null when absent); rtl_equals_ref (null unless rtl and ref
// both rendered); backends.<name>.{hit_pixels, seconds, image}; comparisons.<a>_vs_<b>.
// {mismatched_pixels, hit_only_in_<a>, hit_only_in_<b>, different_primitive, image} (or null);
// heatmap.{image, color_map, pairs_compared, pixels_by_disagreeing_pairs[d]}; config; rtl;
// mismatch_records; ref_vs_float_ip_hit_pixels, ref_vs_float_ip_fraction,
// ref_vs_float_ip_beyond_bound (null unless ref and float-ip both rendered) and
// ref_vs_float_ip_bound (kRefVsFloatIpBound). A pixel mismatches when its primitive id differs
// (image::count_differing_pixels).
//
// Writes into out_dir (created if missing): <backend>.png for every render; diff_<a>_vs_<b>.png
// for each of kComparedPairs whose both renders exist; heatmap.png; metrics.json; report.html.
// Every file is first written into a staging directory inside out_dir and moved into place only
// when all were written (renames replace symlinks there, never follow them); on failure nothing
// of this run is left. Files of an earlier run that this one does not write (any name compare
// owns: metrics.json, report.html, <stem>.png and <stem>_x<k>.png for every backend, diff and the
// heat map) are removed. Throws rpu::Error naming the path on I/O failure, and naming the backend
// on inconsistent input (frames of different sizes, unknown primitive ids, repeated or unusable
// names).
CompareSummary write_compare_report(const CompareInput& in, const std::string& out_dir);

// Refuses, before any work: an empty out_dir, an out_dir that exists and is not a directory, and
// an out_dir where a file compare owns is `input_file` (same device and inode, so hard links and
// symlinks count). Throws rpu::Error naming the path.
void check_compare_output(const std::string& out_dir, const std::string& input_file);

// ref vs float-ip as compare measures it against kRefVsFloatIpBound: the pixels whose primitive
// differs (image::count_differing_pixels), the hit pixels (the larger of the two hit counts),
// their fraction (0 without hits) and whether the difference is beyond the bound (more than
// kRefVsFloatIpBound of the hit pixels and more than kRefVsFloatIpSlackPixels). The frames
// must have one size. metrics.json's ref_vs_float_ip_* hold these; fuzz/fuzz_render checks them.
struct RefVsFloatIp {
  size_t differing = 0;
  size_t hit_pixels = 0;
  double fraction = 0.0;
  bool beyond_bound = false;
};
RefVsFloatIp ref_vs_float_ip(const image::Frame& ref, const image::Frame& float_ip);

// "ref differs from float-ip on N of M hit pixels (P %), beyond the documented bound of 0.1 %"
// when metrics.ref_vs_float_ip_beyond_bound is true; "" otherwise.
std::string ref_vs_float_ip_warning(const nlohmann::json& metrics);

}  // namespace rpu::app
