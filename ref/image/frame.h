// A rendered frame: per pixel, the primitive that won (or background) and its depth.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace rpu::image {

inline constexpr std::int32_t kBackground = -1;

struct Frame {
  int width = 0, height = 0;
  std::vector<std::int32_t> primitive;  // id of the winning primitive, kBackground if none
  std::vector<double> depth;            // depth c of the winning hit (0 for background)

  Frame() = default;
  Frame(int w, int h)
      : width(w), height(h),
        primitive(static_cast<size_t>(w) * h, kBackground),
        depth(static_cast<size_t>(w) * h, 0.0) {}

  size_t index(int i, int j) const { return static_cast<size_t>(j) * width + i; }
  size_t hit_pixels() const;
};

// Pixels whose primitive differs between two frames of the same size.
size_t count_differing_pixels(const Frame& a, const Frame& b);

// Linear RGB image (row-major, 3 floats per pixel) with exact colours: background where no hit,
// otherwise the primitive's colour.
std::vector<float> to_rgb(const Frame& frame, const std::vector<scene::Color>& colors,
                          const scene::Color& background);

}  // namespace rpu::image
