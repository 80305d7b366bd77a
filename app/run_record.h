// What an engineering record of a run states besides its results (issue "the report as an
// engineering record"): the command line, the checkout's git commit, and the versions of the
// tools the co-simulation and the resource figures come from, as found on this machine when the
// report is written.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rpu::app {

// The command line, each argument shell-quoted where it needs it ("rpu compare 'my scene.json'").
std::string command_line(int argc, char** argv);

// {"command", "git_commit", "verilator", "yosys"}: the commit is `git describe --always --dirty`
// of the source checkout this rpu was built from ("unknown" without git or a checkout); a tool
// not on PATH is "not found".
nlohmann::json run_record(const std::string& command);

}  // namespace rpu::app

namespace rpu::app {

// The resources and projected frame rates of a configuration, read from docs/throughput.md of the
// checkout this rpu was built from (its tables hold the default parameters only; the numbers have
// their one home there): for the defaults in the unrolled or iterative form, {"form", "source",
// "lut_sites", "ff", "dsp48e1", "bram36", "sta_ns", "routed_clock"} and, for a built-in scene the
// page projects, "fps_1080p" per part; otherwise {"note": why not}.
nlohmann::json docs_resources(bool defaults, bool unrolled, const std::string& scene_arg);

}  // namespace rpu::app
