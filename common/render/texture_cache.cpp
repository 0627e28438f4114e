#include "render/texture_cache.h"

#include "core/files.h"
#include "core/log.h"
#include "render/texture_disk_cache.h"

#include <epoxy/gl.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
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
constexpr const char* kDiskKind = "texture";

GLenum internal_format(ColorSpace space) {
    return space == ColorSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
}

Texture new_texture(int w, int h) {
    Texture t;
    t.width = w;
    t.height = h;
    glGenTextures(1, &t.id);
    glBindTexture(GL_TEXTURE_2D, t.id);
    return t;
}

// Sampling of the bound texture: repeat, trilinear with mipmaps (and anisotropy when >= 1), else nearest.
void set_sampling(bool mipmaps, float anisotropy) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mipmaps ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    if (mipmaps && anisotropy >= 1.0f)
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, anisotropy);
}

Texture upload(const unsigned char* rgba, int w, int h, ColorSpace space, bool mipmaps, float anisotropy) {
    Texture t = new_texture(w, h);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format(space)), w, h, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, rgba);
    set_sampling(mipmaps, anisotropy);
    if (mipmaps) glGenerateMipmap(GL_TEXTURE_2D);
    return t;
}

// An RGBA image decoded by stb_image (freed with it).
struct Decoded {
    std::unique_ptr<unsigned char, void (*)(void*)> rgba{nullptr, stbi_image_free};
    int width = 0, height = 0;
    float extra = 0.0f;
};

Decoded decode(const std::string& file) {
    Decoded d;
    int channels = 0;
    d.rgba.reset(stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.data()),
                                       static_cast<int>(file.size()), &d.width, &d.height, &channels, 4));
    return d;
}

Texture solid(unsigned char r, unsigned char g, unsigned char b) {
    const unsigned char px[4] = {r, g, b, 255};
    return upload(px, 1, 1, ColorSpace::Linear, false, 1.0f);
}
// In the sRGB-encoded domain (the fast path decodes with a square): encoded * sqrt(ao) squares to linear
// base * ao. Returns the ORM map's mean metalness.
// The occluded base's `extra` (kept with its mip chain in the disk cache): the mean metalness, plus
// kAlphaKept when the base colour had an alpha of its own (not opaque), which then stays in place of the
// metalness.
constexpr float kAlphaKept = 2.0f;

float occlude(unsigned char* colour, const unsigned char* occlusion, size_t n) {
    double metal = 0.0;
    bool opaque = true;
    for (size_t i = 0; i < n && opaque; ++i) opaque = colour[i * 4 + 3] == 255;
    for (size_t i = 0; i < n; ++i) {
        float ao = std::sqrt(occlusion[i * 4] / 255.0f);
        for (int c = 0; c < 3; ++c)
            colour[i * 4 + static_cast<size_t>(c)] =
                static_cast<unsigned char>(std::lround(colour[i * 4 + static_cast<size_t>(c)] * ao));
        if (opaque) colour[i * 4 + 3] = occlusion[i * 4 + 2];
        metal += occlusion[i * 4 + 2] / 255.0;
    }
    const float mean = static_cast<float>(metal / static_cast<double>(std::max<size_t>(n, 1)));
    return opaque ? mean : mean + kAlphaKept;
}
} // namespace

TextureCache::TextureCache(disk_cache::Store store) : store_(std::move(store)) {
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

template <class Decode>
Texture TextureCache::load_through_disk(std::string_view tag, const std::vector<std::string>& images,
                                        ColorSpace space, float& extra, Decode&& decode_image) {
    std::uint64_t key = 0;
    if (store_.enabled()) {
        disk_cache::Hasher h = texture_key_base();
        h.text(tag).value(space == ColorSpace::Srgb).value(images.size());
        for (const std::string& file : images) h.text(file);
        key = h.digest();
        if (auto payload = store_.load(kDiskKind, key)) {
            if (auto chain = read_mip_chain(*payload)) {
                Texture t = new_texture(chain->width, chain->height);
                upload_mip_chain(*chain, internal_format(space));
                set_sampling(true, anisotropy_to_set());
                extra = chain->extra;
                ++disk_stats_.hits;
                return t;
            }
            log::info(store_.file(kDiskKind, key).string(),
                      ": cache entry is not a whole mip chain, decoding the image again");
        }
    }
    Decoded image = decode_image();
    if (!image.rgba) return {};
    ++disk_stats_.misses;
    Texture t = upload(image.rgba.get(), image.width, image.height, space, true, anisotropy_to_set());
    extra = image.extra;
    if (store_.enabled())
        if (auto chain = read_back_mip_chain(t.id, t.width, t.height)) {
            chain->extra = image.extra;
            writer_.save(kDiskKind, key, std::move(*chain));
        }
    return t;
}

const Texture& TextureCache::get(const std::filesystem::path& path, ColorSpace space) {
    std::string key = path.lexically_normal().string() + (space == ColorSpace::Srgb ? "#srgb" : "#linear");
    if (auto it = textures_.find(key); it != textures_.end()) return it->second;
    std::vector<std::string> images;
    std::string why;
    if (auto bytes = files::read_text(path))
        images.push_back(std::move(*bytes));
    else
        why = bytes.error().message;
    float extra = 0.0f;
    Texture t;
    if (!images.empty())
        t = load_through_disk("image", images, space, extra, [&] {
            Decoded d = decode(images[0]);
            if (!d.rgba) why = stbi_failure_reason() ? stbi_failure_reason() : "unknown reason";
            return d;
        });
    if (!t.id) {
        log::warn(path.string(), ": cannot load texture (", why,
                  "); drawing the magenta checker instead (regenerate assets with ks_assetgen)");
        ++placeholder_count_;
        return textures_.emplace(key, placeholder_).first->second;
    }
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
    auto base_bytes = files::read_text(base);
    auto orm_bytes = files::read_text(orm);
    if (base_bytes && orm_bytes) {
        const std::vector<std::string> images{std::move(*base_bytes), std::move(*orm_bytes)};
        float extra = 0.0f;
        out.id = load_through_disk("occluded base, metalness in alpha", images, ColorSpace::Srgb, extra, [&] {
                     Decoded colour = decode(images[0]);
                     const Decoded occlusion = decode(images[1]);
                     if (!colour.rgba || !occlusion.rgba || colour.width != occlusion.width ||
                         colour.height != occlusion.height)
                         return Decoded{};
                     colour.extra =
                         occlude(colour.rgba.get(), occlusion.rgba.get(),
                                 static_cast<size_t>(colour.width) * static_cast<size_t>(colour.height));
                     return colour;
                 }).id;
        out.metal_in_alpha = extra < kAlphaKept;
        out.mean_metallic = out.metal_in_alpha ? extra : extra - kAlphaKept;
    }
    return occluded_.emplace(key, out).first->second;
}

} // namespace ks::render
