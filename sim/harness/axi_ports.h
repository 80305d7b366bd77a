// TopPorts over a Verilated rpu_axi (docs/axi.md): the co-simulation drives rpu_top through its
// AXI shell with bus-functional models of a host. Descriptors go over AXI4-Lite (the staging
// window DESC_DATA, then DESC_COMMIT); work items, pixels and item results are records packed
// into AXI4-Stream beats by the layouts of include/rpu_axi_regs.h, the same generated header a
// host driver includes. The BFMs follow the AXI rules (a beat's TVALID, once raised, stays
// until taken, its TDATA still) and check the shell's: every output beat held still until
// taken, TLAST exactly on the frame's last pixel and result. Gaps between item beats are drawn
// from the frame's seed (begin_frame). What the BFMs saw wrong is kept in protocol_errors().
#pragma once

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <verilated.h>

#include "port_bits.h"
#include "rpu_axi_regs.h"
#include "top_ports.h"
#include "verilated_model.h"

namespace rpu::sim {

// What the AXI configurations add to TopPorts: AXI4-Lite transactions and the BFMs' findings.
class AxiHost : public TopPorts {
 public:
  // One AXI4-Lite write or read (the streams' TREADY low and no new item beat meanwhile);
  // returns BRESP/RRESP (0 OKAY, 2 SLVERR, 3 DECERR).
  virtual int lite_write(std::uint32_t addr, std::uint32_t data, std::uint32_t strb = 0xF) = 0;
  virtual int lite_read(std::uint32_t addr, std::uint32_t* data) = 0;
  std::uint32_t read(std::uint32_t addr) {
    std::uint32_t v = 0;
    if (const int r = lite_read(addr, &v); r != 0)
      throw std::runtime_error(fmt::format("rpu_axi: read of 0x{:03X} answered {}", addr, r));
    return v;
  }
  virtual bool pix_offered() const = 0;     // m_pix's TVALID (a pixel record's beat, any one)
  virtual bool irq() const = 0;
  virtual std::uint64_t clock() const = 0;  // cycles since construction
  virtual int axis_bits() const = 0;        // TDATA bits of s_item and m_pix
  virtual int res_bits() const = 0;         // TDATA bits of m_res
  virtual const rpu_axi_widths& widths() const = 0;
  virtual const std::vector<std::string>& protocol_errors() const = 0;
  // The frame as the BFMs saw it, for the performance counters: the clock edges of START's
  // write and of DONE's rise (irq_o, IRQ_EN set by begin_frame), and the edges in between with
  // an item beat waiting (TVALID, no TREADY) or an output beat waiting.
  struct FrameWatch {
    bool started = false, done = false;
    std::uint64_t start_edge = 0, done_edge = 0, in_stalls = 0, out_stalls = 0;
  };
  virtual const FrameWatch& watch() const = 0;
  bool axi() const override { return true; }
};

template <class V>
class VerilatedAxiPorts final : public AxiHost {
 public:
  VerilatedAxiPorts(const ref::HwParams& p, std::uint64_t x_seed) : w_(p), m_(x_seed) {
    top_->rst_ni = 0;
    idle_inputs();
  }
  ~VerilatedAxiPorts() override { finish(); }

  void reset(int cycles) override {
    top_->rst_ni = 0;
    idle_inputs();
    item_ = Bits();
    item_raised_ = false;
    pix_beats_.clear();
    res_beats_.clear();
    for (int k = 0; k < cycles; ++k) tick();
    top_->rst_ni = 1;
    m_.coverage.mark(*ctx_);
    identify();
  }
  void write_camera(const Bits& data) override { write_descriptor(0, 0, data); }
  void write_segment(std::uint32_t addr, const Bits& data) override {
    write_descriptor(1, addr, data);
  }
  void write_surface(std::uint32_t addr, const Bits& data) override {
    write_descriptor(2, addr, data);
  }
  void begin_frame(std::size_t items, std::size_t pixels, std::uint64_t seed,
                   int valid_pct) override {
    frame_items_ = items;
    frame_pixels_ = pixels;
    items_sent_ = pix_seen_ = res_seen_ = 0;
    rng_.seed(seed ^ 0xA71u);
    gap_pct_ = valid_pct;
    if (const int r = lite_write(RPU_AXI_CTRL, RPU_AXI_CTRL_START_MASK | RPU_AXI_CTRL_IRQ_EN_MASK);
        r != 0)
      throw std::runtime_error(fmt::format("rpu_axi: CTRL.START answered {}", r));
  }

  void drive(const WorkItem* item, bool res_ready, bool pix_ready) override {
    if (item_.width() == 0 && item) {
      item_ = pack_item(*item);
      item_beat_ = 0;
      item_raised_ = false;
    }
    // A beat's TVALID rises after a random gap (the frame's valid_pct) and stays until taken.
    if (item_.width() != 0 && !item_raised_)
      item_raised_ = gap_pct_ >= 100 || static_cast<int>(rng_() % 100) < gap_pct_;
    set_item_beat();
    top_->m_res_tready_i = res_ready;
    top_->m_pix_tready_i = pix_ready;
    top_->eval();
  }
  bool item_ready() const override {
    return top_->s_item_tvalid_i && top_->s_item_tready_o && item_beat_ + 1 == item_nbeats_;
  }
  bool res_valid() const override {
    return top_->m_res_tvalid_o &&
           static_cast<int>(res_beats_.size()) + 1 == res_nbeats_;
  }
  bool pix_valid() const override {
    return top_->m_pix_tvalid_o &&
           static_cast<int>(pix_beats_.size()) + 1 == pix_nbeats_;
  }
  ItemResult result() const override {
    const Bits b = gather(res_beats_, get_bits(top_->m_res_tdata_o, res_bits_));
    const auto f = [&](int k) { return b.field(static_cast<int>(rpu_axi_result_offset(&aw_, k)),
                                               static_cast<int>(rpu_axi_result_width(&aw_, k))); };
    const auto s = [&](int k) {
      return b.field_signed(static_cast<int>(rpu_axi_result_offset(&aw_, k)),
                            static_cast<int>(rpu_axi_result_width(&aw_, k)));
    };
    ItemResult r;
    r.id = static_cast<std::uint32_t>(f(RPU_AXI_RESULT_ID));
    r.i = static_cast<int>(f(RPU_AXI_RESULT_I));
    r.j = static_cast<int>(f(RPU_AXI_RESULT_J));
    r.seg = static_cast<std::uint32_t>(f(RPU_AXI_RESULT_SEG));
    r.last = f(RPU_AXI_RESULT_LAST) != 0;
    r.surface = f(RPU_AXI_RESULT_SURF) != 0;
    r.piece = static_cast<int>(f(RPU_AXI_RESULT_PIECE));
    r.texture = f(RPU_AXI_RESULT_TEX) != 0;
    r.pieces = static_cast<int>(f(RPU_AXI_RESULT_PIECES));
    r.primitive = static_cast<std::uint32_t>(f(RPU_AXI_RESULT_PRIM));
    r.pred1 = f(RPU_AXI_RESULT_PRED1) != 0;
    r.hit = f(RPU_AXI_RESULT_HIT) != 0;
    r.depth = s(RPU_AXI_RESULT_DEPTH);
    r.tau = static_cast<std::uint64_t>(f(RPU_AXI_RESULT_TAU));
    r.t = s(RPU_AXI_RESULT_T);
    const int xo = static_cast<int>(rpu_axi_result_offset(&aw_, RPU_AXI_RESULT_X));
    for (int c = 0; c < 3; ++c) r.X[c] = b.field_signed(xo + c * w_.XW, w_.XW);
    r.overflow = f(RPU_AXI_RESULT_OVF) != 0;
    return r;
  }
  PixelResult pixel() const override {
    const Bits b = gather(pix_beats_, get_bits(top_->m_pix_tdata_o, axis_bits_));
    const auto f = [&](int k) { return b.field(static_cast<int>(rpu_axi_pixel_offset(&aw_, k)),
                                               static_cast<int>(rpu_axi_pixel_width(&aw_, k))); };
    PixelResult p;
    p.i = static_cast<int>(f(RPU_AXI_PIXEL_I));
    p.j = static_cast<int>(f(RPU_AXI_PIXEL_J));
    p.hit = f(RPU_AXI_PIXEL_HIT) != 0;
    p.depth = b.field_signed(static_cast<int>(rpu_axi_pixel_offset(&aw_, RPU_AXI_PIXEL_DEPTH)),
                             static_cast<int>(aw_.DepthW));
    p.primitive = static_cast<std::uint32_t>(f(RPU_AXI_PIXEL_PRIM));
    return p;
  }
  void tick() override {
    // The handshakes of this cycle, before the edge; the output streams' rules checked.
    if (fw_.started && !fw_.done) {
      if (top_->s_item_tvalid_i && !top_->s_item_tready_o) ++fw_.in_stalls;
      if ((top_->m_pix_tvalid_o && !top_->m_pix_tready_i) ||
          (top_->m_res_tvalid_o && !top_->m_res_tready_i))
        ++fw_.out_stalls;
    }
    const bool irq_before = top_->irq_o;
    if (top_->rst_ni) {
      if (top_->s_item_tvalid_i && top_->s_item_tready_o) {
        if (++item_beat_ == item_nbeats_) {
          ++items_sent_;
          item_ = Bits();
        }
        item_raised_ = false;
      }
      watch(top_->m_pix_tvalid_o, top_->m_pix_tready_i, top_->m_pix_tdata_o, axis_bits_,
            top_->m_pix_tlast_o, pix_hold_, "m_pix");
      watch(top_->m_res_tvalid_o, top_->m_res_tready_i, top_->m_res_tdata_o, res_bits_,
            top_->m_res_tlast_o, res_hold_, "m_res");
      take(top_->m_pix_tvalid_o && top_->m_pix_tready_i, top_->m_pix_tdata_o,
           top_->m_pix_tlast_o, pix_beats_, pix_nbeats_, axis_bits_,
           pix_seen_, frame_pixels_, "pixel");
      take(top_->m_res_tvalid_o && top_->m_res_tready_i, top_->m_res_tdata_o,
           top_->m_res_tlast_o, res_beats_, res_nbeats_, res_bits_,
           res_seen_, frame_items_, "item result");
    }
    m_.tick();
    ++clock_;
    if (fw_.started && !fw_.done && !irq_before && top_->irq_o) {
      fw_.done = true;
      fw_.done_edge = clock_;
    }
  }
  void trace(const std::string&) override {}
  void finish() override {
    m_.finish();
  }

  int lite_write(std::uint32_t addr, std::uint32_t data, std::uint32_t strb = 0xF) override {
    quiet_streams();
    top_->s_axil_awaddr_i = addr;
    top_->s_axil_awprot_i = 0;
    top_->s_axil_wdata_i = data;
    top_->s_axil_wstrb_i = strb;
    top_->s_axil_awvalid_i = 1;
    top_->s_axil_wvalid_i = 1;
    top_->s_axil_bready_i = 1;
    for (int k = 0; k < kLiteLimit; ++k) {
      top_->eval();
      const bool aw = top_->s_axil_awvalid_i && top_->s_axil_awready_o;
      const bool w = top_->s_axil_wvalid_i && top_->s_axil_wready_o;
      const bool b = top_->s_axil_bvalid_o;
      const int resp = top_->s_axil_bresp_o;
      if (b && (top_->s_axil_awvalid_i || top_->s_axil_wvalid_i))
        protocol_errors_.push_back(fmt::format("BVALID before AW and W of the write to 0x{:03X} "
                                               "were both taken", addr));
      if (b && addr == RPU_AXI_CTRL && (data & strb & RPU_AXI_CTRL_START_MASK) && resp == 0) {
        fw_ = FrameWatch{};  // START took effect at the last edge (BVALID rose with it)
        fw_.started = true;
        fw_.start_edge = clock_;
      }
      tick();
      if (aw) top_->s_axil_awvalid_i = 0;
      if (w) top_->s_axil_wvalid_i = 0;
      if (b) {
        top_->s_axil_bready_i = 0;
        top_->eval();
        return resp;
      }
    }
    throw std::runtime_error(fmt::format("rpu_axi: no write response for 0x{:03X} in {} cycles",
                                         addr, kLiteLimit));
  }
  int lite_read(std::uint32_t addr, std::uint32_t* data) override {
    quiet_streams();
    top_->s_axil_araddr_i = addr;
    top_->s_axil_arprot_i = 0;
    top_->s_axil_arvalid_i = 1;
    top_->s_axil_rready_i = 1;
    for (int k = 0; k < kLiteLimit; ++k) {
      top_->eval();
      const bool ar = top_->s_axil_arvalid_i && top_->s_axil_arready_o;
      const bool r = top_->s_axil_rvalid_o;
      const std::uint32_t d = top_->s_axil_rdata_o;
      const int resp = top_->s_axil_rresp_o;
      if (r && top_->s_axil_arvalid_i)
        protocol_errors_.push_back(fmt::format("RVALID before AR of the read of 0x{:03X} was "
                                               "taken", addr));
      tick();
      if (ar) top_->s_axil_arvalid_i = 0;
      if (r) {
        top_->s_axil_rready_i = 0;
        top_->eval();
        *data = d;
        return resp;
      }
    }
    throw std::runtime_error(fmt::format("rpu_axi: no read response for 0x{:03X} in {} cycles",
                                         addr, kLiteLimit));
  }
  bool pix_offered() const override { return top_->m_pix_tvalid_o; }
  bool irq() const override { return top_->irq_o; }
  std::uint64_t clock() const override { return clock_; }
  int axis_bits() const override { return axis_bits_; }
  int res_bits() const override { return res_bits_; }
  const rpu_axi_widths& widths() const override { return aw_; }
  const std::vector<std::string>& protocol_errors() const override { return protocol_errors_; }
  const FrameWatch& watch() const override { return fw_; }

 private:
  static constexpr int kLiteLimit = 64;
  struct Hold {
    bool held = false;  // last cycle: TVALID without TREADY
    Bits data;
    bool last = false;
  };

  void idle_inputs() {
    top_->s_axil_awvalid_i = top_->s_axil_wvalid_i = top_->s_axil_arvalid_i = 0;  // no request
    top_->s_axil_bready_i = top_->s_axil_rready_i = 0;
    top_->s_item_tvalid_i = top_->s_item_tlast_i = 0;                           // no item beat
    top_->m_pix_tready_i = top_->m_res_tready_i = 0;                            // nothing taken
  }
  // During an AXI4-Lite access: no output beat taken; an item beat already raised stays.
  void quiet_streams() {
    top_->m_pix_tready_i = 0;
    top_->m_res_tready_i = 0;
    set_item_beat();
  }
  void set_item_beat() {
    const bool on = item_.width() != 0 && item_raised_;
    top_->s_item_tvalid_i = on;
    if (on) {
      put(top_->s_item_tdata_i, slice(item_, item_beat_, axis_bits_));
      top_->s_item_tlast_i = items_sent_ + 1 == frame_items_ && item_beat_ + 1 == item_nbeats_;
    } else {
      top_->s_item_tlast_i = 0;
    }
  }
  static int beats(unsigned bits, int bus) {
    return static_cast<int>((bits + static_cast<unsigned>(bus) - 1) / static_cast<unsigned>(bus));
  }
  Bits pack_item(const WorkItem& it) const {
    Bits b(static_cast<int>(rpu_axi_item_bits(&aw_)));
    const auto set = [&](int k, i128 v) {
      b.set_field(static_cast<int>(rpu_axi_item_offset(&aw_, k)),
                  static_cast<int>(rpu_axi_item_width(&aw_, k)), v);
    };
    set(RPU_AXI_ITEM_ID, it.id);
    set(RPU_AXI_ITEM_I, it.i);
    set(RPU_AXI_ITEM_J, it.j);
    set(RPU_AXI_ITEM_SEG, it.seg);
    set(RPU_AXI_ITEM_LAST, it.last);
    set(RPU_AXI_ITEM_SURF, it.surface);
    set(RPU_AXI_ITEM_PIECE, it.piece);
    return b;
  }
  // Every bus is a whole number of 32-bit words, so beats cut and join at word boundaries.
  static Bits slice(const Bits& rec, int beat, int bus) {
    Bits b(bus);
    const std::size_t first = static_cast<std::size_t>(beat * bus / 32);
    for (std::size_t k = 0; k < b.words().size() && first + k < rec.words().size(); ++k)
      b.words()[k] = rec.words()[first + k];
    return b;
  }
  static Bits gather(const std::vector<Bits>& earlier, const Bits& now) {
    std::vector<std::uint32_t> words;
    for (const Bits& e : earlier) words.insert(words.end(), e.words().begin(), e.words().end());
    words.insert(words.end(), now.words().begin(), now.words().end());
    Bits b(static_cast<int>(32 * words.size()));
    b.words() = std::move(words);
    return b;
  }
  // A master's rule: a beat offered and not taken is offered again next cycle, unchanged.
  // TDATA is read only for a beat offered and not taken, or one held the cycle before.
  template <class P>
  void watch(bool valid, bool ready, const P& tdata, int bus, bool last, Hold& h,
             const char* port) {
    const bool now_held = valid && !ready;
    if (!h.held && !now_held) return;
    const Bits data = get_bits(tdata, bus);
    if (h.held && (!valid || data.words() != h.data.words() || last != h.last))
      protocol_errors_.push_back(fmt::format("{}: a beat not taken was {} (cycle {})", port,
                                             valid ? "changed" : "withdrawn", clock_));
    h.held = now_held;
    h.data = data;
    h.last = last;
  }
  template <class P>
  void take(bool handshake, const P& tdata, bool tlast, std::vector<Bits>& got, int nbeats,
            int bus, std::size_t& seen, std::size_t expected, const char* what) {
    if (!handshake) return;
    const bool final_beat = static_cast<int>(got.size()) + 1 == nbeats;
    const bool want_last = final_beat && seen + 1 == expected;
    if (tlast != want_last)
      protocol_errors_.push_back(fmt::format("{} {} of {}, beat {}: TLAST {} (cycle {})", what,
                                             seen + 1, expected, got.size(), tlast ? 1 : 0,
                                             clock_));
    if (final_beat) {
      got.clear();
      ++seen;
    } else {
      got.push_back(get_bits(tdata, bus));
    }
  }
  void write_descriptor(int target, std::uint32_t addr, const Bits& data) {
    for (std::size_t k = 0; k < data.words().size(); ++k)
      if (const int r = lite_write(RPU_AXI_DESC_DATA + 4 * static_cast<std::uint32_t>(k),
                                   data.words()[k]); r != 0)
        throw std::runtime_error(fmt::format("rpu_axi: DESC_DATA word {} answered {}", k, r));
    const std::uint32_t v = (static_cast<std::uint32_t>(target) << RPU_AXI_DESC_COMMIT_TARGET_LSB) |
                            (addr << RPU_AXI_DESC_COMMIT_ADDR_LSB);
    if (const int r = lite_write(RPU_AXI_DESC_COMMIT, v); r != 0)
      throw std::runtime_error(fmt::format("rpu_axi: DESC_COMMIT target {} address {} answered {}",
                                           target, addr, r));
  }
  // The identification block: what a driver checks before it talks to the unit.
  void identify() {
    if (read(RPU_AXI_ID) != RPU_AXI_MAGIC)
      throw std::runtime_error("rpu_axi: ID is not the magic number");
    const std::uint32_t version = read(RPU_AXI_VERSION);
    if (RPU_AXI_FIELD(version, RPU_AXI_VERSION_MAJOR) != RPU_AXI_VERSION_MAJOR)
      throw std::runtime_error(fmt::format("rpu_axi: register map version {:#x}", version));
    aw_ = rpu_axi_widths_from_regs(read(RPU_AXI_BUILD_IP), read(RPU_AXI_BUILD_W2),
                                   read(RPU_AXI_BUILD_W3), read(RPU_AXI_BUILD_W4));
    const std::uint32_t axis = read(RPU_AXI_BUILD_AXIS);
    axis_bits_ = 8 * static_cast<int>(RPU_AXI_FIELD(axis, RPU_AXI_BUILD_AXIS_AXIS_BYTES));
    res_bits_ = 8 * static_cast<int>(RPU_AXI_FIELD(axis, RPU_AXI_BUILD_AXIS_RES_BYTES));
    item_nbeats_ = beats(rpu_axi_item_bits(&aw_), axis_bits_);
    pix_nbeats_ = beats(rpu_axi_pixel_bits(&aw_), axis_bits_);
    res_nbeats_ = beats(rpu_axi_result_bits(&aw_), res_bits_);
    const auto u = [](int v) { return static_cast<unsigned>(v); };
    if (aw_.IdW != u(TopWidths::kIdW) || aw_.IdxW != u(TopWidths::kIdxW) ||
        aw_.SegAddrW != u(TopWidths::kSegAddrW) || aw_.PrimW != u(TopWidths::kPrimW) ||
        aw_.DepthW != u(w_.DepthW) || aw_.N != u(w_.N) || aw_.TW != u(w_.TW) || aw_.XW != u(w_.XW))
      throw std::runtime_error(fmt::format(
          "rpu_axi: the identification block's widths (IdW {} IdxW {} SegAddrW {} PrimW {} "
          "DepthW {} N {} TW {} XW {}) are not this configuration's", aw_.IdW, aw_.IdxW,
          aw_.SegAddrW, aw_.PrimW, aw_.DepthW, aw_.N, aw_.TW, aw_.XW));
  }

  TopWidths w_;
  rpu_axi_widths aw_{};
  int axis_bits_ = 32, res_bits_ = 32;
  int item_nbeats_ = 1, pix_nbeats_ = 1, res_nbeats_ = 1;  // beats of a record (identify())
  VerilatedModel<V> m_;
  VerilatedContext* const ctx_ = m_.ctx.get();
  V* const top_ = m_.top.get();
  std::uint64_t clock_ = 0;
  Bits item_;                 // the item being sent (width 0: none)
  int item_beat_ = 0;
  bool item_raised_ = false;
  std::vector<Bits> pix_beats_, res_beats_;  // beats of the record being received
  Hold pix_hold_, res_hold_;
  std::size_t frame_items_ = 0, frame_pixels_ = 0, items_sent_ = 0, pix_seen_ = 0, res_seen_ = 0;
  std::mt19937_64 rng_{1};
  int gap_pct_ = 100;
  std::vector<std::string> protocol_errors_;
  FrameWatch fw_;
};

}  // namespace rpu::sim
