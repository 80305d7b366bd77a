// Twin of rtl/common/rpu_sqrt.v | sim/tb/common/tb_rpu_sqrt.cpp | sim/tests/common/rpu_sqrt.cmake
// Square root with the parameterised radicand width.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

// floor(sqrt(x)) for a radicand of format width `format_w`. When sqrt_w > 0 and the format is
// wider, the radicand is shifted right by an even 2s first and the root shifted left by s.
// A negative or over-wide radicand saturates and sets the overflow flag.
i128 sqrt_unit(i128 x, int format_w, int sqrt_w, Overflow& ovf);

}  // namespace rpu::ref
