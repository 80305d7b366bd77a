// Twin of rtl/common/rpu_cordic.v | sim/tb/common/tb_rpu_cordic.cpp |
// sim/tests/common/rpu_cordic.cmake
// CORDIC in vectoring mode (magnitude and atan2) and rotation mode (rotate a vector by a binary
// angle), gain-compensated, integers only. Formats and the derived error bounds are in
// docs/fixed-point.md ("CORDIC").
//
// Bit-exact with the RTL for every input the ports can carry: x and y are taken modulo 2^w as
// w-bit two's complement, the angle modulo 2^aw, and every internal register wraps as the
// hardware's does. Only inputs with |x|, |y| ≤ 2^(w−2) (cordic_in_range) give meaningful
// results; outside that range the result is the hardware's wrapped value.
#pragma once

#include <cstdint>
#include <vector>

#include "model/datapath.h"

namespace rpu::ref {

// Angles are binary angles: an unsigned `aw`-bit fraction of a full turn (2^aw = 2π), wrapping.
struct CordicConfig {
  int w = 32;      // signed width of the input and output coordinates; inputs must satisfy
                   // |x|, |y| ≤ 2^(w−2) (one bit of headroom for the magnitude)
  int aw = 24;     // angle width
  int iters = 24;  // micro-rotation stages
  bool operator==(const CordicConfig&) const = default;
};

struct CordicPolar {
  i64 mag = 0;               // ≈ √(x² + y²), gain-compensated
  std::uint64_t angle = 0;   // ≈ atan2(y, x), in [0, 2^aw)
};
struct CordicXY {
  i64 x = 0, y = 0;
};

// Vectoring: (x, y) → (|(x, y)|, atan2(y, x)). atan2(0, 0) is defined (docs).
CordicPolar cordic_vectoring(const CordicConfig& c, i64 x, i64 y);
// Rotation: (x, y) rotated counter-clockwise by angle/2^aw turns:
// (x cos θ − y sin θ, x sin θ + y cos θ).
CordicXY cordic_rotation(const CordicConfig& c, i64 x, i64 y, std::uint64_t angle);
// Cycles from input to output of rtl/common/rpu_cordic.v in each mode.
int cordic_latency(const CordicConfig& c, bool vectoring);
// Throws rpu::Error when a configuration is outside what the unit supports.
void cordic_validate(const CordicConfig& c);

// ---- formats and constants (docs/fixed-point.md, "CORDIC"), as in rtl/common/rpu_cordic.v ----

// Legal ranges: w in [6, 48], aw in [4, 48], iters in [4, min(48, w + 4)].
// Guard bits below the input LSB of the internal x, y registers: G = ceil(log2 iters) + 2.
int cordic_guard_bits(const CordicConfig& c);
// Guard bits below the angle LSB of the internal angle register: GA = ceil(log2 iters) + 2.
int cordic_angle_guard_bits(const CordicConfig& c);
// Fraction bits of the inverse gain constant: KF = w + 2.
int cordic_gain_frac_bits(const CordicConfig& c);
// True when |x|, |y| ≤ 2^(w−2): the inputs whose results the error bounds cover.
bool cordic_in_range(const CordicConfig& c, i64 x, i64 y);

// The unit's constants, computed with integers only, exactly as rtl/common/rpu_cordic.v computes
// them at elaboration:
//   atan[i]  = atan(2^−i) in units of 2^−(aw+GA) turn, rounded to nearest (i = 0: exactly 1/8
//              turn), from the Taylor series of atan and Machin's formula for π at 70 fraction
//              bits: within 1/2 + 2^−12 of the exact value;
//   gain_inv = 2^KF / K, K = Π_{i<iters} √(1 + 2^−2i) (the CORDIC gain), rounded to nearest,
//              from the product at 62 fraction bits and an integer square root: within
//              1/2 + 2^−7 of the exact value.
struct CordicTables {
  std::vector<std::uint64_t> atan;
  std::uint64_t gain_inv = 0;
};
CordicTables cordic_tables(const CordicConfig& c);

}  // namespace rpu::ref
