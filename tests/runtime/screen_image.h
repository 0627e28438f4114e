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

} // namespace ks::test
