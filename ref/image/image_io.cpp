#include "image/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "common/error.h"

namespace rpu::image {
namespace {

bool is_float_format(const std::string& ext) {
  return ext == ".exr" || ext == ".hdr" || ext == ".pfm";
}

}  // namespace

void check_writable(const std::string& path) {
  if (!OIIO::ImageOutput::create(path))
    throw Error(path, "cannot write this image format (" + OIIO::geterror() +
                          "); use .png, .exr or .ppm");
  const auto dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw Error(path, "the directory " + dir.string() + " does not exist");
}

void write_rgb(const std::string& path, int width, int height, const std::vector<float>& rgb) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  auto out = OIIO::ImageOutput::create(path);
  if (!out)
    throw Error(path, "cannot write this image format (" + OIIO::geterror() +
                          "); use .png, .exr or .ppm");
  if (is_float_format(ext)) {
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()))
      throw Error(path, "cannot write image: " + out->geterror());
  } else {
    std::vector<std::uint8_t> bytes(rgb.size());
    for (size_t k = 0; k < rgb.size(); ++k)
      bytes[k] = static_cast<std::uint8_t>(std::lround(std::clamp(rgb[k], 0.0f, 1.0f) * 255.0f));
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, bytes.data()))
      throw Error(path, "cannot write image: " + out->geterror());
  }
  if (!out->close()) throw Error(path, "cannot close image: " + out->geterror());
}

std::vector<float> read_rgb(const std::string& path, int& width, int& height) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  std::vector<float> rgb(static_cast<size_t>(width) * height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data()))
    throw Error(path, "cannot read image: " + in->geterror());
  in->close();
  return rgb;
}

}  // namespace rpu::image
