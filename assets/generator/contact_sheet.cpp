#include "contact_sheet.h"

#include <algorithm>

namespace ks::assetgen {

Result<void> write_contact_sheet(const Output& out, const std::filesystem::path& file) {
    constexpr int kThumb = 160, kLabel = 18, kColumns = 8;
    const auto& textures = out.textures();
    const int count = static_cast<int>(textures.size());
    const int rows = std::max(1, (count + kColumns - 1) / kColumns);
    Image sheet(kColumns * kThumb, rows * (kThumb + kLabel), Color(0.12f, 0.12f, 0.14f, 1.0f));
    int index = 0;
    for (const auto& [name, image] : textures) {
        const int cx = (index % kColumns) * kThumb, cy = (index / kColumns) * (kThumb + kLabel);
        const float sx = static_cast<float>(image.width) / kThumb,
                    sy = static_cast<float>(image.height) / kThumb;
        const float s = std::max(sx, sy);
        for (int y = 0; y < kThumb; ++y)
            for (int x = 0; x < kThumb; ++x) {
                const float u = (static_cast<float>(x) + 0.5f) * s, v = (static_cast<float>(y) + 0.5f) * s;
                if (u >= static_cast<float>(image.width) || v >= static_cast<float>(image.height)) continue;
                // Transparent sprites are shown over a checkerboard so their alpha can be judged.
                Color c = image.sample(u - 0.5f, v - 0.5f);
                const float checker = ((x / 8 + y / 8) % 2) ? 0.25f : 0.15f;
                c = Color(glm::vec3(c) + glm::vec3(checker) * (1.0f - c.a), 1.0f);
                sheet.at(cx + x, cy + y) = c;
            }
        Field label(sheet.width, sheet.height);
        out.font().draw(label, name,
                        Vec2f(static_cast<float>(cx) + 3.0f, static_cast<float>(cy + kThumb + 14)), 13.0f);
        blend(sheet, label, Color(0.95f, 0.95f, 0.95f, 1.0f));
        ++index;
    }
    return write_png(file, sheet, PngChannels::Rgb);
}

} // namespace ks::assetgen
