// The on-demand co-simulation build of `rpu sweep` ("rtl": {"build": true}): the configurations
// the rpu executable has no Verilated rpu_top for are Verilated by a CMake build of this checkout
// with RPU_COSIM_ONLY under DIR/rtl_build, one cosim_<name> executable each, kept across runs.
// CMake and Ninja run through run_child (argument vectors, their own process group).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "model/hw_params.h"
#include "sweep_spec.h"

namespace rpu::app {

// Whether the rpu executable contains a Verilated rpu_top with exactly these parameters.
bool has_builtin_rtl(const ref::HwParams& p);

// Builds what `todo` needs (valid configurations without a built-in model) with `jobs` compile
// jobs; returns configuration id → executable for every one that exists afterwards. A failed
// build is reported on stderr (see DIR/rtl_build/build.log); its rows then say so.
std::map<std::string, std::string> build_cosim(const std::vector<const SweepConfig*>& todo,
                                               const std::filesystem::path& out_dir, int jobs);

}  // namespace rpu::app
