#include "modelio/embedded_textures.h"

#include <assimp/scene.h>
#include <assimp/texture.h>
#include <stb_image.h>

#include <climits>
#include <string>
#include <utility>

namespace ks::modelio {

namespace {

Error texture_error(const std::filesystem::path& path, const std::string& name, const std::string& what) {
    return Error(
        "the embedded texture \"" + name + "\" " + what, Location(path.string()),
        "export the model again with PNG or JPEG textures (Blender: glTF export, Images: Automatic)");
}

std::uint64_t pixel_hash(const EmbeddedImage& image) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a
    auto mix = [&h](std::uint8_t byte) {
        h ^= byte;
        h *= 1099511628211ull;
    };
    for (int v : {image.width, image.height})
        for (int shift = 0; shift < 32; shift += 8) mix(static_cast<std::uint8_t>(v >> shift));
    for (std::uint8_t byte : image.rgba) mix(byte);
    return h;
}

Result<EmbeddedImage> decode_compressed(const aiTexture& texture, const std::string& name,
                                        const std::filesystem::path& path, std::uint64_t max_pixels) {
    if (texture.pcData == nullptr || texture.mWidth == 0) return texture_error(path, name, "is empty");
    if (texture.mWidth > static_cast<unsigned>(INT_MAX)) return texture_error(path, name, "is too large");
    const auto* bytes = reinterpret_cast<const stbi_uc*>(texture.pcData);
    const int length = static_cast<int>(texture.mWidth);
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, length, &w, &h, &channels)) {
        const char* why = stbi_failure_reason();
        return texture_error(
            path, name,
            std::string("is not an image the game reads (") + (why ? why : "unknown format") +
                (texture.achFormatHint[0] ? std::string(", the file calls it ") + texture.achFormatHint
                                          : std::string()) +
                ")");
    }
    if (w <= 0 || h <= 0) return texture_error(path, name, "has no pixels");
    if (static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) > max_pixels)
        return texture_error(path, name,
                             "is " + std::to_string(w) + "x" + std::to_string(h) + ", more than the " +
                                 std::to_string(max_pixels) + " pixels a model's texture may have");
    stbi_uc* pixels = stbi_load_from_memory(bytes, length, &w, &h, &channels, 4);
    if (!pixels) {
        const char* why = stbi_failure_reason();
        return texture_error(path, name,
                             std::string("does not decode (") + (why ? why : "unknown reason") + ")");
    }
    EmbeddedImage image;
    image.name = name;
    image.width = w;
    image.height = h;
    image.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    stbi_image_free(pixels);
    return image;
}

Result<EmbeddedImage> decode_texels(const aiTexture& texture, const std::string& name,
                                    const std::filesystem::path& path, std::uint64_t max_pixels) {
    const std::uint64_t count = static_cast<std::uint64_t>(texture.mWidth) * texture.mHeight;
    if (texture.pcData == nullptr || count == 0) return texture_error(path, name, "has no pixels");
    if (count > max_pixels || texture.mWidth > static_cast<unsigned>(INT_MAX) ||
        texture.mHeight > static_cast<unsigned>(INT_MAX))
        return texture_error(path, name,
                             "is " + std::to_string(texture.mWidth) + "x" + std::to_string(texture.mHeight) +
                                 ", more than the " + std::to_string(max_pixels) +
                                 " pixels a model's texture may have");
    EmbeddedImage image;
    image.name = name;
    image.width = static_cast<int>(texture.mWidth);
    image.height = static_cast<int>(texture.mHeight);
    image.rgba.reserve(static_cast<std::size_t>(count) * 4);
    for (std::uint64_t i = 0; i < count; ++i) {
        const aiTexel& t = texture.pcData[i];
        image.rgba.insert(image.rgba.end(), {t.r, t.g, t.b, t.a});
    }
    return image;
}

} // namespace

Result<EmbeddedImage> decode_embedded_texture(const aiTexture& texture, const std::string& name,
                                              const std::filesystem::path& path, std::uint64_t max_pixels) {
    Result<EmbeddedImage> image = texture.mHeight == 0 ? decode_compressed(texture, name, path, max_pixels)
                                                       : decode_texels(texture, name, path, max_pixels);
    if (image) image->hash = pixel_hash(*image);
    return image;
}

Result<void> load_embedded_textures(const aiScene& scene, ImportedModel& model, const ImportLimits& limits) {
    model.images.assign(scene.mNumTextures, EmbeddedImage{});
    for (ImportedMaterial& m : model.materials)
        for (std::string* t :
             {&m.textures.base_color, &m.textures.normal, &m.textures.metal_rough, &m.textures.emissive}) {
            if (t->empty()) continue;
            const auto [texture, index] = scene.GetEmbeddedTextureAndIndex(t->c_str());
            if (texture == nullptr) {
                if ((*t)[0] != '*') continue; // a file beside the model (model_import.cpp checks it)
                return Error("material \"" + m.name + "\" names the embedded texture \"" + *t +
                                 "\", but the file holds " + std::to_string(scene.mNumTextures) +
                                 " embedded textures",
                             Location(model.path.string()),
                             "the file is damaged or was cut short: export the model again");
            }
            const auto slot = static_cast<std::size_t>(index);
            const std::string name = *t;
            *t = "*" + std::to_string(index);
            if (!model.images[slot].rgba.empty()) continue;
            Result<EmbeddedImage> image =
                decode_embedded_texture(*texture, name, model.path, limits.max_texture_pixels);
            if (!image) return image.error();
            model.images[slot] = std::move(*image);
        }
    return ok();
}

} // namespace ks::modelio
