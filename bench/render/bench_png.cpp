// ks_bench png: writing a 1280x720 screenshot, the project's encoder (zlib run-length deflate, "up" filter)
// against stb_image_write's (what it replaced), on the main menu's picture when a screenshot file is given
// (--image FILE.png) or on a synthetic picture of smooth gradients and sharp edges.
#include "bench_registry.h"
#include "editor/median_time.h"
#include "render/png_writer.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace ks::bench {
namespace {

struct Picture {
    int width = 1280, height = 720;
    std::vector<unsigned char> rgb;
};

Picture synthetic_picture() {
    Picture p;
    p.rgb.resize(static_cast<size_t>(p.width) * p.height * 3);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            unsigned char* px = &p.rgb[(static_cast<size_t>(y) * p.width + x) * 3];
            const bool panel = x > 320 && x < 960 && y > 190 && y < 570;
            px[0] = panel ? 220 : static_cast<unsigned char>(20 + x / 20);
            px[1] = panel ? 230 : static_cast<unsigned char>(30 + y / 12);
            px[2] = panel ? static_cast<unsigned char>(240 - (x / 64) % 2 * 30)
                          : static_cast<unsigned char>(60 + (x + y) / 40);
        }
    return p;
}

int run_png(int argc, const char* const* argv) {
    Picture p = synthetic_picture();
    std::string source = "synthetic 1280x720";
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--image") == 0) {
            int channels = 0;
            unsigned char* px = stbi_load(argv[i + 1], &p.width, &p.height, &channels, 3);
            if (!px) {
                std::fprintf(stderr, "ks_bench png: cannot read %s\n", argv[i + 1]);
                return 1;
            }
            p.rgb.assign(px, px + static_cast<size_t>(p.width) * p.height * 3);
            stbi_image_free(px);
            source = argv[i + 1];
        }
    const int stride = p.width * 3;
    size_t ours_bytes = 0;
    int stb_bytes = 0;
    const double ours_ms = median_ms(7, [&] {
        auto png = render::encode_png_rgb(p.width, p.height, p.rgb.data(), stride);
        ours_bytes = png ? png->size() : 0;
    });
    const double stb_ms = median_ms(7, [&] {
        stb_bytes = 0;
        stbi_write_png_to_func([](void* total, void*, int size) { *static_cast<int*>(total) += size; },
                               &stb_bytes, p.width, p.height, 3, p.rgb.data(), stride);
    });
    std::printf("screenshot PNG encoding, %s (median of 7, same run)\n", source.c_str());
    std::printf("| encoder | ms | bytes | vs stb |\n|---|---:|---:|---:|\n");
    std::printf("| stb_image_write (default level) | %.1f | %d | 1.00x |\n", stb_ms, stb_bytes);
    std::printf("| render::encode_png_rgb (zlib RLE, up) | %.1f | %zu | %.2fx faster |\n", ours_ms,
                ours_bytes, stb_ms / ours_ms);
    return ours_bytes > 0 ? 0 : 1;
}

const Registrar kPng({"png", "screenshot PNG encoding: ours vs stb_image_write", run_png});

} // namespace
} // namespace ks::bench
