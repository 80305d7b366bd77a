// Yosys resources of one RTL module at a sweep configuration's parameters: runs
// scripts/yosys_report.sh (synth_xilinx) through run_child, caches its CSV row under
// DIR/yosys_cache/<module>-<hash of the module's parameters>, and reads the counts back.
#pragma once

#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep_spec.h"

namespace rpu::app {

// The fields of one CSV line (RFC 4180: quoted fields, "" for a quote inside one).
std::vector<std::string> csv_fields(const std::string& line);

class YosysRunner {
 public:
  YosysRunner(const SweepSpec& spec, std::filesystem::path cache_dir);

  // Sets the row's yosys_* fields and lut, ff, dsp, bram, carry4, longest_path_levels (scaled
  // for "scale": "ip_candidates"). Configurations that share the module's parameters share one
  // run: the first synthesises, the others wait for it and read the cache. Throws rpu::Error
  // when the report could not run at all.
  void measure(const SweepConfig& c, nlohmann::json& row);

 private:
  const SweepSpec& spec_;
  std::filesystem::path cache_;
  std::vector<std::string> declared_;  // the module's integer parameters
  std::mutex table_mu_;
  std::map<std::string, std::mutex> key_mu_;  // per cache directory
};

}  // namespace rpu::app
