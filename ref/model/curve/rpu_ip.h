// Twin of rtl/curve/rpu_ip.v | sim/tb/curve/tb_rpu_ip.cpp | sim/tests/curve/rpu_ip.cmake
// The K-step process, unrolled or iterative.
#pragma once

#include "model/curve/rpu_ip_step.h"
#include "model/curve/rpu_frame.h"
#include "model/datapath.h"

namespace rpu::ref {

// The K-step process in both hardware forms: unrolled (stage k is its own unit with its shift
// n - n1·k wired in) or iterative (one step unit, a step counter selects the shift). They are
// the same arithmetic; `ip_process` picks by p.unrolled, and tests prove the forms equal.
IpState ip_process_unrolled(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                            Overflow& ovf);
IpState ip_process_iterative(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                             Overflow& ovf);
inline IpState ip_process(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                          Overflow& ovf) {
  return p.unrolled ? ip_process_unrolled(p, s, f, ovf) : ip_process_iterative(p, s, f, ovf);
}

}  // namespace rpu::ref
