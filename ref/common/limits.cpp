#include "common/limits.h"

#include <fmt/format.h>

#include "common/error.h"

namespace rpu::limits {

void check_image_size(const std::string& where, long long width, long long height) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw Error(where, fmt::format("image size {}x{} is out of range: each side must be in "
                                   "[1, {}]", width, height, kMaxImageSide));
  if (width * height > kMaxImagePixels)
    throw Error(where, fmt::format("image size {}x{} is too large: {} pixels, at most {} "
                                   "allowed", width, height, width * height, kMaxImagePixels));
}

void check_threads(const std::string& where, long long threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw Error(where, fmt::format("must be in [0, {}] (0 = all cores), got {}", kMaxThreads,
                                   threads));
}

}  // namespace rpu::limits
