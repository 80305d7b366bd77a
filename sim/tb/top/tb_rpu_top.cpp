// rpu_top against the model through the co-simulation harness (sim/harness): every field of
// every work item's result and every pixel of the pixel stream. Modes (first argument):
//   frame        a demo frame's work items (curves, textures, surface pieces), random valid and
//                ready
//   throughput   10,000 work items, input always valid, outputs always ready: counts cycles,
//                checks cycles ≤ items + latency + 8 (unrolled), K·curve items ≤ cycles ≤
//                K·curve + texture items + latency + 8 (iterative), reports latency and rate
//   backpressure random valid and ready with long stalls: the in-order scoreboard proves
//                nothing is lost, duplicated or reordered
// Options: --scene NAME[+NAME...] (default curve12; several: the first one's camera, all their
// primitives), --size N (square side, default 64), --x-seed S
// (Verilator's random initial values; every seed must give the same results), --config NAME
// (a Verilated configuration of rpu_rtl, default n16_n1_2_unrolled).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cosim.h"
#include "tb_base.h"
#include "tb_demo_frame.h"
#include "top_ports.h"

namespace {

// `count` copies of the frame's items, each its own pixel (so the pixel stream is checked too).
sim::FrameSchedule repeat_items(const sim::FrameSchedule& f, std::size_t count) {
  sim::FrameSchedule r = f;
  r.items.clear();
  r.expected.clear();
  r.expected_pixels.clear();
  r.curve_items = r.texture_items = r.surface_items = 0;
  for (std::size_t k = 0; k < count; ++k) {
    sim::WorkItem it = f.items[k % f.items.size()];
    sim::ItemResult e = f.expected[k % f.items.size()];
    it.id = e.id = static_cast<std::uint32_t>(k);
    it.last = e.last = true;
    r.count(it);
    r.items.push_back(it);
    r.expected.push_back(e);
    r.expected_pixels.push_back({e.i, e.j, e.hit, e.hit ? e.depth : 0, e.hit ? e.primitive : 0});
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  sim::TopBench b;
  b.config = "n16_n1_2_unrolled";
  if (!sim::top_bench(argc, argv, false, b)) return 1;
  const std::uint64_t seed = sim::test_seed("tb_rpu_top");
  const std::string& mode = b.mode;
  const std::string& scene_name = b.scene;
  const int size = b.size;
  const sim::RtlConfig* cfg = b.cfg;
  const ref::ModelScene& m = b.model;
  sim::FrameSchedule f = b.frame;
  if (mode == "throughput") f = repeat_items(f, 10000);

  sim::CosimOptions o;
  o.seed = seed;
  if (mode == "frame") o.valid_pct = o.res_ready_pct = o.pix_ready_pct = 80;
  else if (mode == "backpressure") {
    o.valid_pct = 50;
    o.res_ready_pct = 30;
    o.pix_ready_pct = 60;
    o.stall_phases = true;
  } else if (mode != "throughput") {
    std::printf("FAILURE: unknown mode %s\n", mode.c_str());
    return 1;
  }
  auto top = cfg->make(b.x_seed);
  sim::Scoreboard sb(f, m, 4);
  const sim::CosimStats st = sim::cosim_frame(*top, f, sb, o);
  for (const auto& r : sb.reports()) std::printf("FAILURE %s\n", r.c_str());
  if (!sb.ok() || st.timed_out) {
    std::printf("FAILURE: %zu item and %zu pixel mismatches, %zu of %zu results\n",
                sb.item_mismatches(), sb.pixel_mismatches(), sb.results(), f.items.size());
    return 1;
  }
  const auto ull = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  std::printf("rpu_top %s (%s), %s %dx%d: matched %llu items (%llu curve, %llu texture, %llu "
              "surface, %llu hits) and %llu pixels in %llu cycles, latency %llu cycles, %.3f "
              "items/cycle, %llu input stall cycles\n",
              mode.c_str(), cfg->name.c_str(), scene_name.c_str(), size, size, ull(st.items),
              ull(st.curve_items), ull(st.texture_items), ull(st.surface_items), ull(st.hits),
              ull(st.pixels),
              ull(st.cycles), ull(st.latency_cycles), st.items_per_cycle(), ull(st.stall_cycles));
  if (mode != "throughput") return 0;
  if (cfg->params.unrolled) {
    if (st.cycles > st.items + st.latency_cycles + 8) {
      std::printf("FAILURE: %llu cycles for %llu items exceeds items + latency (%llu) + 8\n",
                  ull(st.cycles), ull(st.items), ull(st.latency_cycles));
      return 1;
    }
    return 0;
  }
  // Iterative: the one step unit takes a curve item every K cycles (no faster, and no slower
  // but for the pipeline's latency); a texture item passes in one cycle. Surface pieces are paced
  // by their search ring (docs/rtl.md), not bounded here.
  if (st.surface_items != 0) {
    std::printf("throughput bound not checked: the frame has surface pieces\n");
    return 0;
  }
  const std::uint64_t k = static_cast<std::uint64_t>(cfg->params.K());
  const std::uint64_t least = k * st.curve_items;
  const std::uint64_t most = least + st.texture_items + st.latency_cycles + 8;
  if (st.cycles < least || st.cycles > most) {
    std::printf("FAILURE: %llu cycles for %llu curve and %llu texture items, outside [K·curve = "
                "%llu, K·curve + texture + latency (%llu) + 8 = %llu] (K = %llu)\n",
                ull(st.cycles), ull(st.curve_items), ull(st.texture_items), ull(least),
                ull(st.latency_cycles), ull(most), ull(k));
    return 1;
  }
  std::printf("iterative throughput: %llu cycles within [%llu, %llu] (K = %llu)\n",
              ull(st.cycles), ull(least), ull(most), ull(k));
  return 0;
}
