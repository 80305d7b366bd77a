// Cycle counts of rtl/surface/rpu_surface_ip.v (with rtl/surface/rpu_surface_ip_step.v) and
// rtl/surface/rpu_surface_top.v, whose twins are surface_ip (model/surface/rpu_surface_ip.h) and
// process_surface_piece (model/surface/rpu_surface_top.h): kept apart from the twins' arithmetic,
// as the indicator's and the setup's latencies are (model/surface/rpu_indicator_latency.h,
// model/surface/rpu_surface_setup_latency.h). sim/tb/surface/tb_rpu_surface_ip.cpp and
// sim/tb/surface/tb_rpu_surface_top.cpp check every item against them.
// The RTL runs the model's schedule of the sign search (surf_n1_first, then n1 bits per step) in
// passes of a pass unit with surface_ip_lanes() indicators. `indicators` is the RTL's Indicators
// parameter (0: 2^n1 − 1).
#pragma once

#include "model/hw_params.h"

namespace rpu::ref {

// One pass of rpu_surface_ip_step: the candidate products lAB'·m (rpu_mul), the sum lA' + ⌊·⌋
// (one stage), rpu_indicator, the registered change bits and the one-hot select (two stages).
// 80 at the defaults. The iterative form's ring period.
int surface_ip_pass_latency(const HwParams& p);

// Indicators of one pass unit: `indicators`, or 2^n1 − 1 (so that every step after the first
// takes one pass; 3 at the defaults).
int surface_ip_lanes(const HwParams& p, int indicators = 0);

// Passes of one item: step 1 evaluates its 2^b_1 + 1 candidates, the ends τ = 0 and τ = 1 among
// them, in ⌈(2^b_1 + 1) / lanes⌉ passes, each later step its 2^b_k − 1 new candidates in
// ⌈(2^b_k − 1) / lanes⌉ (b_k = surface_step_bits(k)). 48 at the defaults (43 + 1 + 1 + 1 + 1 + 1),
// K + 1 with the seed's schedule, the evaluations per item (142) with one indicator.
int surface_ip_passes(const HwParams& p, int indicators = 0);

// rpu_surface_ip: the passes and the output register, in both forms: passes·pass + 1 (3,841 at
// the defaults).
int surface_ip_latency(const HwParams& p, int indicators = 0);

// Cycles between accepted items at full load: 1 unrolled; the passes iterative (one pass unit
// used that many times by each item).
int surface_ip_interval(const HwParams& p, int indicators = 0);

// rpu_surface_top: rpu_surface_setup, rpu_surface_ip, then the products AB'·τ (rpu_mul), X and
// X − h (one stage), the products (X − h)·W (rpu_mul) and the depth sum (one stage, registered
// output). 3,953 at the defaults.
int surface_top_latency(const HwParams& p, int indicators = 0);

}  // namespace rpu::ref
