#include "render/texture_cache.h"

#include "core/log.h"

#include <epoxy/gl.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ks::render {

bool is_software_renderer(const std::string& gl_renderer) {
    for (const char* soft : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
        if (gl_renderer.find(soft) != std::string::npos) return true;
    return false;
}

float default_anisotropy_for(const std::string& gl_renderer) {
    return is_software_renderer(gl_renderer) ? 1.0f : 8.0f;
}

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
        if (anisotropy >= 1.0f) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, anisotropy);
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
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &driver_max_anisotropy_);
        driver_max_anisotropy_ = std::max(driver_max_anisotropy_, 1.0f);
        const GLubyte* name = glGetString(GL_RENDERER);
        max_anisotropy_ = std::min(driver_max_anisotropy_,
                                   default_anisotropy_for(name ? reinterpret_cast<const char*>(name) : ""));
    }
}

void TextureCache::set_max_anisotropy(float anisotropy) {
    if (!(anisotropy >= 1.0f)) anisotropy = 1.0f; // NaN too
    max_anisotropy_ = std::min(anisotropy, driver_max_anisotropy_);
    if (driver_max_anisotropy_ <= 1.0f) return; // no extension: nothing to set
    for (auto& [key, t] : textures_) {
        if (t.placeholder) continue;
        glBindTexture(GL_TEXTURE_2D, t.id);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, max_anisotropy_);
    }
}

TextureCache::~TextureCache() {
    for (auto& [path, t] : textures_)
        if (!t.placeholder) glDeleteTextures(1, &t.id);
    for (auto& [path, t] : occluded_)
        if (t.id) glDeleteTextures(1, &t.id);
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
    // 0: the driver has no anisotropic filtering, so the parameter is not set at all.
    Texture t = upload(pixels, w, h, space, true, driver_max_anisotropy_ > 1.0f ? max_anisotropy_ : 0.0f);
    stbi_image_free(pixels);
    return textures_.emplace(key, t).first->second;
}

const Texture& TextureCache::get_rgba(const std::string& key, int width, int height,
                                      std::span<const std::uint8_t> rgba, ColorSpace space) {
    const std::string full = key + (space == ColorSpace::Srgb ? "#srgb" : "#linear");
    if (auto it = textures_.find(full); it != textures_.end()) return it->second;
    if (width <= 0 || height <= 0 ||
        rgba.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 4) {
        log::warn(key, ": the embedded texture has no pixels; drawing the magenta checker instead");
        ++placeholder_count_;
        return textures_.emplace(full, placeholder_).first->second;
    }
    Texture t = upload(rgba.data(), width, height, space, true,
                       driver_max_anisotropy_ > 1.0f ? max_anisotropy_ : 0.0f);
    return textures_.emplace(full, t).first->second;
}

const TextureCache::OccludedBase& TextureCache::get_occluded_base(const std::filesystem::path& base,
                                                                  const std::filesystem::path& orm) {
    std::string key = base.lexically_normal().string() + "#" + orm.lexically_normal().string();
    if (auto it = occluded_.find(key); it != occluded_.end()) return it->second;
    OccludedBase out;
    int w = 0, h = 0, ow = 0, oh = 0, channels = 0;
    unsigned char* colour = stbi_load(base.string().c_str(), &w, &h, &channels, 4);
    unsigned char* occlusion = stbi_load(orm.string().c_str(), &ow, &oh, &channels, 4);
    if (colour && occlusion && w == ow && h == oh) {
        // In the sRGB-encoded domain (the fast path decodes with a square): encoded * sqrt(ao) squares to
        // linear base * ao.
        double metal = 0.0;
        const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
        for (size_t i = 0; i < n; ++i) {
            float ao = std::sqrt(occlusion[i * 4] / 255.0f);
            for (int c = 0; c < 3; ++c)
                colour[i * 4 + static_cast<size_t>(c)] =
                    static_cast<unsigned char>(std::lround(colour[i * 4 + static_cast<size_t>(c)] * ao));
            metal += occlusion[i * 4 + 2] / 255.0;
        }
        out.mean_metallic = static_cast<float>(metal / static_cast<double>(std::max<size_t>(n, 1)));
        out.id = upload(colour, w, h, ColorSpace::Srgb, true,
                        driver_max_anisotropy_ > 1.0f ? max_anisotropy_ : 0.0f)
                     .id;
    }
    if (colour) stbi_image_free(colour);
    if (occlusion) stbi_image_free(occlusion);
    return occluded_.emplace(key, out).first->second;
}

} // namespace ks::render
