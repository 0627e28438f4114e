#include "render/texture_cache.h"

#include "core/log.h"

#include <epoxy/gl.h>
#include <stb_image.h>

#include <algorithm>
#include <vector>

namespace ks::render {

namespace {
Texture upload(const unsigned char* rgba, int w, int h, ColorSpace space, bool mipmaps, float anisotropy) {
    Texture t;
    t.width = w;
    t.height = h;
    glGenTextures(1, &t.id);
    glBindTexture(GL_TEXTURE_2D, t.id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLenum internal = space == ColorSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mipmaps ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    if (mipmaps) {
        glGenerateMipmap(GL_TEXTURE_2D);
        if (anisotropy > 1.0f) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, anisotropy);
    }
    return t;
}

Texture solid(unsigned char r, unsigned char g, unsigned char b) {
    const unsigned char px[4] = {r, g, b, 255};
    return upload(px, 1, 1, ColorSpace::Linear, false, 1.0f);
}
} // namespace

TextureCache::TextureCache() {
    // 8x8 magenta/black checker, nearest-filtered so it is unmistakable on screen.
    std::vector<unsigned char> checker(8 * 8 * 4);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            bool on = ((x ^ y) & 1) != 0;
            unsigned char* p = &checker[static_cast<size_t>((y * 8 + x) * 4)];
            p[0] = on ? 255 : 0;
            p[1] = 0;
            p[2] = on ? 255 : 0;
            p[3] = 255;
        }
    placeholder_ = upload(checker.data(), 8, 8, ColorSpace::Linear, false, 1.0f);
    placeholder_.placeholder = true;
    white_ = solid(255, 255, 255);
    flat_normal_ = solid(128, 128, 255);
    if (epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") ||
        epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic")) {
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &max_anisotropy_);
        max_anisotropy_ = std::min(max_anisotropy_, 8.0f);
    }
}

TextureCache::~TextureCache() {
    for (auto& [path, t] : textures_)
        if (!t.placeholder) glDeleteTextures(1, &t.id);
    for (Texture* t : {&placeholder_, &white_, &flat_normal_}) glDeleteTextures(1, &t->id);
}

const Texture& TextureCache::get(const std::filesystem::path& path, ColorSpace space) {
    std::string key = path.lexically_normal().string() + (space == ColorSpace::Srgb ? "#srgb" : "#linear");
    if (auto it = textures_.find(key); it != textures_.end()) return it->second;
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
    if (!pixels) {
        const char* why = stbi_failure_reason();
        log::warn(path.string(), ": cannot load texture (", why ? why : "unknown reason",
                  "); drawing the magenta checker instead (regenerate assets with ks_assetgen)");
        ++placeholder_count_;
        return textures_.emplace(key, placeholder_).first->second;
    }
    Texture t = upload(pixels, w, h, space, true, max_anisotropy_);
    stbi_image_free(pixels);
    return textures_.emplace(key, t).first->second;
}

} // namespace ks::render
