// The VerilatedContext of one Verilated model of the co-simulation (verilated_ports.h,
// axi_ports.h): with x_seed != 0 every initial register value is random from that seed (the
// models are built --x-initial unique), so a design that depends on one is caught.
#pragma once

#include <cstdint>
#include <memory>

#include <verilated.h>

namespace rpu::sim {

inline std::unique_ptr<VerilatedContext> make_context(std::uint64_t x_seed) {
  auto ctx = std::make_unique<VerilatedContext>();
  if (x_seed != 0) {
    ctx->randReset(2);
    ctx->randSeed(static_cast<int>(x_seed));
  }
  return ctx;
}

}  // namespace rpu::sim
