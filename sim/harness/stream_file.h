// The exchange between `rpu` and the SystemC harness executable (rpu_sc): a job file (the
// descriptors and the work items) and a stream file (every result and pixel record in arrival
// order, with the cycle counts). Binary, little-endian, versioned; read errors name the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cosim.h"
#include "frame_schedule.h"
#include "frame_share.h"

namespace rpu::sim {

struct StreamRecord {
  std::vector<ItemResult> results;
  std::vector<PixelResult> pixels;
  CosimStats stats;
};

// The job file's format: 2 carries every hardware parameter of the table by key (1, without a
// version, carried n ... ip by position). Also part of the names of the co-simulation
// executables `rpu sweep` builds (app/sweep_cosim_build.cpp).
inline constexpr std::uint32_t kJobFileVersion = 2;

void write_job(const std::string& path, const FrameSchedule& f);
// Reads camera, segments, items, width, height and params (expected values are not stored).
FrameSchedule read_job(const std::string& path);
void write_streams(const std::string& path, const StreamRecord& r);
StreamRecord read_streams(const std::string& path);

// A shard file (`rpu render --backend rtl --shard I/N`): one share's recorded streams, with the
// frame's digest (schedule_digest) and the share's place; `--merge-shards` reads them back.
struct ShardRecord {
  std::uint64_t digest = 0;
  FrameShare share;
  std::string config;  // the Verilated configuration or harness that ran it
  StreamRecord streams;
};
void write_shard(const std::string& path, const ShardRecord& r);
ShardRecord read_shard(const std::string& path);

}  // namespace rpu::sim
