#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "common/error.h"
#include "common/output_file.h"

namespace rpu::image {
namespace {

bool is_float_format(const std::string& ext) {
  return ext == ".exr" || ext == ".pfm";
}

// Images carry exact colours (a pixel is its primitive's colour or the background), so a format
// that cannot hold them exactly is refused before any work is done: the JPEG family, WebP,
// HEIF/AVIF and JPEG 2000 (lossy compression), GIF (a 256-colour palette, dithered) and Radiance
// HDR (RGBE: an 8-bit mantissa per channel under a shared exponent).
void check_lossless_format(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  static constexpr std::string_view kLossy[] = {".jpg", ".jpeg", ".jpe", ".jfif", ".jif", ".webp",
                                                ".heic", ".heif", ".avif", ".jp2", ".j2k", ".j2c",
                                                ".jpx", ".gif", ".hdr", ".rgbe"};
  if (std::find(std::begin(kLossy), std::end(kLossy), ext) != std::end(kLossy))
    throw Error(path, ext + " cannot hold the image's exact colours (a lossy format); use .png, "
                      ".exr, .ppm or .tif");
}

std::unique_ptr<OIIO::ImageOutput> create_output(const std::string& path) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out)
    throw Error(path, "cannot write this image format (" + OIIO::geterror() +
                          "); use .png, .exr or .ppm");
  return out;
}

// OpenImageIO's error text (it may span lines) as one line.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "unknown error" : text;
}

}  // namespace

void check_writable(const std::string& path) {
  // Where first (a device or directory says so), then the format (the file name's extension).
  check_output_path(path, "image");
  check_lossless_format(path);
  create_output(path);
}

void write_image_file(const std::string& path, const OIIO::ImageSpec& spec,
                      OIIO::TypeDesc data_type, const void* data) {
  check_output_path(path, "image");
  check_lossless_format(path);
  auto out = create_output(path);
  const auto failed = [&](std::string_view step) {
    throw Error(path, "cannot write image (" + std::string(step) +
                          "): " + one_line(out->geterror()));
  };
  if (out->supports("ioproxy")) {
    // Encode in memory, then write the bytes with every write and the close checked.
    OIIO::Filesystem::IOVecOutput memory;
    OIIO::ImageSpec config = spec;
    if (!out->set_ioproxy(&memory)) failed("set_ioproxy");
    if (!out->open(path, config)) failed("open");
    if (!out->write_image(data_type, data)) failed("write_image");
    if (!out->close()) failed("close");
    const auto& bytes = memory.buffer();
    if (bytes.empty()) throw Error(path, "cannot write image: the encoder produced no data");
    write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()),
                                                 bytes.size()));
    return;
  }
  // Formats without an I/O proxy write a temporary file themselves.
  const std::string tmp = temporary_path_beside(path);
  const auto failed_tmp = [&](std::string_view step) {
    const std::string why = one_line(out->geterror());
    out.reset();
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw Error(path, "cannot write image (" + std::string(step) + "): " + why);
  };
  if (!out->open(tmp, spec)) failed_tmp("open");
  if (!out->write_image(data_type, data)) failed_tmp("write_image");
  if (!out->close()) failed_tmp("close");
  std::error_code ec;
  if (std::filesystem::file_size(tmp, ec) == 0 || ec) {
    std::filesystem::remove(tmp, ec);
    throw Error(path, "cannot write image: the file came out empty");
  }
  commit_temporary(tmp, path);
}

void write_rgb(const std::string& path, int width, int height, const std::vector<float>& rgb) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (is_float_format(ext)) {
    write_image_file(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT),
                     OIIO::TypeDesc::FLOAT, rgb.data());
  } else {
    std::vector<std::uint8_t> bytes(rgb.size());
    for (size_t k = 0; k < rgb.size(); ++k)
      bytes[k] = static_cast<std::uint8_t>(std::lround(std::clamp(rgb[k], 0.0f, 1.0f) * 255.0f));
    write_image_file(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8),
                     OIIO::TypeDesc::UINT8, bytes.data());
  }
}

std::vector<float> read_rgb(const std::string& path, int& width, int& height) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path, "cannot read image: " + one_line(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  std::vector<float> rgb(static_cast<size_t>(width) * height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data()))
    throw Error(path, "cannot read image: " + one_line(in->geterror()));
  in->close();
  return rgb;
}

}  // namespace rpu::image
