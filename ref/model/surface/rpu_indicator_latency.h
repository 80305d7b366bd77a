// The cycle count of rtl/surface/rpu_indicator.v (twin: indicator_unit, rpu_indicator.h here):
// kept in a file of its own so the RTL's schedule and the twin's arithmetic can change apart.
#pragma once

#include "model/hw_params.h"

namespace rpu::ref {

// Cycles from a point at rpu_indicator's inputs to its result, the same for every surface
// type: the input register, the front products, the vectoring CORDIC, ψ·a_turn, three stages to
// the rotation inputs, the rotation CORDICs and the back end of the slowest type (the relief's
// k'² and k'²·s²m² at the defaults), padded for the others, and the output register.
int indicator_latency(const HwParams& p);

}  // namespace rpu::ref
