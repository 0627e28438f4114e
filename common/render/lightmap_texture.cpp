#include "render/lightmap_texture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

namespace ks::render {

namespace {
// The 8-bit encoding covers irradiance 0..kRange (a floor light's hot spot reaches ~6 in the main level;
// brighter texels clip). sqrt spends the code values on the dark end, where banding would show.
constexpr float kRange = 16.0f;
} // namespace

float lightmap_encoding_range(bool lightmap_float) {
    return lightmap_float ? 0.0f : kRange;
}

Vec3 texture_mean_color(unsigned texture, const Vec3& fallback) {
    if (texture == 0) return fallback;
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    glBindTexture(GL_TEXTURE_2D, texture);
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    Vec3 mean = fallback;
    if (w > 0 && h > 0) {
        const int top = static_cast<int>(std::floor(std::log2(static_cast<float>(std::max(w, h)))));
        GLint tw = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, top, GL_TEXTURE_WIDTH, &tw);
        if (tw == 1) {
            unsigned char rgba[16] = {};
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glGetTexImage(GL_TEXTURE_2D, top, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
            // The stored (sRGB-encoded) bytes: decoded here.
            auto linear = [](unsigned char b) {
                const float v = static_cast<float>(b) / 255.0f;
                return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            };
            mean = Vec3(linear(rgba[0]), linear(rgba[1]), linear(rgba[2]));
        }
    }
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    return mean;
}

LightmapTexture::~LightmapTexture() {
    if (id_) glDeleteTextures(1, &id_);
}

void LightmapTexture::upload(const LightBake& bake) {
    if (bake.texels().empty()) return;
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    if (!id_) {
        glGenTextures(1, &id_);
        glBindTexture(GL_TEXTURE_2D, id_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    } else {
        glBindTexture(GL_TEXTURE_2D, id_);
    }
    const bool resize = bake.width() != width_ || bake.height() != height_;
    width_ = bake.width();
    height_ = bake.height();
    range_ = lightmap_encoding_range(float_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (range_ > 0.0f) {
        const auto& t = bake.texels();
        encoded_.resize(t.size() * 4);
        for (size_t i = 0; i < t.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                float v = std::sqrt(std::clamp(t[i][c] / kRange, 0.0f, 1.0f));
                encoded_[i * 4 + static_cast<size_t>(c)] =
                    static_cast<unsigned char>(std::lround(v * 255.0f));
            }
            encoded_[i * 4 + 3] = 255;
        }
        if (resize)
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                         encoded_.data());
        else
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE,
                            encoded_.data());
    } else if (resize) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F, width_, height_, 0, GL_RGB, GL_FLOAT, bake.texels().data());
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGB, GL_FLOAT, bake.texels().data());
    }
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
}

} // namespace ks::render
