// Twin of rtl/curve/rpu_curve_point.v | sim/tb/curve/tb_rpu_curve_point.cpp |
// sim/tests/curve/rpu_curve_point.cmake
// Curve point s(t) from the two guides.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

WVec3 curve_point_unit(const HwParams& p, const SegmentDesc& s, i128 t, i128 g1, i128 g2);
// rpu_curve_point's latency in cycles at these widths (its header).
int curve_point_latency(const HwParams& p);

}  // namespace rpu::ref
