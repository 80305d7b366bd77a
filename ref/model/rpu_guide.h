// Twin of rtl/rpu_guide.v | sim/tb/tb_rpu_guide.cpp | sim/tests/rpu_guide.cmake
// Guide unit: g_k(t) of the closed form.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

// w = t(1-t) in Q(0.FT) (t clamped to [0, 1] first); returns g in LSB.
i128 guide_weight(const HwParams& p, i128 t);
i128 guide_unit(const HwParams& p, const GuideDesc& g, i128 L2, i128 w, Overflow& ovf);

}  // namespace rpu::ref
