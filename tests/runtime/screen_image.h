#pragma once
// What the GL tests need to look at a screenshot: load a PNG, read pixels, count colours.
#include <filesystem>
#include <vector>

namespace ks::test {

bool have_display(); // DISPLAY is set (./run.sh test provides one with xvfb-run)

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    const unsigned char* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

Image load_png(const std::filesystem::path& path); // empty image if unreadable
// Distinct colours on a 4-pixel grid: a blank (single-colour) frame has one.
size_t distinct_colours(const Image& img);
// Pixels of [x0, x1) x [y0, y1) whose colour `accept(r, g, b)` takes.
template <class Accept>
int count_pixels(const Image& img, int x0, int y0, int x1, int y1, Accept accept) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const unsigned char* p = img.at(x, y);
            if (accept(p[0], p[1], p[2])) ++n;
        }
    return n;
}

} // namespace ks::test
