#include "text.h"

#include "core/files.h"

#include <algorithm>
#include <cmath>
#include <stb_truetype.h>
#include <vector>

namespace ks::assetgen {

struct Font::State {
    std::string data;
    stbtt_fontinfo info{};
};

Result<Font> Font::load(const std::filesystem::path& path) {
    auto data = files::read_text(path);
    if (!data)
        return Error("cannot read the label font: " + data.error().message, Location{path.string()},
                     "assets/fonts/DejaVuSans-Bold.ttf ships with the repository; restore it from git");
    auto state = std::make_shared<State>();
    state->data = std::move(*data);
    const auto* bytes = reinterpret_cast<const unsigned char*>(state->data.data());
    // stb_truetype trusts its input; refuse anything too short to hold a font header before it looks.
    const int offset = state->data.size() < 256 ? -1 : stbtt_GetFontOffsetForIndex(bytes, 0);
    if (offset < 0 || !stbtt_InitFont(&state->info, bytes, offset))
        return Error("not a TrueType font", Location{path.string()}, "replace it with DejaVuSans-Bold.ttf");
    Font font;
    font.state_ = std::move(state);
    return font;
}

float Font::measure(std::string_view text, float pixel_height) const {
    const float scale = stbtt_ScaleForPixelHeight(&state_->info, pixel_height);
    float width = 0.0f;
    for (size_t i = 0; i < text.size(); ++i) {
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&state_->info, static_cast<unsigned char>(text[i]), &advance, &bearing);
        width += static_cast<float>(advance) * scale;
        if (i + 1 < text.size())
            width += static_cast<float>(
                         stbtt_GetCodepointKernAdvance(&state_->info, static_cast<unsigned char>(text[i]),
                                                       static_cast<unsigned char>(text[i + 1]))) *
                     scale;
    }
    return width;
}

void Font::draw(Field& field, std::string_view text, Vec2f origin, float pixel_height,
                const Stroke& stroke) const {
    const stbtt_fontinfo* info = &state_->info;
    const float scale = stbtt_ScaleForPixelHeight(info, pixel_height);
    float pen = origin.x;
    std::vector<unsigned char> glyph;
    for (size_t i = 0; i < text.size(); ++i) {
        const int cp = static_cast<unsigned char>(text[i]);
        const float shift_x = pen - std::floor(pen), shift_y = origin.y - std::floor(origin.y);
        int x0, y0, x1, y1;
        stbtt_GetCodepointBitmapBoxSubpixel(info, cp, scale, scale, shift_x, shift_y, &x0, &y0, &x1, &y1);
        const int w = x1 - x0, h = y1 - y0;
        if (w > 0 && h > 0) {
            glyph.assign(static_cast<size_t>(w) * h, 0);
            stbtt_MakeCodepointBitmapSubpixel(info, glyph.data(), w, h, w, scale, scale, shift_x, shift_y,
                                              cp);
            const int gx = static_cast<int>(std::floor(pen)) + x0,
                      gy = static_cast<int>(std::floor(origin.y)) + y0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const float coverage = static_cast<float>(glyph[static_cast<size_t>(y) * w + x]) / 255.0f;
                    if (coverage <= 0.0f) continue;
                    float& v = field.at(gx + x, gy + y);
                    switch (stroke.mode) {
                    case Paint::Max:
                        v = std::max(v, stroke.value * coverage);
                        break;
                    case Paint::Set:
                        v += (stroke.value - v) * coverage;
                        break;
                    case Paint::Add:
                        v += stroke.value * coverage;
                        break;
                    case Paint::Min:
                        v = std::min(v, 1.0f + (stroke.value - 1.0f) * coverage);
                        break;
                    }
                }
        }
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(info, cp, &advance, &bearing);
        pen += static_cast<float>(advance) * scale;
        if (i + 1 < text.size())
            pen += static_cast<float>(
                       stbtt_GetCodepointKernAdvance(info, cp, static_cast<unsigned char>(text[i + 1]))) *
                   scale;
    }
}

void Font::draw_centred(Field& field, std::string_view text, Vec2f centre, float pixel_height,
                        const Stroke& stroke) const {
    // DejaVu's capitals are about 0.73 of the pixel height (ascent to descent); centre them, not the em box.
    const float cap = 0.73f * pixel_height * 0.98f;
    draw(field, text, Vec2f(centre.x - measure(text, pixel_height) * 0.5f, centre.y + cap * 0.5f),
         pixel_height, stroke);
}

} // namespace ks::assetgen
