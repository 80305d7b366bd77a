// Cycle counts of rtl/surface/rpu_surface_ip.v (with rtl/surface/rpu_surface_ip_step.v) and
// rtl/surface/rpu_surface_top.v, whose twins are surface_ip (model/surface/rpu_surface_ip.h) and
// process_surface_piece (model/surface/rpu_surface_top.h): kept apart from the twins' arithmetic,
// as the indicator's and the setup's latencies are (model/surface/rpu_indicator_latency.h,
// model/surface/rpu_surface_setup_latency.h). sim/tb/surface/tb_rpu_surface_ip.cpp and
// sim/tb/surface/tb_rpu_surface_top.cpp check every item against them.
// The RTL implements the seed's schedule of the sign search (surf_n1_first = seed: K steps of n1
// bits), and these counts are that schedule's.
#pragma once

#include "model/hw_params.h"

namespace rpu::ref {

// One pass of rpu_surface_ip_step: the candidate products lAB'·m (rpu_mul), the sum lA' + ⌊·⌋
// (one stage), rpu_indicator, the registered change bits and the one-hot select (two stages).
// 80 at the defaults. The iterative form's ring period.
int surface_ip_pass_latency(const HwParams& p);

// rpu_surface_ip: K + 1 passes (pass 0 evaluates the ends τ = 0 and τ = 1, passes 1..K the
// steps) and the output register, in both forms: (K + 1)·pass + 1 (721 at the defaults).
int surface_ip_latency(const HwParams& p);

// Cycles between accepted items at full load: 1 unrolled; K + 1 iterative (one pass unit used
// K + 1 times by each item).
int surface_ip_interval(const HwParams& p);

// rpu_surface_top: rpu_surface_setup, rpu_surface_ip, then the products AB'·τ (rpu_mul), X and
// X − h (one stage), the products (X − h)·W (rpu_mul) and the depth sum (one stage, registered
// output). 833 at the defaults.
int surface_top_latency(const HwParams& p);

}  // namespace rpu::ref
