#include "render/png_writer.h"

#include <zlib.h>

#include <fstream>

namespace ks::render {
namespace {

void put_u32(std::vector<unsigned char>& out, uint32_t v) {
    out.push_back(static_cast<unsigned char>(v >> 24));
    out.push_back(static_cast<unsigned char>(v >> 16));
    out.push_back(static_cast<unsigned char>(v >> 8));
    out.push_back(static_cast<unsigned char>(v));
}

// A chunk: length, type, data, CRC of type and data.
void put_chunk(std::vector<unsigned char>& out, const char (&type)[5], const unsigned char* data,
               size_t size) {
    put_u32(out, static_cast<uint32_t>(size));
    const size_t type_at = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data, data + size);
    const uLong crc = crc32(0L, out.data() + type_at, static_cast<uInt>(size + 4));
    put_u32(out, static_cast<uint32_t>(crc));
}

// The filtered scanlines: a filter byte per row, the first row unfiltered (0), the others "up" (2).
std::vector<unsigned char> filtered_rows(int width, int height, const unsigned char* top_row,
                                         std::ptrdiff_t stride) {
    const size_t row_bytes = static_cast<size_t>(width) * 3;
    std::vector<unsigned char> rows((row_bytes + 1) * static_cast<size_t>(height));
    unsigned char* out = rows.data();
    const unsigned char* above = nullptr;
    for (int y = 0; y < height; ++y) {
        const unsigned char* row = top_row + stride * y;
        *out++ = above ? 2 : 0;
        if (above) {
            for (size_t i = 0; i < row_bytes; ++i) out[i] = static_cast<unsigned char>(row[i] - above[i]);
        } else {
            std::copy(row, row + row_bytes, out);
        }
        out += row_bytes;
        above = row;
    }
    return rows;
}

} // namespace

Result<std::vector<unsigned char>> encode_png_rgb(int width, int height, const unsigned char* top_row,
                                                  std::ptrdiff_t stride) {
    // PNG allows 2^31 - 1 a side; 2^15 keeps the buffer under zlib's 32-bit sizes (4 GiB).
    constexpr int kMaxSide = 1 << 15;
    if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide || top_row == nullptr)
        return Error("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) +
                     " image as PNG");
    const std::vector<unsigned char> rows = filtered_rows(width, height, top_row, stride);
    // Run-length matches only (Z_RLE): after the "up" filter a screenshot is mostly runs of equal bytes, and
    // this finds them as fast as level 1's hash search while writing a smaller file.
    z_stream stream{};
    if (deflateInit2(&stream, Z_BEST_SPEED, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK)
        return Error("zlib could not start");
    std::vector<unsigned char> packed(deflateBound(&stream, static_cast<uLong>(rows.size())));
    stream.next_in = const_cast<unsigned char*>(rows.data());
    stream.avail_in = static_cast<uInt>(rows.size());
    stream.next_out = packed.data();
    stream.avail_out = static_cast<uInt>(packed.size());
    const int status = deflate(&stream, Z_FINISH);
    const size_t packed_size = stream.total_out;
    deflateEnd(&stream);
    if (status != Z_STREAM_END) return Error("zlib could not compress the image");

    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    png.reserve(packed_size + 64);
    std::vector<unsigned char> header;
    put_u32(header, static_cast<uint32_t>(width));
    put_u32(header, static_cast<uint32_t>(height));
    header.insert(header.end(), {8, 2, 0, 0, 0}); // 8 bits, RGB, deflate, adaptive filters, no interlace
    put_chunk(png, "IHDR", header.data(), header.size());
    put_chunk(png, "IDAT", packed.data(), packed_size);
    put_chunk(png, "IEND", nullptr, 0);
    return png;
}

Result<void> write_png_rgb(const std::string& path, int width, int height, const unsigned char* top_row,
                           std::ptrdiff_t stride) {
    auto png = encode_png_rgb(width, height, top_row, stride);
    if (!png) return Error(png.error().message, Location{path});
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (file)
        file.write(reinterpret_cast<const char*>(png->data()), static_cast<std::streamsize>(png->size()));
    if (!file)
        return Error("cannot write PNG", Location{path}, "check that the folder exists and is writable");
    return ok();
}

} // namespace ks::render
