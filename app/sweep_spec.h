// The sweep file of `rpu sweep` (docs/sweeps.md): its schema, strictly checked, and the grid's
// configurations. Every mistake in the file is one rpu::Error "<file>: <json path>: <problem>":
// unknown or duplicate keys, wrong types, out-of-range numbers, repeated grid values, image
// sizes past limits::check_image_size, grids past limits::kMaxSweepConfigurations.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/hw_params.h"
#include "scene/scene.h"

namespace rpu::app {

// A grid or "base" names hardware parameters by their keys in the parameter table
// (ref/model/hw_params.def: n, n1, ..., metric, ip, surf_w, angle_w); results list them in the
// table's order.

// A parameter's Verilog value (the -G of a Verilated build, Yosys's chparam): the member as an
// integer (metric abs 0 / squared 1, ip unrolled 1 / iterative 0).
std::string verilog_value(const ref::HwParamInfo& d, const ref::HwParams& p);

// An object of hardware parameters by key over the defaults: a sweep file's "base", or the
// "config" of metrics.json (hw_params_json). Values outside int are refused, and so are unknown
// keys, wrong types and unknown choice names, each naming "<where>.<key>"; HwParams::validate
// is the caller's.
ref::HwParams hw_params_from_json(const nlohmann::json& object, const std::string& where);

// One scene of the sweep.
struct SweepScene {
  std::string argument;  // as written in the sweep file
  std::string path;      // the file read (relative paths: from the sweep file's directory), or
                         // builtin:NAME
  std::string label;     // its key in a row's "scenes" and its results.csv columns; distinct
                         // per sweep (the file's stem; the argument when two stems agree)
};

struct SweepSpec {
  std::string path;
  std::vector<SweepScene> scenes;
  int width = 64, height = 64;
  std::vector<std::pair<std::string, std::vector<nlohmann::json>>> grid;  // in file order
  ref::HwParams base;
  bool rtl = true;
  int rtl_width = 32, rtl_height = 32;
  // Verilate configurations the rpu executable does not contain (RPU_COSIM_ONLY build under
  // DIR/rtl_build, one cosim_<id> per configuration, kept across runs).
  bool rtl_build = false;
  // Resources: the whole module (rpu_top by default) at each configuration's parameters through
  // the cached hierarchical synthesis flow (scripts/synth_hier.py; docs/resources.md).
  bool yosys = false;
  std::string yosys_module = "rpu_top";
  int yosys_timeout = 3600;  // per derived module
};

// Reads (rpu::read_input_file, "sweep file") and checks the sweep file. Reads no scene.
SweepSpec parse_sweep_file(const std::string& path);
// The same on the file's contents already read (`path` names it in messages and is the base of
// relative scene files); fuzz/fuzz_sweep calls it.
SweepSpec parse_sweep_text(const std::string& text, const std::string& path);

// The scenes' contents: each file read with rpu::read_input_file ("scene file"), a built-in's
// embedded text; then parsed, so a bad scene is refused before any configuration runs.
struct LoadedScenes {
  std::vector<scene::Scene> scenes;  // as in SweepSpec::scenes
  std::string fingerprint;           // a hash of every label and content
};
LoadedScenes load_sweep_scenes(const SweepSpec& s);

// What a stored result must match to be reused: the scenes' labels and contents, the
// resolutions and the measurements switched on.
std::string sweep_fingerprint(const SweepSpec& s, const LoadedScenes& scenes);

struct SweepConfig {
  std::string id;  // a hash of params_json
  ref::HwParams params;
  nlohmann::json params_json;
};

// The grid's configurations in order (the first grid key varies fastest). parse_sweep_file has
// bounded their number and refused repeated values, so every id is distinct.
std::vector<SweepConfig> expand_grid(const SweepSpec& s);

// FNV-1a 64 of the bytes, as 16 hex digits.
std::string hash_hex(const std::string& bytes);

// The hash of what a sweep's RTL and Yosys columns are made of, under the checkout root: every
// file under rtl/ (sources, headers, the file list, the lint waivers) and scripts/synth_hier.py,
// by relative path and content. Part of the resume fingerprint when rtl or yosys is on, so a
// result of the design before an RTL edit is not reused for the design after it.
std::string rtl_fingerprint(const std::filesystem::path& root);

// JSON text that never throws on strings that are not UTF-8 (paths from the file system):
// invalid bytes become U+FFFD.
std::string dump_json(const nlohmann::json& j, int indent = -1);

}  // namespace rpu::app
