// Latency of rtl/surface/rpu_surface_ip.v | rtl/surface/rpu_surface_top.v |
// sim/tb/surface/tb_rpu_surface_ip.cpp | sim/tb/surface/tb_rpu_surface_top.cpp (the schedule:
// the headers of those modules; the same formulas in Verilog: rtl/surface/rpu_surface_latency.vh).
#include "model/surface/rpu_surface_latency.h"


#include "model/common/rpu_mul.h"
#include "model/surface/rpu_indicator_latency.h"
#include "model/surface/rpu_surface_setup_latency.h"

namespace rpu::ref {

int surface_ip_pass_latency(const HwParams& p) {
  // lAB' (LW + 1 bits signed) × m (n + 1 bits unsigned, a non-negative n + 2-bit operand).
  const int products = mul_latency(p.surf_w + 1, p.n + 2, true);
  return products + 1 + indicator_latency(p) + 2;
}

int surface_ip_lanes(const HwParams& p, int indicators) {
  return indicators != 0 ? indicators : p.J() - 1;
}

int surface_ip_passes(const HwParams& p, int indicators) {
  const int lanes = surface_ip_lanes(p, indicators);
  int passes = 0;
  for (int k = 1; k <= p.surface_steps(); ++k) {
    const int candidates = (1 << p.surface_step_bits(k)) + (k == 1 ? 1 : -1);
    passes += (candidates + lanes - 1) / lanes;
  }
  return passes;
}

int surface_ip_latency(const HwParams& p, int indicators) {
  return surface_ip_passes(p, indicators) * surface_ip_pass_latency(p) + 1;
}

int surface_ip_interval(const HwParams& p, int indicators) {
  return p.unrolled ? 1 : surface_ip_passes(p, indicators);
}

int surface_top_latency(const HwParams& p, int indicators) {
  const int x_products = mul_latency(p.diff_w(), p.n + 1, true);        // AB'·τ
  const int depth_products = mul_latency(p.diff_w(), p.edge_w(), true);  // (X − h)·W
  return surface_setup_latency(p) + surface_ip_latency(p, indicators) + x_products + 1 + depth_products + 1;
}

}  // namespace rpu::ref
