#include "rtl_types.h"

#include <fmt/format.h>

namespace rpu::sim {

ref::HwParams systemc_params() {
  ref::HwParams p;
  p.unrolled = false;
  return p;
}

TopWidths::TopWidths(const ref::HwParams& p)
    : CW(p.coord_w), DW(p.coord_w + 1), TW(p.t_w()), UW(p.unit_w()), XW(p.coord_w + 3),
      HW(p.coord_w + 5), VgW(4 + p.dir_frac + ref::HwParams::kRayGuard), EgW(p.edge_w()),
      R2W(2 * p.coord_w + 1), L2W(2 * p.coord_w + 3), N(p.n) {
  GdW = 2 + HW + CW + p.t_frac + 3 * UW;
  CamW = 9 * VgW + 12 * EgW + 3 * CW;
  SegW = 1 + kPrimW + 3 * CW + 3 * DW + 3 * CW + R2W + L2W + p.inv_w + 7 + 2 * GdW;
  DepthW = CW + 4 + EgW + 2;
}

bool ItemResult::operator==(const ItemResult& o) const {
  return id == o.id && i == o.i && j == o.j && seg == o.seg && last == o.last &&
         texture == o.texture && primitive == o.primitive && pred1 == o.pred1 && hit == o.hit &&
         overflow == o.overflow && depth == o.depth && tau == o.tau && t == o.t &&
         X[0] == o.X[0] && X[1] == o.X[1] && X[2] == o.X[2];
}

std::string ItemResult::describe() const {
  return fmt::format("id {} pixel ({},{}) seg {} last {} {} prim {} pred1 {} hit {} depth {} "
                     "tau {} t {} X ({}, {}, {}) ovf {}",
                     id, i, j, seg, last ? 1 : 0, texture ? "texture" : "curve", primitive,
                     pred1 ? 1 : 0, hit ? 1 : 0, fixed::to_decimal(depth), tau, fixed::to_decimal(t), fixed::to_decimal(X[0]), fixed::to_decimal(X[1]),
                     fixed::to_decimal(X[2]), overflow ? 1 : 0);
}

}  // namespace rpu::sim
