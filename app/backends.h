// The four backends of the command line (README "Command line") behind one call: float, float-ip,
// ref and rtl (the Verilated rpu_top, when this program is built with the co-simulation,
// RPU_SIM=ON).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare_report.h"
#include "model/hw_params.h"
#include "model/ref_renderer.h"
#include "patch/patch_renderer.h"
#include "scene/compiled_scene.h"
#include "tracer/float_tracer.h"

namespace rpu::app {

struct BackendOptions {
  ref::HwParams hw;                 // the model's and the RTL's parameters
  tracer::FloatOptions fl;          // n, n1, threads, binning, grid of the float tracers
  ref::RefOptions ref;              // threads, binning, grid of the model (and the RTL schedule)
  patch::PatchRenderOptions patch;  // float, float-ip: method, map of the patches
                                    // (docs/algorithms.md §4)
  bool systemc = false;             // rtl: the SystemC harness instead of the C++ one
  std::string rtl_exe;              // rtl: a cosim_<name> executable (--rtl-exe)
  int jobs = 0;                     // rtl: instances over contiguous shares (0 = all cores)
  std::optional<std::pair<int, int>> shard;  // rtl: only share I of N (--shard)
  std::string shard_out;                     // rtl: where --shard writes the share's results
  std::vector<std::string> merge_shards;     // rtl: shard files to check and assemble
  bool axi = false;                 // rtl: through the AXI shell rpu_axi (docs/axi.md)
  int fault = 0;                    // rtl: the fault-injected build's fault (checker tests;
                                    // sim::RtlOptions::fault)
  std::optional<std::pair<int, int>> trace_pixel;  // rtl: re-run a pixel with a waveform
  std::string trace_path = "trace.fst";
};

struct BackendResult {
  BackendRender render;
  std::uint64_t pairs = 0, overflows = 0;  // work items processed, of which saturated
  nlohmann::json rtl;                      // rtl only: co-simulation statistics
  std::vector<std::string> reports;        // rtl only: mismatch records
  bool rtl_ok = true;                      // rtl only: equal to the model on every item and pixel
  std::string trace_log;                   // rtl only: what --trace-pixel did
  std::string precision_warning;           // ref, rtl: ref::Precision::warning ("" = none)
  patch::PatchHitMap patch_hits;           // float, float-ip with patches: per-pixel patch hits
  nlohmann::json patch;                    // float, float-ip with patches: method, times, counts
};

inline const std::vector<std::string>& backend_names() {
  static const std::vector<std::string> names = {"float", "float-ip", "ref", "rtl"};
  return names;
}

// The hardware parameters as a JSON object, one key per entry of the parameter table
// ({"n": 16, ..., "metric": "abs", "ip": "unrolled", ...}), for reports (metrics.json "config")
// and sweep results; read back by hw_params_from_json (sweep_spec.h).
nlohmann::json hw_params_json(const ref::HwParams& p);

// True when this program contains the RTL co-simulation.
bool rtl_built();
// The Verilated configurations this program contains, one per line.
std::string rtl_configurations();

// True when the backend can render the scene: ref and rtl have no path for patches, rtl none
// for surfaces (yet).
bool backend_applies(const std::string& backend, const scene::CompiledScene& sc);

// The patch rendering's statistics as JSON (method, map/refine seconds, starts, silhouette
// pixels by reason, ...).
nlohmann::json patch_stats_json(const patch::PatchRenderOptions& o, const patch::PatchRenderStats& s);

// Renders with one backend; throws rpu::Error for an unknown backend or one not built in, and
// for ref and rtl on a scene with patches.
BackendResult run_backend(const std::string& backend, const scene::CompiledScene& sc,
                          const BackendOptions& o);

}  // namespace rpu::app
