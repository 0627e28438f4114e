#pragma once
// Writing screenshots as PNG files fast: the game and the editor write one per screenshot run and the GL
// test suites write hundreds. zlib's run-length deflate over rows filtered with PNG's "up" filter (each
// byte minus the one above) is several times faster than stb_image_write's encoder, which tries every
// filter on every row and compresses with its own slower deflate (docs/performance.md, "Screenshot
// files"). Committed assets keep the generator's smallest-file encoder (assets/generator/image.cpp).
#include "core/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace ks::render {

// Encodes an 8-bit RGB image (3 bytes a pixel) as a PNG in memory. `top_row` points at the image's first
// (top) row and `stride` is the distance in bytes from one row to the next below it (negative for
// bottom-up data such as GL's read-back).
Result<std::vector<unsigned char>> encode_png_rgb(int width, int height, const unsigned char* top_row,
                                                  std::ptrdiff_t stride);

// encode_png_rgb written to `path`; an unwritable path is an error naming it.
Result<void> write_png_rgb(const std::string& path, int width, int height, const unsigned char* top_row,
                           std::ptrdiff_t stride);

} // namespace ks::render
