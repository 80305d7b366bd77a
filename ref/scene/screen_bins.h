// Screen-space binning of interpolation spheres (the seed's classification, for curves): each
// tile of the image lists the curve segments whose interpolation sphere can project into it.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/camera.h"

namespace rpu::scene {

struct CompiledSegment;

// Conservative pixel rectangle [i0, i1] × [j0, j1] covered by the projection of the sphere
// (centre, radius), grown by one pixel. Returns false when the sphere is entirely behind the
// eye plane; a sphere that reaches the eye plane (or holds the eye) covers the whole image.
bool sphere_screen_bounds(const CameraFrame& cam, const Vec3& centre, double radius, int& i0,
                          int& i1, int& j0, int& j1);

class ScreenBins {
 public:
  // `tile` is the tile side in pixels. With `enabled` false every tile lists every segment
  // (for tests proving that binning never changes the image).
  ScreenBins(const CameraFrame& cam, const std::vector<CompiledSegment>& segments, int tile = 8,
             bool enabled = true);

  struct Span {
    const std::uint32_t* begin_;
    const std::uint32_t* end_;
    const std::uint32_t* begin() const { return begin_; }
    const std::uint32_t* end() const { return end_; }
    size_t size() const { return static_cast<size_t>(end_ - begin_); }
  };
  // Segments to test for pixel (i, j).
  Span segments_for_pixel(int i, int j) const {
    const size_t k = static_cast<size_t>(j / tile_) * tiles_x_ + static_cast<size_t>(i / tile_);
    return {items_.data() + offsets_[k], items_.data() + offsets_[k + 1]};
  }
  size_t total_entries() const { return items_.size(); }

 private:
  int tile_, tiles_x_, tiles_y_;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> items_;
};

}  // namespace rpu::scene
