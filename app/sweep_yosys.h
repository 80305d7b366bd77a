// Yosys resources of one RTL module (rpu_top by default) at a sweep configuration's parameters:
// runs the cached hierarchical synthesis flow scripts/synth_hier.py (docs/resources.md) through
// run_child with its cache in DIR/yosys_cache, so configurations share every derived module
// whose parameters agree, and so do resumed runs and the jobs of an emitted job array; its
// report and log per parameter set: DIR/yosys_cache/runs/<module>-<hash>.{json,log}.
#pragma once

#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep_spec.h"

namespace rpu::app {

class YosysRunner {
 public:
  // jobs: Yosys processes at once for each configuration (the cores over the configurations
  // the sweep runs in parallel).
  YosysRunner(const SweepSpec& spec, std::filesystem::path cache_dir, int jobs);

  // Sets the row's yosys_* fields and the whole module's lut_sites, lut (LUT1–6 and INV), srl,
  // lutram, ff, dsp, bram (BRAM36), carry4 and sta_ns (the slowest derived module's own logic).
  // A derived module that fails or times out: yosys_status "failed" / "timeout", yosys_error
  // naming it, no resource figures. Throws rpu::Error when the flow could not run at all (a
  // bad parameter, an elaboration error).
  void measure(const SweepConfig& c, nlohmann::json& row);

 private:
  const SweepSpec& spec_;
  std::filesystem::path cache_;
  int jobs_;
  std::vector<std::string> declared_;  // the module's integer parameters
  std::mutex table_mu_;
  std::map<std::string, std::mutex> key_mu_;  // per cache directory
};

}  // namespace rpu::app
