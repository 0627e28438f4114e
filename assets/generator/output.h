#pragma once
// Where generated assets go: DIR/textures/<name>.png and DIR/models/<name>.gltf|.bin. Keeps what it wrote
// in memory too (textures for the contact sheet, models for previews) and lists every file written.
#include "gltf_writer.h"
#include "image.h"
#include "text.h"

#include "core/result.h"

#include <filesystem>
#include <map>
#include <optional>
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
    Output(std::filesystem::path root, Font font) : root_(std::move(root)), font_(std::move(font)) {}

    Result<void> texture(const std::string& name, const Image& image, PngChannels channels);
    // Writes <name>_basecolor, _normal, _orm (+ _emissive, _height when present).
    Result<void> material(const std::string& name, const MaterialMaps& maps);
    Result<void> model(const Model& model);

    const Font& font() const { return font_; }
    const std::filesystem::path& root() const { return root_; }
    const std::vector<std::filesystem::path>& written() const { return written_; }
    const std::map<std::string, Image>& textures() const { return textures_; }
    const std::vector<Model>& models() const { return models_; }
    // Texture lookup for previews (nullptr when not generated in this run).
    const Image* find_texture(const std::string& name) const;

  private:
    std::filesystem::path root_;
    Font font_;
    std::vector<std::filesystem::path> written_;
    std::map<std::string, Image> textures_;
    std::vector<Model> models_;
};

} // namespace ks::assetgen
