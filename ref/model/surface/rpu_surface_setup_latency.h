// Latency of rtl/surface/rpu_surface_setup.v (sim/tb/surface/tb_rpu_surface_setup.cpp checks it):
// the twin ref/model/surface/rpu_surface_setup.{h,cpp} computes values only; the cycle count of the
// RTL pipeline lives here, beside it.
#pragma once

#include "model/hw_params.h"

namespace rpu::ref {

// rpu_surface_setup's latency in cycles at these widths (its header): the sphere unit, the local
// transform (one rpu_mul group and four single stages), the end-plane products (one rpu_mul
// group and three single stages), the two dividers (SF + 1 stages), two piece stages, the piece
// products (one rpu_mul group) and two output stages. 105 at the defaults.
int surface_setup_latency(const HwParams& p);

}  // namespace rpu::ref
