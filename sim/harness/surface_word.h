// A surface's indicator fields as the RTL carries them on one port, desc_i
// (rtl/surface/rpu_surface_desc.vh: rpu_indicator, rpu_surface_ip, rpu_surface_ip_step,
// rpu_surface_top). Formats: docs/fixed-point.md, "Surfaces". Header-only: the unit testbenches
// pack descriptors with this one function, in the layout's order.
#pragma once

#include "bits.h"
#include "model/descriptors.h"
#include "model/hw_params.h"

namespace rpu::sim {

// The fields, most significant first (the layout lists them LSB first: type at bit 0).
inline void add_surface_desc(Concat& c, const ref::HwParams& p, const ref::SurfaceDesc& s) {
  const int lw = p.surf_w, kf = p.surf_const_frac(), mw = p.surf_mant_w(), tw = lw + 8;
  c.add(s.cone.s, 8);
  c.add(s.cone.m, mw);
  c.add(s.fin.s, 8);
  c.add(s.fin.m, mw);
  c.add(s.rocket_b, lw);
  c.add(s.rocket_a, lw);
  c.add(s.k_turn, tw);
  c.add(s.a_turn, tw);
  c.add(s.rho0, lw);
  c.add(s.y_angle.s, 8);
  c.add(s.y_angle.m, mw);
  c.add(s.ke2, kf + 2);
  c.add(s.kd, kf + 2);
  c.add(s.r2, 2 * lw + 1);
  c.add3(s.sx, s.sy, s.sz, kf + 1);
  c.add(s.full_turns, 4);
  c.add(static_cast<int>(s.type), 3);
}
inline Bits pack_surface_desc(const ref::HwParams& p, const ref::SurfaceDesc& s) {
  Concat c;
  add_surface_desc(c, p, s);
  return c.bits();
}
// The word's width, `RPU_SDW in rtl/common/rpu_widths.vh.
inline int surface_desc_w(const ref::HwParams& p) { return p.surf_desc_w(); }

}  // namespace rpu::sim
