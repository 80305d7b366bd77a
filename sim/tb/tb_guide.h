// A guide on one port of the unit under test (the curve and texture testbenches): driven packed
// as the RTL lays it out (guide_word.h), listed field by field in a mismatch report.
#pragma once

#include <fmt/format.h>

#include "guide_word.h"
#include "tb_base.h"

namespace rpu::sim {

inline std::string guide_text(int mode, i128 h, i128 a, i128 b) {
  return fmt::format("mode {} h {} a {} b {}", mode, static_cast<long long>(h),
                     static_cast<long long>(a), static_cast<long long>(b));
}

// The descriptor {mode, h, a, b, u} (rtl/curve/rpu_guide_desc.vh).
template <class P>
void guide_input(Inputs& in, const char* name, P& port, const ref::HwParams& p,
                 const ref::GuideDesc& g) {
  if (in.mode() == Inputs::kList) {
    in.note(name, guide_text(static_cast<int>(g.mode), g.h, g.a, g.b) +
                      fmt::format(" u ({}, {}, {})", static_cast<long long>(g.u.x),
                                  static_cast<long long>(g.u.y), static_cast<long long>(g.u.z)));
    return;
  }
  in.bits(name, port, pack_guide(p, g));
}

// The shape {mode, h, a, b} alone (rtl/curve/rpu_guide_shape.vh: rpu_guide_pair).
template <class P>
void guide_shape_input(Inputs& in, const char* name, P& port, const ref::HwParams& p, int mode,
                       i128 h, i128 a, i128 b) {
  if (in.mode() == Inputs::kList) {
    in.note(name, guide_text(mode, h, a, b));
    return;
  }
  in.bits(name, port, pack_guide_shape(p, mode, h, a, b));
}

}  // namespace rpu::sim
