#pragma once
// Textures loaded through stb_image with mipmaps and anisotropic filtering, cached by path. A missing or
// corrupt image gives the magenta-checker placeholder and one warning naming the file, never a crash. The
// decoded image with the driver's mip chain also goes to the disk cache (render/texture_disk_cache.h), so a
// later launch uploads the stored levels instead of decoding the PNG and generating mipmaps again.
#include "core/disk_cache.h"
#include "render/texture_disk_cache.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ks::render {

enum class ColorSpace { Srgb, Linear };

// True for CPU rasterisers (Mesa llvmpipe/softpipe, SwiftShader), judged from the GL_RENDERER string.
bool is_software_renderer(const std::string& gl_renderer);

// Anisotropic filtering per renderer: 8x on GPUs (nearly free in hardware); off (1x) on software
// rasterisers, where llvmpipe takes up to 8 trilinear footprints per fetch for every oblique pixel (the
// walls and floor seen along a corridor), measured in docs/performance.md.
float default_anisotropy_for(const std::string& gl_renderer);

struct Texture {
    unsigned id = 0;
    int width = 0, height = 0;
    bool placeholder = false;
};

class TextureCache {
  public:
    // Mip chains are read from and written to `store` (none: Store({})).
    explicit TextureCache(disk_cache::Store store = disk_cache::Store::user());
    ~TextureCache();
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;

    const Texture& get(const std::filesystem::path& path, ColorSpace space);

    // An image already decoded in memory (a model's embedded texture: modelio::EmbeddedImage), 8-bit RGBA,
    // top row first, cached under `key` (make it change when the pixels do). Pixels that do not fill
    // width x height give the placeholder and one warning naming `key`.
    const Texture& get_rgba(const std::string& key, int width, int height, std::span<const std::uint8_t> rgba,
                            ColorSpace space);

    // The fast path's colour map: the base colour (sRGB) times the ORM map's occlusion, with the ORM map's
    // metalness in alpha (when the base colour is opaque) and its mean, so a surface needs one texture
    // lookup instead of two (level surfaces use the mean, models the alpha). id 0 when either image is
    // missing or their sizes differ (the renderer then reads the ORM map as usual).
    struct OccludedBase {
        unsigned id = 0;
        float mean_metallic = 0.0f;
        bool metal_in_alpha = false; // false: the base colour's own alpha was kept
    };
    const OccludedBase& get_occluded_base(const std::filesystem::path& base,
                                          const std::filesystem::path& orm);
    const Texture& placeholder() const { return placeholder_; }
    const Texture& white() const { return white_; }
    const Texture& flat_normal() const { return flat_normal_; }
    int placeholder_count() const { return placeholder_count_; }

    // Applies to every texture loaded so far and to later ones; clamped to 1..the driver's maximum.
    void set_max_anisotropy(float anisotropy);
    float max_anisotropy() const { return max_anisotropy_; }

    // Images (and occluded bases) uploaded from the disk cache / decoded, since construction.
    struct DiskStats {
        int hits = 0, misses = 0;
    };
    const DiskStats& disk_stats() const { return disk_stats_; }
    // Waits until the mip chains decoded so far are in the disk cache (they are written on a worker).
    void flush_disk_writes() { writer_.flush(); }

  private:
    // The image's mip chain from the disk cache (the key hashes `tag`, the files' bytes and `space`, not
    // their paths), else
    // `decode`'s image uploaded with the driver's mipmaps and its chain stored; id 0 when `decode` fails.
    // `extra` is the value stored with the chain (MipChain::extra).
    template <class Decode>
    Texture load_through_disk(std::string_view tag, const std::vector<std::string>& files, ColorSpace space,
                              float& extra, Decode&& decode);
    float anisotropy_to_set() const { return driver_max_anisotropy_ > 1.0f ? max_anisotropy_ : 0.0f; }

    disk_cache::Store store_;
    ChainWriter writer_{store_};
    DiskStats disk_stats_;
    std::unordered_map<std::string, Texture> textures_;
    std::unordered_map<std::string, OccludedBase> occluded_;
    Texture placeholder_, white_, flat_normal_;
    int placeholder_count_ = 0;
    float max_anisotropy_ = 1.0f;
    float driver_max_anisotropy_ = 1.0f;
};

} // namespace ks::render
