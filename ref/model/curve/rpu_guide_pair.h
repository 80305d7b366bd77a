// Twin of rtl/curve/rpu_guide_pair.v | sim/tb/curve/tb_rpu_guide_pair.cpp |
// sim/tests/curve/rpu_guide_pair.cmake
// Guide unit: both guides' offsets g_1(t), g_2(t) of the closed form at one t.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

// w = t(1-t) in Q(0.FT) (t clamped to [0, 1] first).
i128 guide_weight(const HwParams& p, i128 t);
// One guide's offset g (LSB) from w; the arc's radicand is h² + floor(L2·w / 2^FT).
i128 guide_unit(const HwParams& p, const GuideDesc& g, i128 L2, i128 w, Overflow& ovf);

struct GuidePair {
  i128 g1 = 0, g2 = 0;  // LSB
  i128 w = 0;           // Q(0.FT)
};
// rpu_guide_pair: w once, then both guides (the RTL shares w, floor(L2·w) and takes h² from
// the caller; the values are those of guide_unit).
GuidePair guide_pair(const HwParams& p, const GuideDesc& g1, const GuideDesc& g2, i128 L2, i128 t,
                     Overflow& ovf);
// rpu_guide_pair's latency in cycles at these widths (its header: w, the products, the roots).
int guide_pair_latency(const HwParams& p);

}  // namespace rpu::ref
