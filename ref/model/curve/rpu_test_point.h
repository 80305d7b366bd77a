// Twin of rtl/curve/rpu_test_point.v | sim/tb/curve/tb_rpu_ip.cpp | sim/tests/curve/rpu_ip.cmake
// Test-point unit: once per pair, after the K steps, the chord parameter t and the curve point
// X = s(t) of the selected τ (rpu_guide_pair, rpu_curve_point), for the capture unit.
#pragma once

#include <cstdint>

#include "model/curve/rpu_sphere.h"
#include "model/datapath.h"

namespace rpu::ref {

struct TestPoint {
  i128 t = 0;  // t(τ) = sat(α + floor(β·τ_index / 2^n)), Q(3.FT)
  WVec3 X;     // s(t), LSB
};
TestPoint test_point_unit(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                          std::uint64_t tau, Overflow& ovf);

}  // namespace rpu::ref
