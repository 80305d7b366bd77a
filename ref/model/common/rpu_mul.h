// Twin of rtl/common/rpu_mul.v | sim/tb/common/tb_rpu_mul.cpp | sim/tests/common/rpu_mul.cmake
// Pipelined multiplier: the exact product. The RTL splits it into DSP-sized tiles and an adder
// tree; its value is a · b for every operand the ports carry (the twins of the units that use it
// keep writing a plain `*`).
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

inline i128 mul_unit(i128 a, i128 b) { return a * b; }

// Its latency in cycles (rtl/common/rpu_mul_latency.vh): 2 + ceil(log2(tiles)), tiles of chunk_a ×
// chunk_b unsigned bits (a signed operand's sign bit rides in its top tile).
constexpr int mul_latency(int aw, int bw, bool is_signed, int chunk_a = 24, int chunk_b = 17) {
  const int s = is_signed ? 1 : 0;
  const int tiles = ((aw - s + chunk_a - 1) / chunk_a) * ((bw - s + chunk_b - 1) / chunk_b);
  int levels = 0;
  while ((1 << levels) < tiles) ++levels;
  return 2 + levels;
}

}  // namespace rpu::ref
