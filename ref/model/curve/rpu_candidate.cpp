// Twin of rtl/curve/rpu_candidate.v | sim/tb/curve/tb_rpu_candidate.cpp |
// sim/tests/curve/rpu_candidate.cmake
#include "model/curve/rpu_candidate.h"

#include <algorithm>

#include "model/common/rpu_sqrt.h"

namespace rpu::ref {

using fixed::truncate;

namespace {

// floor((c0·2^n + c1·m) / 2^bits): a linear quantity of the frame at the candidate m.
i128 linear(i128 c0, i128 c1, i128 m, int n, int bits) {
  return truncate((c0 << n) + c1 * m, bits);
}

}  // namespace

Candidate candidate_evaluator(const HwParams& p, const FrameDesc& fd, const PairFrame& f,
                              std::uint64_t m, int k, Overflow& ovf) {
  constexpr int FX = HwParams::kFrameFrac, FG = HwParams::kFrameGuideFrac,
                FW = HwParams::kFrameWFrac, FP = HwParams::kFrameProdFrac,
                FC = HwParams::kFrameCosFrac;
  const int n = p.n;
  const i128 mm = static_cast<i128>(m);
  const i128 one = i128{1} << FP;
  Candidate c;
  c.x = linear(f.x0, f.x1, mm, n, n);
  c.y = linear(f.y0, f.y1, mm, n, n);
  // t, c2·t and s2·t at FP fraction bits; t clamped to [0, 1] for 1 − t, c2·t and s2·t to
  // [−1, 1] (outside [0, 1] of t the guides' offsets are 0 and these values do not matter).
  const int tb = p.t_frac + n - FP;
  c.t = std::clamp<i128>(linear(f.alpha, f.beta, mm, n, tb), 0, one);
  const i128 c2t = std::clamp<i128>(linear(f.c2a, f.c2b, mm, n, tb + FC), -one, one);
  const i128 s2t = std::clamp<i128>(linear(f.s2a, f.s2b, mm, n, tb + FC), -one, one);
  const auto quad = [&](const i128* q) { return q[0] + q[1] * mm + q[2] * mm * mm; };
  c.w = std::max<i128>(0, truncate(quad(f.w), 2 * n));  // FW, ≤ 1/4
  i128 g[2];
  for (int j = 0; j < 2; ++j) {
    const FrameGuide& gd = fd.guide[j];
    switch (gd.mode) {
      case GuideMode::kStraight:
        g[j] = 0;
        break;
      case GuideMode::kArc:  // ĝ = sqrt(η² + w) − η
        g[j] = sqrt_unit(gd.eta2 + (c.w << (2 * FG - FW)), HwParams::frame_radicand_w(),
                         p.sqrt_w, ovf) - gd.eta;
        break;
      case GuideMode::kFlat:  // ĝ = w/(2η)
        g[j] = std::max<i128>(0, truncate(quad(f.a[j]), 2 * n));
        break;
    }
  }
  c.g1 = g[0];
  c.g2 = g[1];
  // The curve's offset in the frame: (ĝ1·(1−t) + ĝ2·c2·t, ĝ2·s2·t), FG.
  const i128 gx = truncate(g[0] * (one - c.t), FP) + truncate(g[1] * c2t, FP);
  const i128 gy = truncate(g[1] * s2t, FP);
  const int fo = p.md_frac(k);  // |o| < 2 (L): fo + 2 signed bits
  c.ox = fixed::saturate(truncate(c.x - (gx << (FX - FG)), FX - fo), fo + 2, ovf);
  c.oy = fixed::saturate(truncate(c.y - (gy << (FX - FG)), FX - fo), fo + 2, ovf);
  const i128 md2 = c.ox * c.ox + c.oy * c.oy;
  const int up = HwParams::kFrameMdFracMax - fo;
  c.md = p.metric == Metric::kAbs ? sqrt_unit(md2, 2 * fo + 3, p.sqrt_w, ovf) << up
                                  : md2 << (2 * up);
  return c;
}

}  // namespace rpu::ref
