// `rpu demo`: renders every built-in scene through every available backend and writes the
// images and an agreement summary (summary.json, summary.md).
#pragma once

#include <string>

#include "model/hw_params.h"
#include "tracer/float_tracer.h"

namespace rpu::app {

struct DemoOptions {
  std::string out_dir = "out/demo";
  tracer::FloatOptions float_options;  // n, n1, threads, binning, grid
  ref::HwParams hw;                    // the model's parameters
  int max_side = 0;  // when > 0, scales each scene's resolution down to at most this side
};

// Returns the process exit status.
int run_demo(const DemoOptions& options);

}  // namespace rpu::app
