// Twin of rtl/texture/rpu_texture.v | sim/tb/texture/tb_rpu_texture.cpp |
// sim/tests/texture/rpu_texture.cmake
// Texture predicates pr1, pr2, pr3.
#pragma once

#include "model/datapath.h"

namespace rpu::ref {

struct TextureOut {
  bool pr1 = false, pr2 = false, pr3 = false;
  bool covers = false;  // pr1 ∧ (pr2 ∨ pr3); with a round join (pr1 ∧ pr3) ∨ pr2
  i128 t = 0;
  WVec3 X;
};
TextureOut texture_unit(const HwParams& p, const SegmentDesc& s, const WVec3& p0, Overflow& ovf);
// rpu_texture's latency in cycles at these widths (its header: six single stages, the front
// products, the squares e_k², rpu_chord, rpu_guide_pair, rpu_curve_point).
int texture_latency(const HwParams& p);

}  // namespace rpu::ref
