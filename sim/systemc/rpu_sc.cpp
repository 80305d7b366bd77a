// rpu_sc: the SystemC harness of rpu_top (Verilated with --sc). `rpu render --backend rtl
// --systemc` writes a job file (descriptors and work items, sim/harness/stream_file.h) and
// runs `rpu_sc JOB STREAMS`; this program plays the frame through the SystemC model and writes
// every result and pixel record with the cycle counts, and `rpu` checks them with the same
// scoreboard as the C++ harness.
//
// Structure: an sc_clock; a Loader (reset, camera and segment writes, then starts the
// stream); a Source that takes work items from an sc_fifo and drives the valid/ready input; a
// ResultSink and a PixelSink that take the output streams into sc_fifos; a Recorder that drains
// those fifos and stops the simulation after the last pixel. Every process acts on the falling
// edge: the design's outputs are settled there, its ready/valid outputs come from registers, so
// a handshake seen at the falling edge completes at the next rising edge — the same cycle
// accounting as the C++ harness (sim/harness/cosim.cpp), which gives the same cycle count.
#include <systemc.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>

#include "Vrpu_top_sc.h"
#include "coverage_file.h"
#include "stream_file.h"

using namespace rpu;

// sc_fifo<T> prints its contents with operator<< (sc_fifo::print, dump).
namespace rpu::sim {
std::ostream& operator<<(std::ostream& os, const WorkItem& w) {
  return os << "item " << w.id << " (" << w.i << "," << w.j << ") seg " << w.seg;
}
std::ostream& operator<<(std::ostream& os, const ItemResult& r) { return os << r.describe(); }
std::ostream& operator<<(std::ostream& os, const PixelResult& p) {
  return os << "pixel (" << p.i << "," << p.j << ") hit " << p.hit << " primitive " << p.primitive;
}
}  // namespace rpu::sim

namespace {

template <class T>
struct PortType;
template <class T>
struct PortType<sc_core::sc_in<T>> {
  using type = T;
};
template <class T>
struct PortType<sc_core::sc_out<T>> {
  using type = T;
};
// The value type of a Verilated port member (declared as a reference to the port).
template <class P>
using value_t = typename PortType<std::remove_cvref_t<P>>::type;
template <class P>
using sig_t = sc_core::sc_signal<value_t<P>>;

template <int W>
void to_sc(sc_dt::sc_bv<W>& v, const sim::Bits& b) {
  for (int k = 0; k < (W + 31) / 32; ++k)
    v.set_word(k, k < static_cast<int>(b.words().size()) ? b.words()[static_cast<size_t>(k)] : 0u);
}
inline sim::u128 from_sc(std::uint32_t v) { return v; }
inline sim::u128 from_sc(std::uint64_t v) { return v; }
inline sim::u128 from_sc(bool v) { return v ? 1 : 0; }
template <int W>
sim::Bits bits_of(const sc_dt::sc_bv<W>& v) {
  sim::Bits b(W);
  for (int k = 0; k < (W + 31) / 32; ++k) b.words()[static_cast<size_t>(k)] = v.get_word(k);
  return b;
}
template <class T>
sim::Bits bits_of(const T& v) {
  sim::Bits b(64);
  const std::uint64_t u = static_cast<std::uint64_t>(v);
  b.words()[0] = static_cast<std::uint32_t>(u);
  b.words()[1] = static_cast<std::uint32_t>(u >> 32);
  return b;
}

// The signals between the testbench modules and the design.
struct Wires {
  sc_clock clk{"clk", 10, SC_NS};  // Clock::kPeriodNs
  sc_signal<bool> rst_n{"rst_n"}, cam_we{"cam_we"}, seg_we{"seg_we"}, surf_we{"surf_we"};
  sig_t<decltype(Vrpu_top_sc::cam_data_i)> cam_data{"cam_data"};
  sig_t<decltype(Vrpu_top_sc::seg_addr_i)> seg_addr{"seg_addr"};
  sig_t<decltype(Vrpu_top_sc::seg_data_i)> seg_data{"seg_data"};
  sig_t<decltype(Vrpu_top_sc::surf_addr_i)> surf_addr{"surf_addr"};
  sig_t<decltype(Vrpu_top_sc::surf_data_i)> surf_data{"surf_data"};
  sc_signal<bool> item_surf{"item_surf"}, res_surf{"res_surf"};
  sig_t<decltype(Vrpu_top_sc::item_piece_i)> item_piece{"item_piece"};
  sig_t<decltype(Vrpu_top_sc::res_piece_o)> res_piece{"res_piece"};
  sig_t<decltype(Vrpu_top_sc::res_pieces_o)> res_pieces{"res_pieces"};
  sc_signal<bool> item_valid{"item_valid"}, item_ready{"item_ready"}, item_last{"item_last"};
  sig_t<decltype(Vrpu_top_sc::item_id_i)> item_id{"item_id"};
  sig_t<decltype(Vrpu_top_sc::item_i_i)> item_i{"item_i"};
  sig_t<decltype(Vrpu_top_sc::item_j_i)> item_j{"item_j"};
  sig_t<decltype(Vrpu_top_sc::item_seg_i)> item_seg{"item_seg"};
  sc_signal<bool> res_valid{"res_valid"}, res_ready{"res_ready"}, res_last{"res_last"},
      res_tex{"res_tex"}, res_pred1{"res_pred1"}, res_hit{"res_hit"}, res_ovf{"res_ovf"};
  sig_t<decltype(Vrpu_top_sc::res_id_o)> res_id{"res_id"};
  sig_t<decltype(Vrpu_top_sc::res_i_o)> res_i{"res_i"};
  sig_t<decltype(Vrpu_top_sc::res_j_o)> res_j{"res_j"};
  sig_t<decltype(Vrpu_top_sc::res_seg_o)> res_seg{"res_seg"};
  sig_t<decltype(Vrpu_top_sc::res_prim_o)> res_prim{"res_prim"};
  sig_t<decltype(Vrpu_top_sc::res_depth_o)> res_depth{"res_depth"};
  sig_t<decltype(Vrpu_top_sc::res_tau_o)> res_tau{"res_tau"};
  sig_t<decltype(Vrpu_top_sc::res_t_o)> res_t{"res_t"};
  sig_t<decltype(Vrpu_top_sc::res_x_o)> res_x{"res_x"};
  sc_signal<bool> pix_valid{"pix_valid"}, pix_ready{"pix_ready"}, pix_hit{"pix_hit"};
  sig_t<decltype(Vrpu_top_sc::pix_i_o)> pix_i{"pix_i"};
  sig_t<decltype(Vrpu_top_sc::pix_j_o)> pix_j{"pix_j"};
  sig_t<decltype(Vrpu_top_sc::pix_depth_o)> pix_depth{"pix_depth"};
  sig_t<decltype(Vrpu_top_sc::pix_prim_o)> pix_prim{"pix_prim"};

  void bind(Vrpu_top_sc& d) {
    d.clk_i(clk);
    d.rst_ni(rst_n);
    d.cam_we_i(cam_we);
    d.cam_data_i(cam_data);
    d.seg_we_i(seg_we);
    d.seg_addr_i(seg_addr);
    d.seg_data_i(seg_data);
    d.surf_we_i(surf_we);
    d.surf_addr_i(surf_addr);
    d.surf_data_i(surf_data);
    d.item_surf_i(item_surf);
    d.item_piece_i(item_piece);
    d.res_surf_o(res_surf);
    d.res_piece_o(res_piece);
    d.res_pieces_o(res_pieces);
    d.item_valid_i(item_valid);
    d.item_ready_o(item_ready);
    d.item_id_i(item_id);
    d.item_i_i(item_i);
    d.item_j_i(item_j);
    d.item_seg_i(item_seg);
    d.item_last_i(item_last);
    d.res_valid_o(res_valid);
    d.res_ready_i(res_ready);
    d.res_id_o(res_id);
    d.res_i_o(res_i);
    d.res_j_o(res_j);
    d.res_seg_o(res_seg);
    d.res_last_o(res_last);
    d.res_tex_o(res_tex);
    d.res_prim_o(res_prim);
    d.res_pred1_o(res_pred1);
    d.res_hit_o(res_hit);
    d.res_depth_o(res_depth);
    d.res_tau_o(res_tau);
    d.res_t_o(res_t);
    d.res_x_o(res_x);
    d.res_ovf_o(res_ovf);
    d.pix_valid_o(pix_valid);
    d.pix_ready_i(pix_ready);
    d.pix_i_o(pix_i);
    d.pix_j_o(pix_j);
    d.pix_hit_o(pix_hit);
    d.pix_depth_o(pix_depth);
    d.pix_prim_o(pix_prim);
  }
};

// The stream's cycle index, from simulated time: falling edge k after the start (k = 0, 1, …)
// acts for rising edge k + 1, as iteration k of the C++ harness's loop.
struct Clock {
  bool running = false;
  sc_core::sc_time start;
  static constexpr double kPeriodNs = 10;
  bool active() const { return running && sc_core::sc_time_stamp() > start; }
  std::uint64_t index() const {
    return static_cast<std::uint64_t>((sc_core::sc_time_stamp() - start).to_seconds() * 1e9 /
                                      kPeriodNs + 0.5) - 1;
  }
};

SC_MODULE(Loader) {
  Wires* w = nullptr;
  const sim::FrameSchedule* f = nullptr;
  Clock* clock = nullptr;
  sim::CoverageFile* coverage = nullptr;
  SC_CTOR(Loader) { SC_THREAD(run); }
  void cycle() { wait(w->clk.negedge_event()); }
  void reset() {
    w->rst_n = false;
    for (int k = 0; k < 4; ++k) cycle();
    w->rst_n = true;
  }
  void run() {
    cycle();
    reset();
    // The toggle base of a coverage build (as the C++ harness: after the first reset). The model
    // runs in Verilator's default context.
    coverage->mark(*Verilated::threadContextp());
    value_t<decltype(Vrpu_top_sc::cam_data_i)> cam;
    to_sc(cam, f->camera);
    w->cam_data = cam;
    w->cam_we = true;
    cycle();
    w->cam_we = false;
    for (size_t k = 0; k < f->segments.size(); ++k) {
      value_t<decltype(Vrpu_top_sc::seg_data_i)> seg;
      to_sc(seg, f->segments[k]);
      w->seg_data = seg;
      w->seg_addr = static_cast<std::uint32_t>(k);
      w->seg_we = true;
      cycle();
    }
    w->seg_we = false;
    for (size_t k = 0; k < f->surfaces.size(); ++k) {
      value_t<decltype(Vrpu_top_sc::surf_data_i)> surf;
      to_sc(surf, f->surfaces[k]);
      w->surf_data = surf;
      w->surf_addr = static_cast<std::uint32_t>(k);
      w->surf_we = true;
      cycle();
    }
    w->surf_we = false;
    reset();
    clock->start = sc_time_stamp();
    clock->running = true;
  }
};

// Work items from an sc_fifo onto the valid/ready input.
SC_MODULE(Source) {
  sc_fifo_in<sim::WorkItem> in;
  Wires* w = nullptr;
  Clock* clock = nullptr;
  std::int64_t first_accept = -1;
  std::uint64_t stall_cycles = 0;
  SC_CTOR(Source) { SC_THREAD(run); }
  void run() {
    sim::WorkItem cur;
    bool have = false;
    for (;;) {
      wait(w->clk.negedge_event());
      if (!clock->active()) continue;
      if (!have) have = in.nb_read(cur);
      w->item_valid = have;
      if (have) {
        w->item_id = cur.id;
        w->item_i = static_cast<std::uint32_t>(cur.i);
        w->item_j = static_cast<std::uint32_t>(cur.j);
        w->item_seg = cur.seg;
        w->item_last = cur.last;
        w->item_surf = cur.surface;
        w->item_piece = static_cast<std::uint32_t>(cur.piece);
        if (w->item_ready.read()) {  // taken at the coming rising edge
          if (first_accept < 0) first_accept = static_cast<std::int64_t>(clock->index());
          have = false;
        } else {
          ++stall_cycles;
        }
      }
    }
  }
};

// The result stream into an sc_fifo.
SC_MODULE(ResultSink) {
  sc_fifo_out<sim::ItemResult> out;
  Wires* w = nullptr;
  Clock* clock = nullptr;
  sim::TopWidths widths{ref::HwParams{}};
  std::int64_t first_result = -1;
  SC_CTOR(ResultSink) { SC_THREAD(run); }
  void run() {
    for (;;) {
      wait(w->clk.negedge_event());
      if (!clock->active()) continue;
      w->res_ready = true;
      if (!w->res_valid.read()) continue;
      if (first_result < 0) first_result = static_cast<std::int64_t>(clock->index());
      sim::ItemResult r;
      r.id = static_cast<std::uint32_t>(w->res_id.read());
      r.i = static_cast<int>(w->res_i.read());
      r.j = static_cast<int>(w->res_j.read());
      r.seg = static_cast<std::uint32_t>(w->res_seg.read());
      r.last = w->res_last.read();
      r.texture = w->res_tex.read();
      r.surface = w->res_surf.read();
      r.piece = static_cast<int>(w->res_piece.read());
      r.pieces = static_cast<int>(w->res_pieces.read());
      r.primitive = static_cast<std::uint32_t>(w->res_prim.read());
      r.pred1 = w->res_pred1.read();
      r.hit = w->res_hit.read();
      r.overflow = w->res_ovf.read();
      r.depth = bits_of(w->res_depth.read()).field_signed(0, widths.DepthW);
      r.tau = static_cast<std::uint64_t>(bits_of(w->res_tau.read()).field(0, widths.N));
      r.t = bits_of(w->res_t.read()).field_signed(0, widths.TW);
      const sim::Bits x = bits_of(w->res_x.read());
      for (int c = 0; c < 3; ++c) r.X[c] = x.field_signed(c * widths.XW, widths.XW);
      out.write(r);
    }
  }
};

// The pixel stream into an sc_fifo.
SC_MODULE(PixelSink) {
  sc_fifo_out<sim::PixelResult> out;
  Wires* w = nullptr;
  Clock* clock = nullptr;
  sim::TopWidths widths{ref::HwParams{}};
  std::uint64_t last_index = 0;  // cycle index of the latest pixel taken
  SC_CTOR(PixelSink) { SC_THREAD(run); }
  void run() {
    for (;;) {
      wait(w->clk.negedge_event());
      if (!clock->active()) continue;
      w->pix_ready = true;
      if (!w->pix_valid.read()) continue;
      sim::PixelResult p;
      p.i = static_cast<int>(w->pix_i.read());
      p.j = static_cast<int>(w->pix_j.read());
      p.hit = w->pix_hit.read();
      p.depth = bits_of(w->pix_depth.read()).field_signed(0, widths.DepthW);
      p.primitive = static_cast<std::uint32_t>(w->pix_prim.read());
      last_index = clock->index();
      out.write(p);
    }
  }
};

// Drains the sinks' fifos, counts cycles, stops after the last pixel (or at the cycle limit).
SC_MODULE(Recorder) {
  sc_fifo_in<sim::ItemResult> results;
  sc_fifo_in<sim::PixelResult> pixels;
  Wires* w = nullptr;
  Clock* clock = nullptr;
  sim::StreamRecord* rec = nullptr;
  std::size_t want_pixels = 0;
  std::uint64_t limit = 0;
  SC_CTOR(Recorder) { SC_THREAD(run); }
  void run() {
    for (;;) {
      wait(w->clk.negedge_event());
      if (!clock->active()) continue;
      sim::ItemResult r;
      while (results.nb_read(r)) rec->results.push_back(r);
      sim::PixelResult p;
      while (pixels.nb_read(p)) rec->pixels.push_back(p);
      if (rec->pixels.size() >= want_pixels || clock->index() >= limit) {
        rec->stats.timed_out = rec->pixels.size() < want_pixels;
        sc_stop();
        return;
      }
    }
  }
};

}  // namespace

int sc_main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: rpu_sc JOB STREAMS (written and read by `rpu render "
                         "--backend rtl --systemc`)\n");
    return 2;
  }
  try {
    const sim::FrameSchedule f = sim::read_job(argv[1]);
    const sim::TopWidths widths(f.params);
    if (f.params != sim::systemc_params()) {
      std::fprintf(stderr, "rpu_sc: error: this SystemC model is built at the default widths, "
                           "n 16, n1 2, iterative (--ip iterative); the job asks for others\n");
      return 1;
    }
    Wires w;
    Vrpu_top_sc dut("dut");
    w.bind(dut);
    sim::CoverageFile coverage(sim::CoverageFile::program() + "-" + dut.modelName());
    Clock clock;
    sim::StreamRecord rec;
    sc_fifo<sim::WorkItem> items("items", static_cast<int>(f.items.size()) + 1);
    sc_fifo<sim::ItemResult> results("results", 4096);
    sc_fifo<sim::PixelResult> pixels("pixels", 4096);
    for (const auto& it : f.items) items.nb_write(it);
    Loader loader("loader");
    loader.w = &w;
    loader.f = &f;
    loader.clock = &clock;
    loader.coverage = &coverage;
    Source source("source");
    source.in(items);
    source.w = &w;
    source.clock = &clock;
    ResultSink rsink("result_sink");
    rsink.out(results);
    rsink.w = &w;
    rsink.clock = &clock;
    rsink.widths = widths;
    PixelSink psink("pixel_sink");
    psink.out(pixels);
    psink.w = &w;
    psink.clock = &clock;
    psink.widths = widths;
    Recorder recorder("recorder");
    recorder.results(results);
    recorder.pixels(pixels);
    recorder.w = &w;
    recorder.clock = &clock;
    recorder.rec = &rec;
    recorder.want_pixels = f.expected_pixels.size();
    recorder.limit = sim::default_cycle_limit(f);
    const auto t0 = std::chrono::steady_clock::now();
    sc_start();
    rec.stats.sim_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    dut.final();
    coverage.write(*Verilated::threadContextp());
    // As the C++ harness: cycles up to and including the one that took the last pixel.
    rec.stats.cycles = rec.stats.timed_out ? recorder.limit : psink.last_index + 1;
    rec.stats.load_cycles = 1 + f.segments.size() + f.surfaces.size();
    rec.stats.items = f.items.size();
    rec.stats.curve_items = f.curve_items;
    rec.stats.texture_items = f.texture_items;
    rec.stats.surface_items = f.surface_items;
    rec.stats.pixels = rec.pixels.size();
    for (const auto& r : rec.results) rec.stats.hits += r.hit;
    if (source.first_accept >= 0 && rsink.first_result >= 0)
      rec.stats.latency_cycles =
          static_cast<std::uint64_t>(rsink.first_result - source.first_accept);
    rec.stats.stall_cycles = source.stall_cycles;
    sim::write_streams(argv[2], rec);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rpu_sc: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
