// fuzz_sweep (issue 14, item 3): bytes → sweep file text → the sweep-file parser
// (app/sweep_spec: parse_sweep_text, as parse_sweep_file after reading) → the grid's
// configurations (expand_grid), each validated as `rpu sweep` does (HwParams::validate) and its
// parameters written as the co-simulation build names them (verilog_value). Scenes are named,
// never read.
//
// A bad sweep file must be refused with one rpu::Error: one line, naming the file. Any other
// exception, a crash, a hang, undefined behaviour or a leak is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/error.h"
#include "sweep_spec.h"

namespace {

constexpr const char* kSource = "fuzz_sweep.json";

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_sweep: %s\n", what.c_str());
  std::abort();
}

void check_message(const rpu::Error& e) {
  const std::string what = e.what();
  if (what.empty() || what.find('\n') != std::string::npos || e.problem().empty())
    finding("malformed error message: [" + what + "]");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rpu::app::SweepSpec spec;
  try {
    spec = rpu::app::parse_sweep_text(text, kSource);
  } catch (const rpu::Error& e) {
    check_message(e);
    if (std::string(e.what()).find(kSource) == std::string::npos)
      finding(std::string("error does not name the file: ") + e.what());
    return 0;
  }
  if (spec.scenes.empty() || spec.grid.empty()) finding("accepted a sweep without scenes or grid");
  const std::vector<rpu::app::SweepConfig> configs = rpu::app::expand_grid(spec);
  if (configs.empty()) finding("a grid without configurations");
  for (const rpu::app::SweepConfig& c : configs) {
    try {
      c.params.validate();  // `rpu sweep` records a refused configuration as failed
    } catch (const rpu::Error& e) {
      check_message(e);
    }
    for (const rpu::ref::HwParamInfo& d : rpu::ref::hw_param_table())
      (void)rpu::app::verilog_value(d, c.params);
  }
  return 0;
}
