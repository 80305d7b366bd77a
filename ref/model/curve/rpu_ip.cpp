// Twin of rtl/curve/rpu_ip.v | sim/tb/curve/tb_rpu_ip.cpp | sim/tests/curve/rpu_ip.cmake
#include "model/curve/rpu_ip.h"

namespace rpu::ref {

IpState ip_process_unrolled(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                            Overflow& ovf) {
  // Stage 0 evaluates the two ends; stages 1..K each own one step (state.k enters as k - 1).
  IpState st = ip_start(p, s, f, ovf);
  for (int stage = 1; stage <= p.K(); ++stage) {
    st.k = stage - 1;
    ip_step_in_place(p, s, f, st, ovf, nullptr);
  }
  return st;
}

IpState ip_process_iterative(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                             Overflow& ovf) {
  // One step unit; its counter (state.k) advances each pass until K passes are done.
  IpState st = ip_start(p, s, f, ovf);
  while (st.k < p.K()) ip_step_in_place(p, s, f, st, ovf, nullptr);
  return st;
}

}  // namespace rpu::ref
