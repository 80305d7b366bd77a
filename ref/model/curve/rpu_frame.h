// Twin of rtl/curve/rpu_frame.v | sim/tb/curve/tb_rpu_frame.cpp | sim/tests/curve/rpu_frame.cmake
// Frame unit: once per (ray, segment) pair, the coefficients in the candidate index m of
// everything the candidates evaluate in the chord's 2-D frame (docs/fixed-point.md, "The
// candidate in the chord's frame"). Every quantity is a polynomial in m of degree ≤ 2 with
// integer coefficients, so the unrolled RTL steps it by forward differences and the model
// evaluates it directly: the two are the same integers.
#pragma once

#include "model/curve/rpu_sphere.h"
#include "model/datapath.h"

namespace rpu::ref {

struct PairFrame {
  // x(m) = floor((x0·2^n + x1·m) / 2^n), y likewise: (pr(τ) − p1)·e/L at FX fraction bits.
  i128 x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  // t(m) = α + β·m/2^n, Q(3.FT) (the sphere unit's α, β).
  i128 alpha = 0, beta = 0;
  // c2·t(m) = (c2a·2^n + c2b·m) / 2^n at FC + FT fraction bits; s2·t likewise.
  i128 c2a = 0, c2b = 0, s2a = 0, s2b = 0;
  // W(m) = w0 + w1·m + w2·m² ≈ t(1−t)·2^(FW+2n).
  i128 w[3] = {0, 0, 0};
  // A flat guide k: A_k(m) = a_k·W(m) coefficient by coefficient, ≈ ĝ_k·2^(FG+2n).
  i128 a[2][3] = {{0, 0, 0}, {0, 0, 0}};
};
// x0, x1, y0, y1 saturate to kCandXW bits (|·| < 4; ovf): only a saturated A or B (the sphere
// unit's ovf) reaches that. The other coefficients are exact (docs/fixed-point.md gives widths).
PairFrame frame_unit(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                     Overflow& ovf);

}  // namespace rpu::ref
