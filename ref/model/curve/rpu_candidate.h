// Twin of rtl/curve/rpu_candidate.v | sim/tb/curve/tb_rpu_candidate.cpp |
// sim/tests/curve/rpu_candidate.cmake
// Candidate evaluator in the chord's 2-D frame (docs/fixed-point.md, "The candidate in the
// chord's frame").
#pragma once

#include <cstdint>

#include "model/curve/rpu_frame.h"
#include "model/datapath.h"

namespace rpu::ref {

// A candidate's polynomial values: the pair's frame (PairFrame) at its index m, floored to the
// candidate's formats and saturated to its port widths (HwParams::kCand*W). The step unit forms
// them by forward differences (rpu_ip_step).
struct CandidateIn {
  i128 x = 0, y = 0;       // FX, kCandXW signed bits
  i128 t = 0;              // FP, kCandTW (t is clamped to [0, 1] inside the candidate)
  i128 c2t = 0, s2t = 0;   // c2·t, s2·t, FP, kCandTW (clamped to [−1, 1] inside)
  i128 w = 0;              // W(m) at FW, kCandWW (max(0, ·) inside)
  i128 a[2] = {0, 0};      // flat guides' A_k(m) at FG, kCandAW (max(0, ·) inside)
  bool operator==(const CandidateIn&) const = default;
};
CandidateIn candidate_inputs(const HwParams& p, const PairFrame& f, std::uint64_t m,
                             Overflow& ovf);

struct Candidate {
  i128 md = 0;    // the distance md of the candidate (|o| or |o|² by the metric), scaled to
                  // kFrameMdFracMax fraction bits of L (of L² when squared)
  // Intermediates (tests and --trace-pixel): the guides' offsets (FG) and the offset
  // o = (ox, oy) from the curve at md_frac(k) fraction bits.
  i128 g1 = 0, g2 = 0;
  i128 ox = 0, oy = 0;
};
// fo: the offsets' fraction bits (rpu_candidate's Fo), md_frac(k) in step k (k = 0: the two
// ends τ = 0 and τ = 1).
Candidate candidate_unit(const HwParams& p, const FrameDesc& fd, const CandidateIn& in, int fo,
                         Overflow& ovf);
// Both: the candidate m (τ = m · 2^-n, 0 ≤ m ≤ 2^n) of step k.
inline Candidate candidate_evaluator(const HwParams& p, const FrameDesc& fd, const PairFrame& f,
                                     std::uint64_t m, int k, Overflow& ovf) {
  return candidate_unit(p, fd, candidate_inputs(p, f, m, ovf), p.md_frac(k), ovf);
}

}  // namespace rpu::ref
