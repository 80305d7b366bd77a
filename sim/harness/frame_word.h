// The chord's-frame fields as the RTL carries them: the frame descriptor {e1, e2, s, c2, s2, a1,
// a2} (rtl/curve/rpu_frame.v's fr_i, `RPU_FRDW bits) and a frame guide {mode, η, η²}
// (rpu_candidate's g1_i/g2_i; two of them, {g1, g2}, are rpu_ip's fg_i and the segment
// descriptor's frame guides). Formats: docs/fixed-point.md. Header-only: the co-simulation
// harness and the unit testbenches pack them with the same functions.
#pragma once

#include "bits.h"
#include "model/descriptors.h"
#include "model/hw_params.h"

namespace rpu::sim {

// The descriptor, most significant field first; e1, e2 as {z, y, x}.
inline void add_frame_desc(Concat& c, const ref::FrameDesc& f) {
  using H = ref::HwParams;
  const int EW = H::kFrameMant + 2, CW2 = H::kFrameCosFrac + 2, AW = H::kFrameFlatFrac - 3;
  c.add3(f.e1.x, f.e1.y, f.e1.z, EW);
  c.add3(f.e2.x, f.e2.y, f.e2.z, EW);
  c.add(f.s, 6);
  c.add(f.c2, CW2);
  c.add(f.s2, CW2);
  c.add(f.guide[0].a, AW);
  c.add(f.guide[1].a, AW);
}
// One frame guide: mode (2 bits), η (FG + 5, unsigned), η² (the radicand width).
inline void add_frame_guide(Concat& c, const ref::FrameGuide& g) {
  using H = ref::HwParams;
  c.add(static_cast<i128>(g.mode), 2);
  c.add(g.eta, H::kFrameGuideFrac + 5);
  c.add(g.eta2, H::frame_radicand_w());
}
inline Bits pack_frame_desc(const ref::FrameDesc& f) {
  Concat c;
  add_frame_desc(c, f);
  return c.bits();
}
inline Bits pack_frame_guide(const ref::FrameGuide& g) {
  Concat c;
  add_frame_guide(c, g);
  return c.bits();
}
// Both guides of a descriptor, {g1, g2}.
inline Bits pack_frame_guides(const ref::FrameDesc& f) {
  Concat c;
  for (const ref::FrameGuide& g : f.guide) add_frame_guide(c, g);
  return c.bits();
}

}  // namespace rpu::sim
