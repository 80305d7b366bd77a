// Twin of rtl/curve/rpu_test_point.v | sim/tb/curve/tb_rpu_ip.cpp | sim/tests/curve/rpu_ip.cmake
#include "model/curve/rpu_test_point.h"

#include "model/curve/rpu_curve_point.h"
#include "model/curve/rpu_guide_pair.h"

namespace rpu::ref {

TestPoint test_point_unit(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                          std::uint64_t tau, Overflow& ovf) {
  TestPoint r;
  r.t = fixed::saturate(si.alpha + fixed::truncate(si.beta * static_cast<i128>(tau), p.n),
                        p.t_w(), ovf);
  const GuidePair g = guide_pair(p, s.guide[0], s.guide[1], s.L2, r.t, ovf);
  r.X = curve_point_unit(p, s, r.t, g.g1, g.g2);
  return r;
}

}  // namespace rpu::ref
