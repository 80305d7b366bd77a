// Twin of rtl/curve/rpu_ip_step.v | sim/tb/curve/tb_rpu_ip.cpp (-DIP_STEP=1) |
// sim/tests/curve/rpu_ip.cmake
// IP step: 2^n1 - 1 new candidates, pair sums, lowest-index argmin.
#pragma once

#include <array>
#include <cstdint>

#include "model/curve/rpu_candidate.h"
#include "model/curve/rpu_frame.h"
#include "model/datapath.h"

namespace rpu::ref {

struct IpState {
  std::uint64_t tau = 0;  // τ index of the selected interval's start, n bits
  Candidate lo, hi;       // the selected interval's end candidates
  int k = 0;              // steps done
};
struct IpStepTrace {
  std::array<i128, 257> md{};  // md_j, j = 0..J
  std::array<i128, 256> sd{};  // sd_j = md_j + md_{j+1}
  int eta = 0;
};
// The frame's polynomials at a step's interval start m0 at full precision: what rpu_ip_step
// carries from step to step to evaluate its candidates by forward differences
// (docs/fixed-point.md, "The candidate in the chord's frame"). The step's integers are these at
// m0 + j·2^(n − n1·k), exactly (candidate_inputs floors and saturates them).
struct FrameState {
  i128 X = 0, Y = 0;     // x0·2^n + x1·m0, y likewise
  i128 T = 0;            // α·2^n + β·m0
  i128 C2 = 0, S2 = 0;   // c2a·2^n + c2b·m0, s2a·2^n + s2b·m0
  i128 W = 0, SW = 0;    // W(m0) and its slope w1 + 2·w2·m0
  i128 A[2] = {0, 0}, SA[2] = {0, 0};  // the flat guides' A_k(m0) and slopes
  bool operator==(const FrameState&) const = default;
};
FrameState frame_state(const HwParams& p, const PairFrame& f, std::uint64_t m0);

// The initial state (step 0): candidates τ = 0 and τ = 1 evaluated.
IpState ip_start(const HwParams& p, const SegmentDesc& s, const PairFrame& f, Overflow& ovf);
// Step k = state.k + 1: J - 1 new candidates, pair sums, lowest-index argmin.
IpState ip_step(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                const IpState& state, Overflow& ovf, IpStepTrace* trace = nullptr);
// The same step updating `state` in place (the model's hot loop).
void ip_step_in_place(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                      IpState& state, Overflow& ovf, IpStepTrace* trace = nullptr);
// Lowest-index argmin of the pair sums (in rtl/curve/rpu_ip_step): strict < keeps the first
// minimum.
int argmin_lowest(const i128* sd, int count);

}  // namespace rpu::ref
