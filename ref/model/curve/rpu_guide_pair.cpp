// Twin of rtl/curve/rpu_guide_pair.v | sim/tb/curve/tb_rpu_guide_pair.cpp |
// sim/tests/curve/rpu_guide_pair.cmake
#include "model/curve/rpu_guide_pair.h"

#include <algorithm>

#include "model/common/rpu_mul.h"
#include "model/common/rpu_sqrt.h"

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

int guide_pair_latency(const HwParams& p) {
  const int ft = p.t_frac, ww = ft - 1, aw = p.coord_w, aww = aw + ww - ft;
  const int l2w = 2 * p.coord_w + 3, radw = p.guide_radicand_w();
  const int shift = (p.sqrt_w == 0 || radw <= p.sqrt_w) ? 0 : (radw - p.sqrt_w + 1) / 2;
  const int lat_w = mul_latency(ft, ft, false);
  const int lat_awbw = std::max(mul_latency(aw, ww, false), mul_latency(ft, ww, false));
  const int lat_prod = std::max(lat_awbw + mul_latency(aww, ww, false), mul_latency(l2w, ww, false)) + 1;
  return lat_w + lat_prod + (radw - 2 * shift + 1) / 2 + 1;
}

GuidePair guide_pair(const HwParams& p, const GuideDesc& g1, const GuideDesc& g2, i128 L2, i128 t,
                     Overflow& ovf) {
  GuidePair r;
  r.w = guide_weight(p, t);
  r.g1 = guide_unit(p, g1, L2, r.w, ovf);
  r.g2 = guide_unit(p, g2, L2, r.w, ovf);
  return r;
}

}  // namespace rpu::ref
