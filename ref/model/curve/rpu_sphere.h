// Twin of rtl/curve/rpu_sphere.v | sim/tb/curve/tb_rpu_sphere.cpp |
// sim/tests/curve/rpu_sphere.cmake
// Sphere unit: pred_1 and the search interval.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

struct SearchInterval {
  bool pred1 = false;  // the ray meets the interpolation sphere in front of the eye
  i128 tc = 0;         // v̂·q, LSB (distance along the ray to the closest approach)
  i128 half_chord = 0; // sqrt(R² - |q × v̂|²), LSB
  WVec3 A, B;          // interval end points, LSB (saturated to coord_w)
  WVec3 AB;            // B - A, LSB
  i128 alpha = 0;      // t(τ = 0) = (A - p1)·d / L², Q(3.FT)
  i128 beta = 0;       // t(1) - t(0) = (B - A)·d / L², Q(3.FT)
};
SearchInterval sphere_unit(const HwParams& p, const IVec3& eye, const IVec3& vhat,
                           const SegmentDesc& s, Overflow& ovf);
// rpu_sphere's latency in cycles at these widths (its header: the square root, nine single stages,
// four rpu_mul groups, rpu_chord).
int sphere_latency(const HwParams& p);

}  // namespace rpu::ref
