// The exchange between `rpu` and the SystemC harness executable (rpu_sc): a job file (the
// descriptors and the work items) and a stream file (every result and pixel record in arrival
// order, with the cycle counts). Binary, little-endian, versioned; read errors name the file.
#pragma once

#include <string>
#include <vector>

#include "cosim.h"
#include "frame_schedule.h"

namespace rpu::sim {

struct StreamRecord {
  std::vector<ItemResult> results;
  std::vector<PixelResult> pixels;
  CosimStats stats;
};

void write_job(const std::string& path, const FrameSchedule& f);
// Reads camera, segments, items, width, height and params (expected values are not stored).
FrameSchedule read_job(const std::string& path);
void write_streams(const std::string& path, const StreamRecord& r);
StreamRecord read_streams(const std::string& path);

}  // namespace rpu::sim
