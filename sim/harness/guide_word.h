// One guide as the RTL carries it on one port: its shape {mode, h, a, b}
// (rtl/curve/rpu_guide_shape.vh, rpu_guide_pair's g1_i/g2_i) and its descriptor {shape, u}
// (rtl/curve/rpu_guide_desc.vh: rpu_ip, rpu_ip_step, rpu_candidate, rpu_texture and the segment
// descriptor of rpu_top). Formats: docs/fixed-point.md. Header-only: the co-simulation harness
// and the unit testbenches pack guides with the same two functions.
#pragma once

#include "bits.h"
#include "model/descriptors.h"
#include "model/hw_params.h"

namespace rpu::sim {

// The shape's fields, most significant first: mode (2 bits), h (CW + 5), a (CW), b (FT).
inline void add_guide_shape(Concat& c, const ref::HwParams& p, int mode, i128 h, i128 a, i128 b) {
  c.add(mode, 2);
  c.add(h, p.coord_w + 5);
  c.add(a, p.coord_w);
  c.add(b, p.t_frac);
}
// The descriptor: the shape above u = {z, y, x}, Q(2.FU) each.
inline void add_guide(Concat& c, const ref::HwParams& p, const ref::GuideDesc& g) {
  add_guide_shape(c, p, static_cast<int>(g.mode), g.h, g.a, g.b);
  c.add3(g.u.x, g.u.y, g.u.z, p.unit_w());
}
inline Bits pack_guide_shape(const ref::HwParams& p, int mode, i128 h, i128 a, i128 b) {
  Concat c;
  add_guide_shape(c, p, mode, h, a, b);
  return c.bits();
}
inline Bits pack_guide(const ref::HwParams& p, const ref::GuideDesc& g) {
  Concat c;
  add_guide(c, p, g);
  return c.bits();
}

}  // namespace rpu::sim
