#include "image/frame.h"

#include <stdexcept>

namespace rpu::image {

size_t Frame::hit_pixels() const {
  size_t n = 0;
  for (auto p : primitive) n += p != kBackground;
  return n;
}

size_t count_differing_pixels(const Frame& a, const Frame& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("count_differing_pixels: frames differ in size");
  size_t n = 0;
  for (size_t k = 0; k < a.primitive.size(); ++k) n += a.primitive[k] != b.primitive[k];
  return n;
}

std::vector<float> to_rgb(const Frame& frame, const std::vector<scene::Color>& colors,
                          const scene::Color& background) {
  std::vector<float> rgb(frame.primitive.size() * 3);
  for (size_t k = 0; k < frame.primitive.size(); ++k) {
    const auto id = frame.primitive[k];
    const scene::Color& c = id == kBackground ? background : colors.at(static_cast<size_t>(id));
    for (int ch = 0; ch < 3; ++ch) rgb[3 * k + ch] = static_cast<float>(c[ch]);
  }
  return rgb;
}

}  // namespace rpu::image
