// Twin of rtl/curve/rpu_frame.v | sim/tb/curve/tb_rpu_frame.cpp | sim/tests/curve/rpu_frame.cmake
#include "model/curve/rpu_frame.h"

namespace rpu::ref {

using fixed::truncate;

PairFrame frame_unit(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                     Overflow& ovf) {
  PairFrame f;
  const FrameDesc& fd = s.frame;
  const int sh = fd.s - HwParams::kFrameFrac;  // e/L · 2^FX = m · 2^-sh
  const WVec3 a = si.A - widen(s.p1);
  const auto proj = [&](const WVec3& v, const IVec3& e) {
    return fixed::saturate(truncate(dot(v, widen(e)), sh), HwParams::kCandXW, ovf);
  };
  f.x0 = proj(a, fd.e1);
  f.y0 = proj(a, fd.e2);
  f.x1 = proj(si.AB, fd.e1);
  f.y1 = proj(si.AB, fd.e2);
  f.alpha = si.alpha;
  f.beta = si.beta;
  f.c2a = fd.c2 * si.alpha;
  f.c2b = fd.c2 * si.beta;
  f.s2a = fd.s2 * si.alpha;
  f.s2b = fd.s2 * si.beta;
  // t(1−t) = α(1−α) + β(1−2α)·μ − β²·μ² with μ = m/2^n; each coefficient (2·FT fraction bits)
  // floored to FW + 2n − i·n fraction bits per m^i.
  const i128 one = i128{1} << p.t_frac;
  const int fw = HwParams::kFrameWFrac, n = p.n, ft2 = 2 * p.t_frac;
  f.w[0] = truncate(si.alpha * (one - si.alpha), ft2 - fw - 2 * n);
  f.w[1] = truncate(si.beta * (one - 2 * si.alpha), ft2 - fw - n);
  f.w[2] = truncate(-(si.beta * si.beta), ft2 - fw);
  // A flat guide: ĝ = w/(2η) ≤ 2^-7, from W's coefficients floored to FG + 2n − i·n fraction
  // bits (the product stays within 2^(FA + FG + 2n + 1)).
  // (a is 0 unless the guide is flat, so the products are 0 there.)
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i)
      f.a[k][i] = truncate(fd.guide[k].a * truncate(f.w[i], fw - HwParams::kFrameGuideFrac),
                           HwParams::kFrameFlatFrac);
  return f;
}

}  // namespace rpu::ref
