// Twin of rtl/curve/rpu_candidate.v | sim/tb/curve/tb_rpu_candidate.cpp |
// sim/tests/curve/rpu_candidate.cmake
// Candidate evaluator.
#pragma once

#include "model/curve/rpu_sphere.h"
#include "model/datapath.h"

namespace rpu::ref {

struct Candidate {
  i128 t = 0;     // chord parameter, Q(3.FT)
  WVec3 X;        // curve point s(t), LSB
  WVec3 pr;       // ray point pr(τ), LSB
  i128 md = 0;    // |pr - X| (LSB) or |pr - X|² (LSB²) by the metric
};
// m is the candidate's τ index: τ = m · 2^-n, 0 ≤ m ≤ 2^n.
Candidate candidate_evaluator(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                              std::uint64_t m, Overflow& ovf);

}  // namespace rpu::ref
