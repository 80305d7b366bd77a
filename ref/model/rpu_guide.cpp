// Twin of rtl/rpu_guide.v | sim/tb/tb_rpu_guide.cpp | sim/tests/rpu_guide.cmake
#include "model/rpu_guide.h"

#include <algorithm>

#include "model/rpu_sqrt.h"

namespace rpu::ref {

using fixed::truncate;

i128 guide_weight(const HwParams& p, i128 t) {
  const i128 one = i128{1} << p.t_frac;
  const i128 tc = std::clamp<i128>(t, 0, one);
  return truncate(tc * (one - tc), p.t_frac);  // Q(0.FT), ≤ 1/4
}

i128 guide_unit(const HwParams& p, const GuideDesc& g, i128 L2, i128 w, Overflow& ovf) {
  switch (g.mode) {
    case GuideMode::kStraight:
      return 0;
    case GuideMode::kArc: {
      // g = sqrt(h² + L²·w) - h: one square root, no division.
      const i128 rad = i128{g.h} * g.h + truncate(L2 * w, p.t_frac);
      return sqrt_unit(rad, p.guide_radicand_w(), p.sqrt_w, ovf) - g.h;
    }
    case GuideMode::kFlat: {
      // h > 16·L: g = h(√(1+x) - 1) = a·w·(1 - b·w) + O(h x³/16) with x = L²w/h² ≤ 1/1024.
      const i128 aw = truncate(i128{g.a} * w, p.t_frac);
      const i128 bw = truncate(i128{g.b} * w, p.t_frac);
      return aw - truncate(aw * bw, p.t_frac);
    }
  }
  return 0;
}

}  // namespace rpu::ref
