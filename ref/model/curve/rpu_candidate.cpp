// Twin of rtl/curve/rpu_candidate.v | sim/tb/curve/tb_rpu_candidate.cpp |
// sim/tests/curve/rpu_candidate.cmake
#include "model/curve/rpu_candidate.h"

#include <algorithm>

#include "model/common/rpu_sqrt.h"

namespace rpu::ref {

using fixed::saturate;
using fixed::truncate;

namespace {

// floor((c0·2^n + c1·m) / 2^bits): a linear quantity of the frame at the candidate m.
i128 linear(i128 c0, i128 c1, i128 m, int n, int bits) {
  return truncate((c0 << n) + c1 * m, bits);
}

}  // namespace

CandidateIn candidate_inputs(const HwParams& p, const PairFrame& f, std::uint64_t m,
                             Overflow& ovf) {
  constexpr int FP = HwParams::kFrameProdFrac, FC = HwParams::kFrameCosFrac;
  const int n = p.n, tb = p.t_frac + n - FP;
  const i128 mm = static_cast<i128>(m);
  const auto quad = [&](const i128* q) { return truncate(q[0] + q[1] * mm + q[2] * mm * mm, 2 * n); };
  CandidateIn in;
  in.x = saturate(linear(f.x0, f.x1, mm, n, n), HwParams::kCandXW, ovf);
  in.y = saturate(linear(f.y0, f.y1, mm, n, n), HwParams::kCandXW, ovf);
  in.t = saturate(linear(f.alpha, f.beta, mm, n, tb), HwParams::kCandTW, ovf);
  in.c2t = saturate(linear(f.c2a, f.c2b, mm, n, tb + FC), HwParams::kCandTW, ovf);
  in.s2t = saturate(linear(f.s2a, f.s2b, mm, n, tb + FC), HwParams::kCandTW, ovf);
  in.w = saturate(quad(f.w), HwParams::kCandWW, ovf);
  for (int k = 0; k < 2; ++k) in.a[k] = saturate(quad(f.a[k]), HwParams::kCandAW, ovf);
  return in;
}

Candidate candidate_unit(const HwParams& p, const FrameDesc& fd, const CandidateIn& in, int fo,
                         Overflow& ovf) {
  constexpr int FX = HwParams::kFrameFrac, FG = HwParams::kFrameGuideFrac,
                FW = HwParams::kFrameWFrac, FP = HwParams::kFrameProdFrac;
  const i128 one = i128{1} << FP;
  Candidate c;
  // t clamped to [0, 1] for 1 − t, c2·t and s2·t to [−1, 1]: outside [0, 1] of t the guides'
  // offsets are 0 (w ≤ 0), so these values do not matter there.
  const i128 t = std::clamp<i128>(in.t, 0, one);
  const i128 c2t = std::clamp<i128>(in.c2t, -one, one);
  const i128 s2t = std::clamp<i128>(in.s2t, -one, one);
  const i128 w = std::max<i128>(0, in.w);  // FW, ≤ 1/4 where t ∈ [0, 1]
  i128 g[2];
  for (int j = 0; j < 2; ++j) {
    const FrameGuide& gd = fd.guide[j];
    switch (gd.mode) {
      default:  // kStraight and the unused mode code 3
        g[j] = 0;
        break;
      case GuideMode::kArc:  // ĝ = sqrt(η² + w) − η
        g[j] = sqrt_unit(gd.eta2 + (std::min<i128>(w, i128{1} << (FW - 2)) << (2 * FG - FW)),
                         HwParams::frame_radicand_w(), p.sqrt_w, ovf) - gd.eta;
        break;
      case GuideMode::kFlat:  // ĝ = w/(2η) ≤ 2^-7, from the pair's polynomial, kept < 1
        g[j] = std::clamp<i128>(in.a[j], 0, (i128{1} << FG) - 1);
        break;
    }
  }
  c.g1 = g[0];
  c.g2 = g[1];
  // The curve's offset in the frame: (ĝ1·(1−t) + ĝ2·c2·t, ĝ2·s2·t), FG.
  const i128 gx = truncate(g[0] * (one - t), FP) + truncate(g[1] * c2t, FP);
  const i128 gy = truncate(g[1] * s2t, FP);
  // |o| < 2 (L): saturated symmetrically to ±(2^(fo+1) − 1), so md2 < 2^(2·fo + 3).
  const i128 lim = (i128{1} << (fo + 1)) - 1;
  const auto offset = [&](i128 v) {
    const i128 o = truncate(v, FX - fo);
    if (o > lim || o < -lim) ovf.flag = true;
    return std::clamp(o, -lim, lim);
  };
  c.ox = offset(in.x - (gx << (FX - FG)));
  c.oy = offset(in.y - (gy << (FX - FG)));
  const i128 md2 = c.ox * c.ox + c.oy * c.oy;
  const int up = HwParams::kFrameMdFracMax - fo;
  c.md = p.metric == Metric::kAbs ? sqrt_unit(md2, 2 * fo + 3, p.sqrt_w, ovf) << up
                                  : md2 << (2 * up);
  return c;
}

}  // namespace rpu::ref
