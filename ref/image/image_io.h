// Writing images with OpenImageIO.
#pragma once

#include <string>
#include <vector>

namespace rpu::image {

// Writes a linear RGB float image. The format follows the extension (anything OpenImageIO
// writes: .png, .exr, .ppm, .tif, ...). Float formats (.exr, .tif with float, .hdr) receive the
// values unchanged; 8-bit formats receive round(255·v) of v clamped to [0, 1] — no gamma, so a
// colour c written to png reads back as round(255·c). Throws rpu::Error naming the file.
void write_rgb(const std::string& path, int width, int height, const std::vector<float>& rgb);

// Checks, before any work is done, that `path` has a format OpenImageIO can write and that its
// directory exists. Throws rpu::Error naming the file.
void check_writable(const std::string& path);

// Reads any image OpenImageIO can read as float RGB (for tests and comparisons).
std::vector<float> read_rgb(const std::string& path, int& width, int& height);

}  // namespace rpu::image
