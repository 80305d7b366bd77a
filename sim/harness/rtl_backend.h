// `rpu render --backend rtl`: a frame through the Verilated rpu_top, every work item and every
// pixel checked against the reference model. The C++ harness runs in this process; the
// SystemC harness is the executable rpu_sc beside it (same schedule, same checker).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cosim.h"
#include "image/frame.h"
#include "model/descriptors.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"

namespace rpu::sim {

struct RtlOptions {
  ref::RefOptions ref;          // threads, binning, grid (the schedule is render_ref's)
  bool systemc = false;         // run the SystemC harness (rpu_sc) instead of the C++ one
  std::string sc_exe;           // rpu_sc; empty: beside the running executable
  std::string external_exe;     // a cosim_<name> executable (rpu sweep's on-demand builds)
  CosimOptions cosim;           // handshake patterns
  bool axi = false;             // rpu_top inside its AXI shell rpu_axi (a configuration built
                                // with AXI; docs/axi.md)
  int fault = 0;                // the fault-injected build's fault (tests of the checker):
                                // 0 none, 1 argmin-tie, 2 far-hit (rtl_fault_names())
  std::uint64_t x_seed = 0;     // random initial register values (0: Verilator's default)
  int max_reports = 8;          // mismatches reported in full
  std::optional<std::pair<int, int>> trace_pixel;  // re-run this pixel with an FST waveform
  std::string trace_path = "trace.fst";
  // Frame-parallel co-simulation (frame_share.h): the frame's work items in `jobs` contiguous
  // shares, each on its own Verilated instance (or harness process) and thread.
  int jobs = 1;
  // Only share I of N (`--shard I/N`), its recorded streams written to shard_out.
  std::optional<std::pair<int, int>> shard;
  std::string shard_out;
  // Check and assemble these shard files (`--merge-shards`) instead of simulating.
  std::vector<std::string> merge_shards;
};

struct RtlRender {
  image::Frame frame;           // from rpu_top's pixel stream (every share's)
  CosimStats stats;             // summed over the instances (sim_seconds: the wall time)
  std::vector<CosimStats> instances;  // per instance (share), in frame order
  std::uint64_t frame_cycles = 0;     // the longest instance: the frame on N parallel units
  std::string config;           // the Verilated configuration's name
  std::string harness;          // "c++" or "systemc"
  std::size_t item_mismatches = 0, pixel_mismatches = 0;
  std::vector<std::string> reports;     // mismatch records, the model's stages included
  std::pair<int, int> first_bad{-1, -1};
  std::string trace_log;        // what --trace-pixel did
  bool ok = false;              // every item and every pixel equal to the model
};

RtlRender render_rtl(const scene::CompiledScene& sc, const ref::ModelScene& m,
                     const RtlOptions& o);

// The Verilated configurations of this build, one line each (for errors and `rpu config`).
std::string describe_rtl_configs();

}  // namespace rpu::sim
