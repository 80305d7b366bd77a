// Images carry exact colours (SCENE.md): the background where nothing is hit, the primitive's
// colour otherwise, in every format.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "common/error.h"
#include "image/frame.h"
#include "image/image_io.h"

namespace rpu::image {
namespace {

TEST(ImageIo, ExactColoursInEveryFormat) {
  Frame f(5, 3);
  f.primitive[f.index(1, 0)] = 0;
  f.primitive[f.index(4, 2)] = 1;
  const std::vector<scene::Color> colors = {{1.0, 0.8, 0.2}, {0.5, 0.5, 0.5}};
  const scene::Color background = {0.05, 0.15, 0.05};
  const auto rgb = to_rgb(f, colors, background);
  const auto dir = std::filesystem::temp_directory_path() / "rpu_test_image";
  std::filesystem::create_directories(dir);
  for (const char* ext : {".png", ".ppm", ".exr", ".tif"}) {
    const std::string path = (dir / (std::string("frame") + ext)).string();
    write_rgb(path, f.width, f.height, rgb);
    int w = 0, h = 0;
    const auto back = read_rgb(path, w, h);
    ASSERT_EQ(w, 5);
    ASSERT_EQ(h, 3);
    const bool is_float = std::string(ext) == ".exr";
    for (size_t k = 0; k < rgb.size(); ++k) {
      // 8-bit formats hold round(255·c) exactly; float formats hold c itself.
      const float expected = is_float ? rgb[k] : std::round(rgb[k] * 255.0f) / 255.0f;
      EXPECT_FLOAT_EQ(back[k], expected) << ext << " value " << k;
    }
  }
}

TEST(ImageIo, BadPathsAreReported) {
  EXPECT_THROW(check_writable("image.nosuchformat"), rpu::Error);
  EXPECT_THROW(check_writable("/no/such/directory/image.png"), rpu::Error);
  EXPECT_NO_THROW(check_writable("image.png"));
}

}  // namespace
}  // namespace rpu::image
