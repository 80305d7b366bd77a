#include "rtl_types.h"

#include <fmt/format.h>

namespace rpu::sim {

ref::HwParams systemc_params() {
  ref::HwParams p;
  p.unrolled = false;
  return p;
}

// Every width is a named function of HwParams (model/hw_params.h), the one place that restates
// rpu_top.v's derived parameters.
TopWidths::TopWidths(const ref::HwParams& p)
    : CW(p.coord_w), DW(p.diff_w()), TW(p.t_w()), UW(p.unit_w()), XW(p.point_w()),
      HW(p.guide_h_w()), VgW(p.ray_dir_w()), EgW(p.edge_w()), R2W(p.r2_w()), L2W(p.l2_w()),
      GdW(p.guide_desc_w()), CamW(p.camera_desc_w()), SegW(p.segment_desc_w(kPrimW)),
      SurfDW(p.surface_ram_desc_w(kPrimW)), DepthW(p.depth_w()), N(p.n) {}

bool ItemResult::operator==(const ItemResult& o) const {
  return id == o.id && i == o.i && j == o.j && seg == o.seg && last == o.last &&
         texture == o.texture && surface == o.surface && piece == o.piece &&
         pieces == o.pieces && primitive == o.primitive && pred1 == o.pred1 && hit == o.hit &&
         overflow == o.overflow && depth == o.depth && tau == o.tau && t == o.t &&
         X[0] == o.X[0] && X[1] == o.X[1] && X[2] == o.X[2];
}

std::string ItemResult::describe() const {
  return fmt::format("id {} pixel ({},{}) seg {} last {} {} prim {} pred1 {} hit {} depth {} "
                     "tau {} t {} X ({}, {}, {}) ovf {}",
                     id, i, j, seg, last ? 1 : 0,
                     surface ? fmt::format("surface piece {} of {}", piece, pieces)
                             : std::string(texture ? "texture" : "curve"), primitive,
                     pred1 ? 1 : 0, hit ? 1 : 0, fixed::to_decimal(depth), tau, fixed::to_decimal(t), fixed::to_decimal(X[0]), fixed::to_decimal(X[1]),
                     fixed::to_decimal(X[2]), overflow ? 1 : 0);
}

}  // namespace rpu::sim
