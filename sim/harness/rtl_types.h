// The co-simulation's view of rpu_top: its ports as plain records (work items in, per-item
// results and per-pixel results out), the port widths that follow from the hardware
// parameters, and the bit vectors that carry wide fields between the harnesses and the
// Verilated models (C++ or SystemC): Bits, bits.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bits.h"
#include "fixed/fixed.h"
#include "model/hw_params.h"

namespace rpu::sim {

using fixed::i128;
using fixed::u128;

// rpu_top's widths at the given hardware parameters (rtl/top/rpu_top.v, docs/rtl.md). The
// top-level parameters that are not hardware parameters are fixed here and in every build.
struct TopWidths {
  static constexpr int kSegAddrW = 12;  // segment RAM: 4096 descriptors
  static constexpr int kIdxW = 14;      // pixel index
  static constexpr int kIdW = 32;       // work-item id
  static constexpr int kPrimW = 16;     // primitive id
  static constexpr int kSurfAddrW = 4;  // surface RAM: 16 descriptors
  static constexpr int kIndicators = 1; // the surface search's pass unit (rpu_top's Indicators)
  int CW, DW, TW, UW, XW, HW, VgW, EgW, R2W, L2W, GdW, CamW, SegW, SurfDW, DepthW, N;
  explicit TopWidths(const ref::HwParams& p);
};

// The parameters of the SystemC build (sim/systemc/CMakeLists.txt passes -GUnrolled=0): the
// default widths and n, n1 in the iterative form.
ref::HwParams systemc_params();

// One work item as rpu_top takes it: (pixel, segment) or (pixel, surface, piece).
struct WorkItem {
  std::uint32_t id = 0;
  int i = 0, j = 0;
  std::uint32_t seg = 0;  // segment RAM address, or surface RAM address (surface)
  bool last = false;      // the pixel's last item
  bool texture = false;   // (not a port: the descriptor's bit; kept for reports)
  bool surface = false;   // a surface piece (item_surf_i)
  int piece = 0;          // the piece, 0..2 (item_piece_i)
  const char* kind() const { return surface ? "surface" : texture ? "texture" : "curve"; }
};

// One result record of rpu_top's result stream.
struct ItemResult {
  std::uint32_t id = 0;
  int i = 0, j = 0;
  std::uint32_t seg = 0;
  bool last = false, texture = false, surface = false;
  int piece = 0, pieces = 0;  // surfaces: the piece and the pair's non-empty pieces
  std::uint32_t primitive = 0;
  bool pred1 = false, hit = false, overflow = false;
  i128 depth = 0;
  std::uint64_t tau = 0;
  i128 t = 0;
  i128 X[3] = {0, 0, 0};
  bool operator==(const ItemResult& o) const;
  std::string describe() const;  // every field, one line
};

// One result of rpu_top's pixel stream.
struct PixelResult {
  int i = 0, j = 0;
  bool hit = false;
  i128 depth = 0;
  std::uint32_t primitive = 0;
};

}  // namespace rpu::sim
