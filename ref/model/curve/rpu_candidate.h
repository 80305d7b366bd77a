// Twin of rtl/curve/rpu_candidate.v | sim/tb/curve/tb_rpu_candidate.cpp |
// sim/tests/curve/rpu_candidate.cmake
// Candidate evaluator in the chord's 2-D frame (docs/fixed-point.md, "The candidate in the
// chord's frame").
#pragma once

#include <cstdint>

#include "model/curve/rpu_frame.h"
#include "model/datapath.h"

namespace rpu::ref {

struct Candidate {
  i128 md = 0;    // the distance md of the candidate (|o| or |o|² by the metric), scaled to
                  // kFrameMdFracMax fraction bits of L (of L² when squared)
  // Intermediates (tests and --trace-pixel): the frame point, t, w, the guides' offsets and the
  // offset o = (ox, oy) from the curve at md_frac(k) fraction bits.
  i128 x = 0, y = 0;   // FX
  i128 t = 0;          // FP, clamped to [0, 1]
  i128 w = 0;          // FW
  i128 g1 = 0, g2 = 0; // FG
  i128 ox = 0, oy = 0; // md_frac(k)
};
// m is the candidate's τ index (τ = m · 2^-n, 0 ≤ m ≤ 2^n); k the step that evaluates it (0 for
// the two ends τ = 0 and τ = 1), which sets the offsets' fraction bits md_frac(k).
Candidate candidate_evaluator(const HwParams& p, const FrameDesc& fd, const PairFrame& f,
                              std::uint64_t m, int k, Overflow& ovf);

}  // namespace rpu::ref
