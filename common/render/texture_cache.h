#pragma once
// Textures loaded through stb_image with mipmaps and anisotropic filtering, cached by path. A missing or
// corrupt image gives the magenta-checker placeholder and one warning naming the file, never a crash.
#include <filesystem>
#include <string>
#include <unordered_map>

namespace ks::render {

enum class ColorSpace { Srgb, Linear };

struct Texture {
    unsigned id = 0;
    int width = 0, height = 0;
    bool placeholder = false;
};

class TextureCache {
  public:
    TextureCache();
    ~TextureCache();
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;

    const Texture& get(const std::filesystem::path& path, ColorSpace space);
    const Texture& placeholder() const { return placeholder_; }
    const Texture& white() const { return white_; }
    const Texture& flat_normal() const { return flat_normal_; }
    int placeholder_count() const { return placeholder_count_; }

  private:
    std::unordered_map<std::string, Texture> textures_;
    Texture placeholder_, white_, flat_normal_;
    int placeholder_count_ = 0;
    float max_anisotropy_ = 1.0f;
};

} // namespace ks::render
