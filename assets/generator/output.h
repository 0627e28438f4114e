#pragma once
// Where generated assets go: DIR/textures/<name>.png, DIR/models/<name>.gltf|.bin, DIR/sounds/<name>.wav and
// DIR/icons/hicolor/<size>x<size>/apps/<name>.png.
// Keeps what it wrote in memory too (textures for the contact sheet, models for previews, sounds for the
// sound report) and lists every file written.
#include "gltf_writer.h"
#include "image.h"
#include "text.h"

#include "core/result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

// Returns the error of a failed Result<void> expression from the enclosing function.
#define KS_ASSETGEN_TRY(expr)                                                                                \
    do {                                                                                                     \
        if (auto ks_try_result_ = (expr); !ks_try_result_) return ks_try_result_.error();                    \
    } while (0)

namespace ks::assetgen {

// The maps of one PBR material. Base colour and emissive are sRGB; the rest linear.
struct MaterialMaps {
    Image basecolor;
    Image normal;
    Image orm; // R occlusion, G roughness, B metallic
    std::optional<Image> emissive;
    std::optional<Field> height;
};

class Output {
  public:
    // `keep_images`: hold every texture in memory for the contact sheet and previews (about 4 MB per 512²
    // map).
    Output(std::filesystem::path root, Font font, bool keep_images = false)
        : root_(std::move(root)), font_(std::move(font)), keep_images_(keep_images) {}

    Result<void> texture(const std::string& name, const Image& image, PngChannels channels);
    // Writes DIR/icons/hicolor/<size>x<size>/apps/<name>.png (RGBA, straight alpha): the freedesktop icon
    // theme's layout, installed as it is into share/icons/.
    Result<void> icon(const std::string& name, const Image& image);
    // Writes <name>_basecolor, _normal, _orm (+ _emissive, _height when present).
    Result<void> material(const std::string& name, const MaterialMaps& maps);
    Result<void> model(const Model& model);
    // A model with its levels of detail: `build` (one recipe's geometry) run in full and then under a Detail
    // of each of kLevelTolerances (shapes.h) times its bounds' diagonal. A level is kept when it has under
    // kLevelMinSaving of the last kept one's triangles and written as <name>_lod<k>.gltf|.bin;
    // <name>.lods.json lists the levels with each one's deviation bound (Model::deviation, rounded up) and
    // triangle count (docs/assets.md).
    Result<void> model_levels(const std::function<Model()>& build);
    // Writes DIR/sounds/<name>.wav: 16-bit PCM, mono, 48 kHz; unless the name is one of the designer's
    // sounds, whose file is left as it is.
    Result<void> sound(const std::string& name, std::vector<std::int16_t> samples);
    void keep_designer_sounds(std::set<std::string> names) { designer_sounds_ = std::move(names); }
    // The designer's sounds this run left alone.
    const std::vector<std::string>& kept_sounds() const { return kept_sounds_; }

    const Font& font() const { return font_; }
    const std::filesystem::path& root() const { return root_; }
    const std::vector<std::filesystem::path>& written() const { return written_; }
    const std::map<std::string, Image>& textures() const { return textures_; }
    const std::vector<Model>& models() const { return models_; }
    // The sounds of this run by name (mono 48 kHz samples).
    const std::map<std::string, std::vector<std::int16_t>>& sounds() const { return sounds_; }
    // Texture lookup for previews (nullptr when not generated in this run or not kept).
    const Image* find_texture(const std::string& name) const;
    bool has_written_texture(const std::string& name) const { return texture_names_.count(name) > 0; }

  private:
    std::filesystem::path root_;
    Font font_;
    std::vector<std::filesystem::path> written_;
    bool keep_images_ = false;
    std::map<std::string, Image> textures_;
    std::set<std::string> texture_names_;
    std::vector<Model> models_;
    std::map<std::string, std::vector<std::int16_t>> sounds_;
    std::set<std::string> designer_sounds_;
    std::vector<std::string> kept_sounds_;
};

} // namespace ks::assetgen
