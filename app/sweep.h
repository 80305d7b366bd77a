// `rpu sweep SWEEP.json --out DIR`: a hardware-parameter sweep. Per configuration of the grid:
// mismatched pixels of ref vs float-ip and vs float per scene, RTL cycles and latency from a
// co-simulated sample (configurations with a Verilated build), and Yosys resources of a chosen
// module (cached by the module's parameter hash). Results in results.csv / results.json, plots
// and index.html (sweep_report.h). Runs configurations on all cores, resumes, isolates failures,
// and can emit one command per configuration for other machines (then --merge).
#pragma once

#include <string>

namespace rpu::app {

struct SweepOptions {
  std::string file;        // the sweep description (JSON)
  std::string out_dir;
  int jobs = 0;            // configurations in parallel (0: all cores)
  bool no_rtl = false;     // skip the co-simulation
  bool no_yosys = false;   // skip the resource estimates
  bool emit_jobs = false;  // write jobs.txt (one command per configuration) and merge.sh
  std::string config;      // run only this configuration id (a line of jobs.txt)
  bool merge = false;      // only collect the per-configuration results and write the report
  std::string self;        // this executable (for the emitted commands)
};

// Returns the exit status: 0 when every configuration finished (invalid parameter combinations
// are recorded, not failures), 2 when some failed; bad sweep files, an all-invalid grid, bad
// scenes and out-of-range options throw rpu::Error.
int run_sweep(const SweepOptions& o);

}  // namespace rpu::app
