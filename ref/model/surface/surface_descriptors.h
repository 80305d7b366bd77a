// Quantisation of the vector-described surfaces (docs/algorithms.md §3) into SurfaceDesc
// (descriptors.h), and the product with a block-floating-point constant the surface twins share.
// Formats: docs/fixed-point.md, "Surfaces".
#pragma once

#include <string>

#include "model/descriptors.h"

namespace rpu::ref {

// Quantises one compiled surface (quantize_scene calls it for every surface, in order). Throws
// rpu::Error naming `where` (e.g. "scene.json: surfaces[1]") when a constant cannot be held.
SurfaceDesc quantize_surface(const scene::CompiledSurface& s, const Normalization& norm,
                             const HwParams& p, const std::string& where);

// The block-floating-point form of v with a `mant_w`-bit mantissa (0 → {0, 0}).
ScaledConst scaled_const(double v, int mant_w);

// x · c keeping `keep` fraction bits below x's LSB: floor(x · c.m · 2^-(c.s - keep)), exact
// product then one floor (a left shift when c.s < keep).
inline i128 const_product(i128 x, const ScaledConst& c, int keep) {
  return fixed::truncate(x * c.m, c.s - keep);
}

// One full turn of an `aw`-bit binary angle (2^aw).
inline std::uint64_t full_turn(int aw) { return std::uint64_t{1} << aw; }

}  // namespace rpu::ref
