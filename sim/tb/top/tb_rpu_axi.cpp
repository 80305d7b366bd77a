// rpu_axi, rpu_top's AXI shell (docs/axi.md), through the bus-functional models of
// sim/harness/axi_ports.h. Modes (first argument):
//   frame  a demo frame through the shell with random TVALID gaps and TREADY back-pressure
//          (seeded, printed): every item result and pixel against the model (the co-simulation's
//          scoreboard), the BFMs' protocol checks (outputs held until taken, TLAST on the frame's
//          last pixel and result), DONE and irq_o, and every performance counter against what the
//          BFMs counted (cycles START -> DONE, items and results per kind, pixels, hits, stalls)
//   host   bad host behaviour, each with its defined answer: reads and writes outside the map,
//          writes to read-only registers, commits outside a RAM, an item before START, START and
//          a commit during a frame, TLAST on an item that is not its pixel's last, SOFT_RESET in
//          the middle of a frame and with a pixel held on m_pix (the next frame is still right
//          and ends); the identification block and the staging window's byte strobes
// Options: --scene NAME[+NAME...] (default curve12), --size N (default 16), --config NAME (an AXI
// configuration of rpu_rtl, default n16_n1_2_iterative_axi).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "axi_ports.h"
#include "cosim.h"
#include "tb_base.h"
#include "tb_demo_frame.h"

namespace {

using rpu::sim::AxiHost;
int failures = 0;

void expect(bool ok, const std::string& what) {
  if (!ok) {
    std::printf("FAILURE: %s\n", what.c_str());
    ++failures;
  }
}

void expect_eq(std::uint64_t got, std::uint64_t want, const std::string& what) {
  expect(got == want, fmt::format("{}: {} (expected {})", what, got, want));
}

std::uint32_t err(AxiHost& h) { return h.read(RPU_AXI_ERROR); }

// Clears every error cause (W1C) and checks that they are gone.
void clear_errors(AxiHost& h) {
  expect_eq(h.lite_write(RPU_AXI_ERROR, 0xFFFFFFFFu), 0, "ERROR W1C response");
  expect_eq(err(h), 0, "ERROR after W1C");
}

// Clocks with `item` offered (nullptr: none) and the sinks' TREADY as given until `until()`
// holds after the inputs are set, at most `limit` clocks; returns whether it held. With `edge`
// the clock edge of the cycle where it holds runs too (its handshake happens).
template <class F>
bool clock_until(AxiHost& h, const sim::WorkItem* item, bool res_ready, bool pix_ready, int limit,
                 F until, bool edge = true) {
  for (int k = 0; k < limit; ++k) {
    h.drive(item, res_ready, pix_ready);
    const bool held = until();
    if (!held || edge) h.tick();
    if (held) return true;
  }
  return false;
}

// Clocks with the outputs ready and nothing offered until DONE (or `limit` clocks).
bool wait_done(AxiHost& h, int limit) {
  return clock_until(h, nullptr, true, true, limit, [&] { return h.watch().done; }, false);
}

// The frame through the shell, then the counters against the BFMs' counts.
void frame(AxiHost& h, const sim::FrameSchedule& f, const ref::ModelScene& m,
           const sim::CosimOptions& o, const char* label) {
  sim::Scoreboard sb(f, m, 4);
  const sim::CosimStats st = sim::cosim_frame(h, f, sb, o);
  for (const auto& r : sb.reports()) std::printf("FAILURE %s\n", r.c_str());
  expect(sb.ok() && !st.timed_out,
         fmt::format("{}: {} item and {} pixel mismatches, {} of {} results", label,
                     sb.item_mismatches(), sb.pixel_mismatches(), sb.results(), f.items.size()));
  expect(wait_done(h, 1000), fmt::format("{}: no DONE (irq_o) after the last pixel", label));
  const AxiHost::FrameWatch w = h.watch();
  const std::uint32_t status = h.read(RPU_AXI_STATUS);
  expect(RPU_AXI_FIELD(status, RPU_AXI_STATUS_DONE) == 1 &&
             RPU_AXI_FIELD(status, RPU_AXI_STATUS_BUSY) == 0,
         fmt::format("{}: STATUS {:#x} after the frame (DONE, not BUSY expected)", label, status));
  expect(h.irq(), fmt::format("{}: irq_o low with DONE and IRQ_EN", label));
  const std::uint64_t cycles = h.read(RPU_AXI_CYCLES_LO) |
                               (static_cast<std::uint64_t>(h.read(RPU_AXI_CYCLES_HI)) << 32);
  expect_eq(cycles, w.done_edge - w.start_edge, fmt::format("{}: CYCLES (START -> DONE)", label));
  const bool surfaces_built = m.params.surfaces;
  expect_eq(h.read(RPU_AXI_CURVE_IN), f.curve_items, fmt::format("{}: CURVE_IN", label));
  expect_eq(h.read(RPU_AXI_TEXTURE_IN), f.texture_items, fmt::format("{}: TEXTURE_IN", label));
  expect_eq(h.read(RPU_AXI_SURFACE_IN), f.surface_items, fmt::format("{}: SURFACE_IN", label));
  expect_eq(h.read(RPU_AXI_CURVE_OUT), f.curve_items, fmt::format("{}: CURVE_OUT", label));
  expect_eq(h.read(RPU_AXI_TEXTURE_OUT), f.texture_items, fmt::format("{}: TEXTURE_OUT", label));
  expect_eq(h.read(RPU_AXI_SURFACE_OUT), f.surface_items, fmt::format("{}: SURFACE_OUT", label));
  expect_eq(h.read(RPU_AXI_PIXELS_OUT), f.expected_pixels.size(),
            fmt::format("{}: PIXELS_OUT", label));
  std::uint64_t pixel_hits = 0;
  for (const auto& p : f.expected_pixels) pixel_hits += p.hit ? 1 : 0;
  expect_eq(h.read(RPU_AXI_HITS_OUT), pixel_hits, fmt::format("{}: HITS_OUT", label));
  expect_eq(h.read(RPU_AXI_IN_STALL), w.in_stalls, fmt::format("{}: IN_STALL", label));
  expect_eq(h.read(RPU_AXI_OUT_STALL), w.out_stalls, fmt::format("{}: OUT_STALL", label));
  expect_eq(h.read(RPU_AXI_FRAMES), 1, fmt::format("{}: FRAMES", label));
  const std::uint32_t want_err =
      !surfaces_built && f.surface_items ? RPU_AXI_ERROR_UNBUILT_KIND_MASK : 0u;
  expect_eq(err(h), want_err, fmt::format("{}: ERROR after the frame", label));
  for (const auto& e : h.protocol_errors()) expect(false, fmt::format("{}: {}", label, e));
  std::printf("%s: %zu items (%zu curve, %zu texture, %zu surface), %zu pixels (%llu hits) "
              "matched; %llu cycles START -> DONE (CYCLES agrees), %llu input and %llu output "
              "stall cycles; %d-bit item and pixel streams, %d-bit result stream\n",
              label, f.items.size(), f.curve_items, f.texture_items, f.surface_items,
              f.expected_pixels.size(), static_cast<unsigned long long>(pixel_hits),
              static_cast<unsigned long long>(cycles),
              static_cast<unsigned long long>(w.in_stalls),
              static_cast<unsigned long long>(w.out_stalls), h.axis_bits(), h.res_bits());
}

// One item driven by hand until taken (at most `limit` clocks); returns whether it was.
bool send(AxiHost& h, const sim::WorkItem& it, int limit = 200) {
  return clock_until(h, &it, false, false, limit, [&] { return h.item_ready(); });
}

void host(AxiHost& h, const sim::FrameSchedule& f, const ref::ModelScene& m,
          const sim::CosimOptions& o) {
  // Load the frame (reset, descriptors) without running it.
  sim::CosimOptions none = o;
  sim::FrameSchedule empty = f;
  empty.items.clear();
  empty.expected.clear();
  empty.expected_pixels.clear();
  {
    sim::Scoreboard sb(empty, m, 1);
    sim::cosim_frame(h, empty, sb, none);  // resets, loads, starts a frame of no items
  }
  // (a frame of no items never ends: only a TLAST item ends a frame; SOFT_RESET ends it)
  expect_eq(h.lite_write(RPU_AXI_CTRL, RPU_AXI_CTRL_SOFT_RESET_MASK), 0, "SOFT_RESET response");
  expect_eq(h.read(RPU_AXI_STATUS), 0, "STATUS after SOFT_RESET");

  // The identification block.
  const std::uint32_t kinds = h.read(RPU_AXI_BUILD_KINDS);
  expect_eq(RPU_AXI_FIELD(kinds, RPU_AXI_BUILD_KINDS_SURFACES), m.params.surfaces ? 1 : 0,
            "BUILD_KINDS.SURFACES");
  expect_eq(RPU_AXI_FIELD(kinds, RPU_AXI_BUILD_KINDS_UNROLLED), m.params.unrolled ? 1 : 0,
            "BUILD_KINDS.UNROLLED");
  const std::uint32_t ip = h.read(RPU_AXI_BUILD_IP);
  expect_eq(RPU_AXI_FIELD(ip, RPU_AXI_BUILD_IP_N), static_cast<unsigned>(m.params.n), "BUILD_IP.N");
  expect_eq(RPU_AXI_FIELD(ip, RPU_AXI_BUILD_IP_N1), static_cast<unsigned>(m.params.n1),
            "BUILD_IP.N1");
  const std::uint32_t w0 = h.read(RPU_AXI_BUILD_W0);
  expect_eq(RPU_AXI_FIELD(w0, RPU_AXI_BUILD_W0_COORD_W), static_cast<unsigned>(m.params.coord_w),
            "BUILD_W0.COORD_W");
  const sim::TopWidths tw(m.params);
  const std::uint32_t d0 = h.read(RPU_AXI_DESC_W0);
  expect_eq(RPU_AXI_FIELD(d0, RPU_AXI_DESC_W0_SEG_W), static_cast<unsigned>(tw.SegW),
            "DESC_W0.SEG_W");
  expect_eq(RPU_AXI_FIELD(d0, RPU_AXI_DESC_W0_CAM_W), static_cast<unsigned>(tw.CamW),
            "DESC_W0.CAM_W");
  const std::uint32_t words = RPU_AXI_FIELD(h.read(RPU_AXI_DESC_W1), RPU_AXI_DESC_W1_WORDS);
  expect_eq(words, static_cast<unsigned>((std::max({tw.CamW, tw.SegW, tw.SurfDW}) + 31) / 32),
            "DESC_W1.WORDS");

  // Outside the map: DECERR and BAD_ADDR; read-only registers: SLVERR.
  std::uint32_t v = 0;
  clear_errors(h);
  expect_eq(h.lite_read(0x3F0, &v), 3, "read of unmapped 0x3F0");
  expect_eq(err(h), RPU_AXI_ERROR_BAD_ADDR_MASK, "ERROR after an unmapped read");
  clear_errors(h);
  expect_eq(h.lite_write(0x3F0, 1), 3, "write of unmapped 0x3F0");
  expect_eq(h.lite_write(RPU_AXI_DESC_DATA + 4 * words, 1), 3, "write past DESC_DATA's words");
  expect_eq(h.lite_read(RPU_AXI_DESC_DATA + 4 * words, &v), 3, "read past DESC_DATA's words");
  expect_eq(err(h), RPU_AXI_ERROR_BAD_ADDR_MASK, "ERROR after writes outside the map");
  clear_errors(h);
  expect_eq(h.lite_write(RPU_AXI_ID, 0), 2, "write to ID (read only)");
  expect_eq(h.lite_write(RPU_AXI_CYCLES_LO, 0), 2, "write to CYCLES_LO (read only)");
  expect_eq(h.read(RPU_AXI_ID), RPU_AXI_MAGIC, "ID after a write to it");
  expect_eq(err(h), RPU_AXI_ERROR_BAD_ADDR_MASK, "ERROR after writes to read-only registers");
  clear_errors(h);

  // The staging window: read back, byte strobes.
  expect_eq(h.lite_write(RPU_AXI_DESC_DATA + 4, 0x11223344u), 0, "DESC_DATA[1] write");
  expect_eq(h.lite_write(RPU_AXI_DESC_DATA + 4, 0xAABBCCDDu, 0x5), 0, "DESC_DATA[1] strobed");
  expect_eq(h.read(RPU_AXI_DESC_DATA + 4), 0x11BB33DDu, "DESC_DATA[1] after strobes 0101");

  // Commits outside a RAM: SLVERR, DESC_RANGE, nothing written.
  const auto commit = [&](unsigned target, unsigned addr) {
    return h.lite_write(RPU_AXI_DESC_COMMIT, (target << RPU_AXI_DESC_COMMIT_TARGET_LSB) |
                                                 (addr << RPU_AXI_DESC_COMMIT_ADDR_LSB));
  };
  expect_eq(commit(3, 0), 2, "DESC_COMMIT target 3");
  expect_eq(commit(1, 1u << sim::TopWidths::kSegAddrW), 2, "DESC_COMMIT segment past the RAM");
  expect_eq(commit(2, 1u << sim::TopWidths::kSurfAddrW), 2, "DESC_COMMIT surface past the RAM");
  expect_eq(commit(0, 1), 2, "DESC_COMMIT camera address 1");
  expect_eq(err(h), RPU_AXI_ERROR_DESC_RANGE_MASK, "ERROR after commits outside a RAM");
  clear_errors(h);

  // An item before START: taken, discarded, counted; no pixel comes.
  expect(send(h, f.items.front()), "an item before START is taken (TREADY) and discarded");
  expect(!clock_until(h, nullptr, true, true, 2000,
                      [&] { return h.pix_valid() || h.res_valid(); }, false),
         "a pixel or result from a discarded item");
  expect_eq(h.read(RPU_AXI_DISCARDED), 1, "DISCARDED after an item before START");
  expect_eq(err(h), RPU_AXI_ERROR_ITEM_IDLE_MASK, "ERROR after an item before START");
  clear_errors(h);

  // START, then START again and a commit during the frame: refused, the descriptors unchanged.
  // The frame: the schedule's first pixel, its last item sent with TLAST; then SOFT_RESET in
  // the middle of a second frame, and the whole frame after it (the descriptors survive).
  sim::FrameSchedule one = f;
  one.items.clear();
  one.expected.clear();
  one.expected_pixels.clear();
  one.curve_items = one.texture_items = one.surface_items = 0;
  for (std::size_t k = 0; k < f.items.size(); ++k) {
    if (f.items[k].i != f.items.front().i || f.items[k].j != f.items.front().j) continue;
    one.items.push_back(f.items[k]);
    one.expected.push_back(f.expected[k]);
    one.count(f.items[k]);
  }
  one.expected_pixels.push_back(f.expected_pixels.front());
  sim::CosimOptions again = o;
  again.load = false;
  {
    expect_eq(h.lite_write(RPU_AXI_CTRL, RPU_AXI_CTRL_START_MASK | RPU_AXI_CTRL_IRQ_EN_MASK), 0,
              "START");
    expect_eq(h.lite_write(RPU_AXI_CTRL, RPU_AXI_CTRL_START_MASK), 0, "START while busy");
    expect_eq(commit(1, 0), 2, "DESC_COMMIT during a frame");
    expect_eq(err(h), RPU_AXI_ERROR_START_BUSY_MASK | RPU_AXI_ERROR_DESC_BUSY_MASK,
              "ERROR after START and DESC_COMMIT during a frame");
    clear_errors(h);
    expect_eq(h.lite_write(RPU_AXI_CTRL, RPU_AXI_CTRL_SOFT_RESET_MASK), 0, "SOFT_RESET");
    expect_eq(h.read(RPU_AXI_STATUS), 0, "STATUS after SOFT_RESET in a frame");
    sim::Scoreboard sb(one, m, 4);
    const sim::CosimStats st = sim::cosim_frame(h, one, sb, again);
    for (const auto& r : sb.reports()) std::printf("FAILURE %s\n", r.c_str());
    expect(sb.ok() && !st.timed_out, "the first pixel's frame after SOFT_RESET");
    expect(wait_done(h, 1000), "DONE after the first pixel's frame");
  }
  // TLAST on an item that is not its pixel's last: the pixel ends with it (one pixel out, with
  // TLAST), BAD_LAST is set, the frame is DONE.
  if (one.items.size() > 1) {
    sim::FrameSchedule cut = one;
    cut.items.resize(1);
    cut.expected.resize(1);
    cut.items[0].last = false;  // sent as is; TLAST on it (the frame's only item)
    h.begin_frame(1, 1, o.seed, 100);
    expect(send(h, cut.items[0]), "the BAD_LAST item taken");
    expect(clock_until(h, nullptr, true, true, 20000, [&] { return h.pix_valid(); }),
           "a pixel for a frame ended by TLAST on a non-last item");
    expect(wait_done(h, 1000), "DONE after a frame ended by TLAST on a non-last item");
    expect_eq(err(h), RPU_AXI_ERROR_BAD_LAST_MASK, "ERROR after TLAST on a non-last item");
    clear_errors(h);
  } else {
    std::printf("(the first pixel has one item: the BAD_LAST case needs two; skipped)\n");
  }
  // SOFT_RESET while a pixel waits on m_pix (TREADY low): it is still handed out (the AXI4-Stream
  // rule), counted in no frame, and the next frame ends (DONE) as if it had not been there.
  {
    h.begin_frame(one.items.size(), 1, o.seed, 100);
    for (const auto& it : one.items)
      expect(clock_until(h, &it, true, false, 2000, [&] { return h.item_ready(); }),
             "an item of the frame SOFT_RESET interrupts");
    expect(clock_until(h, nullptr, true, false, 20000, [&] { return h.pix_offered(); }, false),
           "a pixel waiting on m_pix before SOFT_RESET");
    expect_eq(h.lite_write(RPU_AXI_CTRL, RPU_AXI_CTRL_SOFT_RESET_MASK), 0, "SOFT_RESET, pixel held");
    // Past the soft reset's 4 cycles, the pixel still held; then taken.
    expect(!clock_until(h, nullptr, true, false, 8, [&] { return !h.pix_offered(); }, false),
           "the held pixel withdrawn by SOFT_RESET");
    expect(clock_until(h, nullptr, true, true, 100, [&] { return h.pix_valid(); }),
           "the held pixel handed out after SOFT_RESET");
    expect_eq(h.read(RPU_AXI_PIXELS_OUT), 0, "PIXELS_OUT after the held pixel left");
  }
  // The whole frame after all that, the descriptors as loaded at the start.
  sim::Scoreboard sb(f, m, 4);
  const sim::CosimStats st = sim::cosim_frame(h, f, sb, again);
  for (const auto& r : sb.reports()) std::printf("FAILURE %s\n", r.c_str());
  expect(sb.ok() && !st.timed_out, "the whole frame after the bad host's session");
  expect(wait_done(h, 1000), "DONE after the whole frame after the bad host's session");
  expect_eq(h.read(RPU_AXI_PIXELS_OUT), f.expected_pixels.size(),
            "PIXELS_OUT of the whole frame after the bad host's session");
  for (const auto& e : h.protocol_errors()) expect(false, e);
  std::printf("host: %zu-item frame still right after every bad access\n", f.items.size());
}

}  // namespace

int main(int argc, char** argv) {
  sim::TopBench b;
  b.config = "n16_n1_2_iterative_axi";
  b.size = 16;
  if (!sim::top_bench(argc, argv, true, b)) return 1;
  const std::uint64_t seed = sim::test_seed("tb_rpu_axi");
  const std::string& mode = b.mode;
  const sim::RtlConfig* cfg = b.cfg;
  const ref::ModelScene& m = b.model;
  const sim::FrameSchedule& f = b.frame;
  sim::CosimOptions o;
  o.seed = seed;
  o.valid_pct = 70;
  o.res_ready_pct = 60;
  o.pix_ready_pct = 50;
  o.stall_phases = true;
  auto ports = cfg->make(b.x_seed);
  auto* h = dynamic_cast<AxiHost*>(ports.get());
  if (!h) {
    std::printf("FAILURE: %s is not an AXI configuration\n", cfg->name.c_str());
    return 1;
  }
  try {
    if (mode == "frame") {
      frame(*h, f, m, o, fmt::format("rpu_axi frame ({}, {} {}x{})", cfg->name, b.scene, b.size,
                                     b.size).c_str());
    } else if (mode == "host") {
      host(*h, f, m, o);
    } else {
      std::printf("FAILURE: unknown mode %s\n", mode.c_str());
      return 1;
    }
  } catch (const std::exception& e) {
    std::printf("FAILURE: %s\n", e.what());
    return 1;
  }
  if (failures) {
    std::printf("FAILURE: %d checks failed\n", failures);
    return 1;
  }
  return 0;
}
