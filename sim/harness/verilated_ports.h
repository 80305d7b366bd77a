// TopPorts over a Verilated C++ model of rpu_top (any parameters: widths come from TopWidths).
// Each instance owns its VerilatedContext; in a coverage build each writes its own coverage files
// (coverage_file.h: after the first reset and at finish()).
#pragma once

#include <verilated.h>

#include "port_bits.h"
#include "top_ports.h"
#include "verilated_model.h"

namespace rpu::sim {

// Traced: the model was Verilated with --trace-fst (only those have V::trace).
template <class V, bool Traced>
class VerilatedPorts final : public TopPorts {
 public:
  VerilatedPorts(const ref::HwParams& p, std::uint64_t x_seed) : w_(p), m_(x_seed) {
    top_->rst_ni = 0;
    top_->cam_we_i = top_->seg_we_i = top_->surf_we_i = 0;          // no descriptor write
    top_->item_valid_i = top_->res_ready_i = top_->pix_ready_i = 0;  // no item, nothing taken
  }
  ~VerilatedPorts() override { finish(); }

  void reset(int cycles) override {
    top_->rst_ni = 0;
    for (int k = 0; k < cycles; ++k) tick();
    top_->rst_ni = 1;
    m_.coverage.mark(*ctx_);  // the toggle base: power-up values and the first reset left out
  }
  void write_camera(const Bits& data) override {
    put(top_->cam_data_i, data);
    top_->cam_we_i = 1;
    tick();
    top_->cam_we_i = 0;
  }
  void write_segment(std::uint32_t addr, const Bits& data) override {
    write_ram(top_->seg_data_i, top_->seg_addr_i, top_->seg_we_i, addr, data);
  }
  void write_surface(std::uint32_t addr, const Bits& data) override {
    write_ram(top_->surf_data_i, top_->surf_addr_i, top_->surf_we_i, addr, data);
  }
  void drive(const WorkItem* item, bool res_ready, bool pix_ready) override {
    top_->item_valid_i = item != nullptr;
    if (item) {
      top_->item_id_i = item->id;
      top_->item_i_i = static_cast<unsigned>(item->i);
      top_->item_j_i = static_cast<unsigned>(item->j);
      top_->item_seg_i = item->seg;
      top_->item_last_i = item->last;
      top_->item_surf_i = item->surface;
      top_->item_piece_i = static_cast<unsigned>(item->piece);
    }
    top_->res_ready_i = res_ready;
    top_->pix_ready_i = pix_ready;
    top_->eval();
  }
  bool item_ready() const override { return top_->item_ready_o; }
  bool res_valid() const override { return top_->res_valid_o; }
  bool pix_valid() const override { return top_->pix_valid_o; }
  ItemResult result() const override {
    ItemResult r;
    r.id = top_->res_id_o;
    r.i = static_cast<int>(top_->res_i_o);
    r.j = static_cast<int>(top_->res_j_o);
    r.seg = top_->res_seg_o;
    r.last = top_->res_last_o;
    r.texture = top_->res_tex_o;
    r.surface = top_->res_surf_o;
    r.piece = static_cast<int>(top_->res_piece_o);
    r.pieces = static_cast<int>(top_->res_pieces_o);
    r.primitive = top_->res_prim_o;
    r.pred1 = top_->res_pred1_o;
    r.hit = top_->res_hit_o;
    r.overflow = top_->res_ovf_o;
    r.depth = get_signed(top_->res_depth_o, w_.DepthW);
    r.tau = static_cast<std::uint64_t>(get_unsigned(top_->res_tau_o, w_.N));
    r.t = get_signed(top_->res_t_o, w_.TW);
    for (int c = 0; c < 3; ++c) r.X[c] = get_comp(top_->res_x_o, c, w_.XW);
    return r;
  }
  PixelResult pixel() const override {
    PixelResult p;
    p.i = static_cast<int>(top_->pix_i_o);
    p.j = static_cast<int>(top_->pix_j_o);
    p.hit = top_->pix_hit_o;
    p.depth = get_signed(top_->pix_depth_o, w_.DepthW);
    p.primitive = top_->pix_prim_o;
    return p;
  }
  void tick() override { m_.tick(); }
  void trace(const std::string& fst_path) override {
    if constexpr (Traced) m_.open_trace(fst_path);
  }
  void finish() override { m_.finish(); }

 private:
  // One clock with a descriptor RAM's write enable high.
  template <class D, class A, class W>
  void write_ram(D& data_port, A& addr_port, W& we_port, std::uint32_t addr, const Bits& data) {
    put(data_port, data);
    addr_port = addr;
    we_port = 1;
    tick();
    we_port = 0;
  }
  TopWidths w_;
  VerilatedModel<V> m_;
  VerilatedContext* const ctx_ = m_.ctx.get();
  V* const top_ = m_.top.get();
};

}  // namespace rpu::sim
