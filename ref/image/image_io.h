// Writing images with OpenImageIO.
#pragma once

#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

namespace rpu::image {

// Writes a linear RGB float image. The format follows the extension (anything OpenImageIO
// writes losslessly: .png, .exr, .ppm, .tif, ...; lossy formats, .jpg, .webp, .gif, .hdr and the
// like, are refused because images carry exact colours). Float formats (.exr, .pfm) receive the
// values unchanged; 8-bit formats receive round(255·v) of v clamped to [0, 1] — no gamma, so a
// colour c written to png reads back as round(255·c). Throws rpu::Error naming the file.
// Written as write_image_file says: no partial file on failure.
void write_rgb(const std::string& path, int width, int height, const std::vector<float>& rgb);

// Writes an image of `spec` (its size, channels and file pixel format) from `data` (pixels of
// `data_type`, converted by OpenImageIO) to `path`, the format following the extension. The file
// is encoded in memory and written through a temporary beside `path` and a rename, every write
// and the close checked (common/output_file.h): a full disk or a file-size limit throws rpu::Error
// naming the file and leaves neither a partial file nor a temporary behind.
void write_image_file(const std::string& path, const OIIO::ImageSpec& spec,
                      OIIO::TypeDesc data_type, const void* data);

// Checks, before any work is done, that `path` has a lossless format OpenImageIO can write and
// can become a regular file (common/output_file.h: its directory exists and is writable; not a
// directory, device or FIFO). Throws rpu::Error naming the file.
void check_writable(const std::string& path);

// Reads any image OpenImageIO can read as float RGB (for tests and comparisons).
std::vector<float> read_rgb(const std::string& path, int& width, int& height);

}  // namespace rpu::image
