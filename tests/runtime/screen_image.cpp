#include "runtime/screen_image.h"

#include <stb_image.h>

#include <cstdlib>
#include <set>

namespace ks::test {

bool have_display() {
    const char* d = std::getenv("DISPLAY");
    return d && *d;
}

Image load_png(const std::filesystem::path& path) {
    Image img;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &img.width, &img.height, &channels, 3);
    if (data) {
        img.rgb.assign(data, data + static_cast<size_t>(img.width) * img.height * 3);
        stbi_image_free(data);
    }
    return img;
}

size_t distinct_colours(const Image& img) {
    std::set<unsigned> colours;
    for (int y = 0; y < img.height; y += 4)
        for (int x = 0; x < img.width; x += 4) {
            const unsigned char* p = img.at(x, y);
            colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
        }
    return colours.size();
}

} // namespace ks::test
