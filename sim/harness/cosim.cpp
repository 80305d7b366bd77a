#include "cosim.h"

#include <chrono>
#include <random>

#include <fmt/format.h>

#include "model/surface/rpu_surface_latency.h"

namespace rpu::sim {

namespace {

void load(TopPorts& top, const FrameSchedule& f) {
  top.reset(4);
  top.write_camera(f.camera);
  for (size_t k = 0; k < f.segments.size(); ++k)
    top.write_segment(static_cast<std::uint32_t>(k), f.segments[k]);
  for (size_t k = 0; k < f.surfaces.size(); ++k)
    top.write_surface(static_cast<std::uint32_t>(k), f.surfaces[k]);
  top.reset(4);
}

}  // namespace

std::uint64_t default_cycle_limit(const FrameSchedule& f) {
  // A surface piece holds a ring slot for P passes (142 at the defaults), so surface items get
  // twice that each, and twice the surface path's latency, on top of the general allowance.
  const std::uint64_t surface_allowance =
      f.surface_items == 0
          ? 0
          : 2 * static_cast<std::uint64_t>(
                    ref::surface_ip_passes(f.params, TopWidths::kIndicators)) * f.surface_items +
                2 * static_cast<std::uint64_t>(
                        ref::surface_top_latency(f.params, TopWidths::kIndicators));
  return 100 * f.items.size() + surface_allowance + 100000;
}

CosimStats cosim_frame(TopPorts& top, const FrameSchedule& f, ResultSink& sb,
                       const CosimOptions& o) {
  CosimStats st;
  if (o.load) load(top, f);
  st.load_cycles = 1 + f.segments.size() + f.surfaces.size();
  st.items = f.items.size();
  st.curve_items = f.curve_items;
  st.texture_items = f.texture_items;
  st.surface_items = f.surface_items;
  top.begin_frame(f.items.size(), f.expected_pixels.size(), o.seed, o.valid_pct);
  std::mt19937_64 rng(o.seed);
  const auto pct = [&](int p) { return p >= 100 || static_cast<int>(rng() % 100) < p; };
  const std::uint64_t limit = o.max_cycles ? o.max_cycles : default_cycle_limit(f);
  const auto t0 = std::chrono::steady_clock::now();
  size_t next = 0;
  std::int64_t first_accept = -1, first_result = -1;
  bool stall = false;
  std::uint64_t cycle = 0;
  while (!sb.done()) {
    if (o.stall_phases && cycle % 500 == 0) stall = !stall && rng() % 3 == 0;
    // An AXI source keeps offering what it offered: axi_ports.h draws the gaps itself.
    const bool offer = next < f.items.size() && (top.axi() || pct(o.valid_pct));
    const bool res_ready = !stall && pct(o.res_ready_pct);
    const bool pix_ready = !stall && pct(o.pix_ready_pct);
    top.drive(offer ? &f.items[next] : nullptr, res_ready, pix_ready);
    const bool accepted = offer && top.item_ready();
    if (offer && !accepted) ++st.stall_cycles;
    if (top.res_valid() && res_ready) {
      if (first_result < 0) first_result = static_cast<std::int64_t>(cycle);
      sb.on_result(top.result());
    }
    if (top.pix_valid() && pix_ready) sb.on_pixel(top.pixel());
    top.tick();
    ++cycle;
    if (accepted) {
      if (first_accept < 0) first_accept = static_cast<std::int64_t>(cycle - 1);
      ++next;
    }
    if (cycle >= limit) {
      st.timed_out = true;
      sb.note(fmt::format("TIMEOUT: {} cycles, {} of {} items accepted, {} of {} results and {} "
                          "of {} pixels received", cycle, next, f.items.size(), sb.results(),
                          f.items.size(), sb.pixels(), f.expected_pixels.size()));
      break;
    }
  }
  st.sim_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  top.finish();
  st.cycles = cycle;
  st.pixels = sb.pixels();
  st.hits = sb.hits();
  if (first_result >= 0 && first_accept >= 0)
    st.latency_cycles = static_cast<std::uint64_t>(first_result - first_accept);
  return st;
}

bool trace_pixel(TopPorts& top, const FrameSchedule& f, const ref::ModelScene& m, int i, int j,
                 const std::string& fst_path, std::string* log) {
  FrameSchedule one = f;
  one.items.clear();
  one.expected.clear();
  one.expected_pixels.clear();
  one.curve_items = one.texture_items = one.surface_items = 0;
  for (size_t k = 0; k < f.items.size(); ++k) {
    if (f.items[k].i != i || f.items[k].j != j) continue;
    one.items.push_back(f.items[k]);
    one.expected.push_back(f.expected[k]);
    one.count(f.items[k]);
  }
  if (one.items.empty()) return false;
  for (const PixelResult& p : f.expected_pixels)
    if (p.i == i && p.j == j) one.expected_pixels.push_back(p);
  top.trace(fst_path);
  Scoreboard sb(one, m, 1000);
  const CosimStats st = cosim_frame(top, one, sb);
  if (log) {
    *log = fmt::format("pixel ({},{}): {} work items, {} cycles, {} item and {} pixel "
                       "mismatches; waveform {}\n", i, j, one.items.size(), st.cycles,
                       sb.item_mismatches(), sb.pixel_mismatches(), fst_path);
    for (size_t k = 0; k < one.items.size(); ++k)
      *log += fmt::format("  item {}: expected {}\n{}", one.items[k].id,
                          one.expected[k].describe(), explain_item(m, one.items[k]));
    for (const auto& r : sb.reports()) *log += r + "\n";
  }
  return true;
}

}  // namespace rpu::sim
