// Twin of rtl/curve/rpu_candidate.v | sim/tb/curve/tb_rpu_candidate.cpp |
// sim/tests/curve/rpu_candidate.cmake
#include "model/curve/rpu_candidate.h"

#include "model/common/rpu_sqrt.h"
#include "model/curve/rpu_curve_point.h"
#include "model/curve/rpu_guide_pair.h"

namespace rpu::ref {

using fixed::truncate;

Candidate candidate_evaluator(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                              std::uint64_t m, Overflow& ovf) {
  Candidate c;
  const i128 mm = static_cast<i128>(m);
  c.pr = si.A + scale_truncate(si.AB, mm, p.n);                            // pr(τ), LSB
  c.t = fixed::saturate(si.alpha + truncate(si.beta * mm, p.n), p.t_w(), ovf);  // t(τ), Q(3.FT)
  const GuidePair g = guide_pair(p, s.guide[0], s.guide[1], s.L2, c.t, ovf);
  c.X = curve_point_unit(p, s, c.t, g.g1, g.g2);
  const WVec3 diff = c.pr - c.X;
  const i128 md2 = dot(diff, diff);
  c.md = p.metric == Metric::kAbs ? sqrt_unit(md2, p.dist_radicand_w(), p.sqrt_w, ovf)
                                  : fixed::saturate_unsigned(md2, p.dist_radicand_w(), ovf);
  return c;
}

}  // namespace rpu::ref
