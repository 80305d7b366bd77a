// Cycle-by-cycle co-simulation of rpu_top over a frame: load the descriptors, stream the work
// items (valid/ready), drain the result and pixel streams into the scoreboard, count cycles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frame_schedule.h"
#include "scoreboard.h"
#include "top_ports.h"

namespace rpu::sim {

struct CosimOptions {
  // Handshake patterns: the chance (percent) that the source offers an item in a cycle, and
  // that the result and pixel sinks are ready. 100/100/100 measures the hardware's own rate.
  int valid_pct = 100, res_ready_pct = 100, pix_ready_pct = 100;
  bool stall_phases = false;      // also long stretches with both sinks stalled
  std::uint64_t seed = 1;         // of the handshake patterns
  bool load = true;               // reset and load the descriptors first (false: the unit
                                  // holds them already)
  std::uint64_t max_cycles = 0;   // 0: 100 × items + 100,000, and 2 × P per surface piece plus
                                  // twice the surface latency (a hang is reported, never waited out)
};

struct CosimStats {
  std::uint64_t cycles = 0;          // reset released → last pixel taken
  std::uint64_t load_cycles = 0;     // descriptor writes (camera, segments, surfaces)
  std::uint64_t items = 0, curve_items = 0, texture_items = 0, surface_items = 0;
  std::uint64_t pixels = 0, hits = 0;
  std::uint64_t latency_cycles = 0;  // first item accepted → its result on the port
  std::uint64_t stall_cycles = 0;    // an item offered but not accepted
  double sim_seconds = 0;            // wall time of the cycle loop
  bool timed_out = false;
  double items_per_cycle() const { return cycles ? static_cast<double>(items) / cycles : 0; }
};

// The cycles after which a frame counts as hung: 100 per item + 100,000, and per surface piece
// twice the search ring's passes plus twice the surface path's latency.
std::uint64_t default_cycle_limit(const FrameSchedule& f);

// Loads the descriptors into `top` (after a reset) and runs every item of `f`.
CosimStats cosim_frame(TopPorts& top, const FrameSchedule& f, ResultSink& sb,
                       const CosimOptions& o = {});

// Only the work items of pixel (i, j), with an FST waveform (the configuration must be
// traceable); returns false when the pixel has no work items.
bool trace_pixel(TopPorts& top, const FrameSchedule& f, const ref::ModelScene& m, int i, int j,
                 const std::string& fst_path, std::string* log);

}  // namespace rpu::sim
