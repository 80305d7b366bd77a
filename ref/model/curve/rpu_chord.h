// Twin of rtl/curve/rpu_chord.v | sim/tb/curve/tb_rpu_chord.cpp | sim/tests/curve/rpu_sphere.cmake
// Chord parameter t of a point (used by rtl/curve/rpu_sphere and rtl/texture/rpu_texture).
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

// t = floor(dot · inv_m · 2^-(inv_s - FT)), saturated to Q(3.FT), for dot = (x - p1)·d (LSB²);
// inv_s < FT (segments with L² < 2^(FT-IW+3)) makes it an exact left shift.
i128 chord_parameter(const HwParams& p, const SegmentDesc& s, i128 dot, Overflow& ovf);
// rpu_chord's latency in cycles at these widths (its header: the product dot · inv_m with a dot of
// 2·diff_w + 2 bits, as rpu_sphere and rpu_texture feed it, then three stages).
int chord_latency(const HwParams& p);

}  // namespace rpu::ref
