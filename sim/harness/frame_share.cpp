#include "frame_share.h"

#include <algorithm>

#include "common/error.h"

namespace rpu::sim {

std::vector<FrameShare> split_frame(const FrameSchedule& f, int count) {
  if (count < 1) throw Error("split_frame", "the share count must be at least 1");
  const std::size_t n = f.items.size();
  std::vector<FrameShare> out(static_cast<std::size_t>(count));
  std::size_t item = 0, pixel = 0;
  for (int k = 0; k < count; ++k) {
    FrameShare& s = out[static_cast<std::size_t>(k)];
    s.index = k;
    s.count = count;
    s.first_item = item;
    s.first_pixel = pixel;
    // Items up to the share's even cut, then on to the end of the pixel the cut falls in.
    const std::size_t cut = k + 1 == count ? n : n * static_cast<std::size_t>(k + 1) /
                                                     static_cast<std::size_t>(count);
    while (item < n && (item < cut || (item > 0 && !f.items[item - 1].last))) {
      if (f.items[item].last) ++pixel;
      ++item;
    }
    s.end_item = item;
    s.end_pixel = pixel;
  }
  return out;
}

FrameSchedule share_schedule(const FrameSchedule& f, const FrameShare& s) {
  if (s.end_item > f.items.size() || s.first_item > s.end_item ||
      s.end_pixel > f.expected_pixels.size() || s.first_pixel > s.end_pixel)
    throw Error("share_schedule", "the share lies outside the frame");
  FrameSchedule out;
  out.params = f.params;
  out.camera = f.camera;
  out.segments = f.segments;
  out.surfaces = f.surfaces;
  out.width = f.width;
  out.height = f.height;
  const auto first = static_cast<std::ptrdiff_t>(s.first_item);
  const auto end = static_cast<std::ptrdiff_t>(s.end_item);
  out.items.assign(f.items.begin() + first, f.items.begin() + end);
  if (!f.expected.empty())
    out.expected.assign(f.expected.begin() + first, f.expected.begin() + end);
  out.expected_pixels.assign(f.expected_pixels.begin() + static_cast<std::ptrdiff_t>(s.first_pixel),
                             f.expected_pixels.begin() + static_cast<std::ptrdiff_t>(s.end_pixel));
  for (const WorkItem& it : out.items) out.count(it);
  return out;
}

std::uint64_t schedule_digest(const FrameSchedule& f) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](std::uint64_t v) {
    for (int b = 0; b < 8; ++b) {
      h ^= (v >> (8 * b)) & 0xffu;
      h *= 1099511628211ull;
    }
  };
  for (const ref::HwParamInfo& d : ref::hw_param_table()) mix(static_cast<std::uint64_t>(d.get(f.params)));
  mix(static_cast<std::uint64_t>(f.width));
  mix(static_cast<std::uint64_t>(f.height));
  const auto bits = [&mix](const Bits& b) {
    mix(static_cast<std::uint64_t>(b.width()));
    for (auto w : b.words()) mix(w);
  };
  bits(f.camera);
  mix(f.segments.size());
  for (const Bits& b : f.segments) bits(b);
  mix(f.surfaces.size());
  for (const Bits& b : f.surfaces) bits(b);
  mix(f.items.size());
  for (const WorkItem& it : f.items) {
    mix(it.id);
    mix(static_cast<std::uint64_t>(it.i) << 32 | static_cast<std::uint32_t>(it.j));
    mix(static_cast<std::uint64_t>(it.seg) << 5 | static_cast<std::uint64_t>(it.piece) << 3 |
        (it.surface ? 4u : 0u) | (it.last ? 1u : 0u) | (it.texture ? 2u : 0u));
  }
  return h;
}

}  // namespace rpu::sim
