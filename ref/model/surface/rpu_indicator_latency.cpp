// Twin of the schedule of rtl/surface/rpu_indicator.v (its localparams LF, LT, LB, ...).
#include "model/surface/rpu_indicator_latency.h"

#include <algorithm>

#include "model/common/rpu_cordic.h"
#include "model/common/rpu_mul.h"
#include "model/surface/rpu_indicator.h"

namespace rpu::ref {

int indicator_latency(const HwParams& p) {
  const int lw = p.surf_w, aw = p.angle_w, kf = p.surf_const_frac(), mw = p.surf_mant_w();
  const int corw = p.surf_cordic_w(), turn_w = lw + 8;  // a_turn, k_turn: LW + 8 bits
  const int xsw = lw + 3;                             // x·sx ≫ (KF − G)
  const int hiw = turn_w + 7;                         // |P_j| of the snail
  const int kpw = corw + 2, k2w = 2 * kpw - 2 - kf, d2w = 2 * lw + 1;  // relief k', k2, s²m²
  const CordicConfig cc = surface_cordic(p);
  // Front: x·sx (and y·sy, z·sz) beside the constant product y·m, padded to the slower.
  const int lf = std::max(mul_latency(lw, kf + 2, true), mul_latency(lw + 1, mw, true));
  const int lt = mul_latency(aw + 2, turn_w, true);  // ψ_u·a_turn
  // Back end, in cycles after the rotations, to each type's registered bit.
  const int lsc = mul_latency(corw, kf + 2, true), lq = mul_latency(lw + 1, lw + 1, true);
  const int lxy = std::max(mul_latency(xsw, xsw, true), 1 + lq);
  const int lk = mul_latency(kpw, kpw, true), lkd = mul_latency(k2w, d2w, false);
  const int ln = mul_latency(lw, hiw, false);
  const int tkd = std::max(1 + lk, lxy + 1);
  const int last = std::max({lsc + lq + 3,  // spiral
                             lxy + 2,       // ellipsoid
                             ln + 5,        // snail
                             2,             // rocket
                             tkd + lkd});   // relief (its compare is the output stage)
  return 1 + lf + cordic_latency(cc, true) + lt + 3 + cordic_latency(cc, false) + last + 1;
}

}  // namespace rpu::ref
