// Frame-parallel co-simulation (docs/cosim.md, "Frame-parallel co-simulation"): a frame's work
// items cut into N contiguous shares, each run by its own Verilated instance (`--jobs N`) or by a
// process of its own (`--shard I/N`), as N units on one device would each take a share of the
// frame. Shares are cut between pixels, so each pixel's items and its resolve stay in one share.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "frame_schedule.h"

namespace rpu::sim {

struct FrameShare {
  int index = 0, count = 1;
  std::size_t first_item = 0, end_item = 0;    // items[first_item, end_item)
  std::size_t first_pixel = 0, end_pixel = 0;  // expected_pixels[first_pixel, end_pixel)
};

// `count` shares (1 ≤ count) with about equal numbers of work items; each ends after a pixel's
// last item. A share may be empty when the frame has fewer pixels with work than shares.
std::vector<FrameShare> split_frame(const FrameSchedule& f, int count);

// The share as a frame of its own: the same parameters and descriptors, its items (with their
// frame-wide ids) and the model's results for them.
FrameSchedule share_schedule(const FrameSchedule& f, const FrameShare& s);

// A 64-bit FNV-1a digest of what the hardware is given (parameters, camera, segments, work
// items): a shard file carries it, so a merge with another scene or other flags is refused.
std::uint64_t schedule_digest(const FrameSchedule& f);

}  // namespace rpu::sim
