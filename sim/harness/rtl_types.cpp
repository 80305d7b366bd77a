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
      DepthW(p.depth_w()), N(p.n) {}

void Bits::set_bit(int k, bool v) {
  std::uint32_t& w = words_[static_cast<size_t>(k / 32)];
  const std::uint32_t m = 1u << (k % 32);
  w = v ? (w | m) : (w & ~m);
}

u128 Bits::field(int lo, int w) const {
  u128 u = 0;
  for (int b = 0; b < w; ++b)
    if (lo + b < width_ && bit(lo + b)) u |= u128{1} << b;
  return u;
}

i128 Bits::field_signed(int lo, int w) const {
  const u128 u = field(lo, w);
  if (w >= 128) return static_cast<i128>(u);
  const u128 sign = u128{1} << (w - 1);
  return static_cast<i128>((u ^ sign) - sign);
}

int Concat::width() const {
  int w = 0;
  for (const auto& f : fields_) w += f.width;
  return w;
}

Bits Concat::bits() const {
  Bits b(width());
  int at = 0;
  for (auto it = fields_.rbegin(); it != fields_.rend(); ++it) {
    const u128 u = static_cast<u128>(it->value);
    for (int k = 0; k < it->width; ++k, ++at)
      b.set_bit(at, k < 128 ? ((u >> k) & 1) != 0 : it->value < 0);
  }
  return b;
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
