// One Verilated model of the co-simulation (verilated_ports.h: rpu_top; axi_ports.h: rpu_axi):
// its VerilatedContext, the model, and its coverage file. With x_seed != 0 every initial
// register value is random from that seed (the models are built --x-initial unique), so a
// design that depends on one is caught. In a coverage build each model writes its own counts
// (coverage_file.h: after the first reset, mark(), and at finish()).
#pragma once

#include <cstdint>
#include <memory>

#include <verilated.h>

#include "coverage_file.h"

namespace rpu::sim {

template <class V>
struct VerilatedModel {
  explicit VerilatedModel(std::uint64_t x_seed) : ctx(std::make_unique<VerilatedContext>()) {
    if (x_seed != 0) {
      ctx->randReset(2);
      ctx->randSeed(static_cast<int>(x_seed));
    }
    top = std::make_unique<V>(ctx.get());
    coverage.set_name(CoverageFile::program() + "-" + top->modelName());
  }
  // The final blocks and the coverage counts, once; false when already finished.
  bool finish() {
    if (finished) return false;
    finished = true;
    top->final();
    coverage.write(*ctx);
    return true;
  }
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<V> top;
  CoverageFile coverage;
  bool finished = false;
};

}  // namespace rpu::sim
