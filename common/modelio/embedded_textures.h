#pragma once
// Textures stored inside a model file (a .glb's images, an FBX's embedded media): assimp hands them over as
// aiScene::mTextures, compressed (a PNG or JPEG file's bytes) or as raw aiTexel arrays, and a material names
// one as "*N" (or, for FBX, by the file name it had). Internal to modelio (model_import.cpp uses it).
#include "modelio/model_import.h"

#include <filesystem>

struct aiScene;
struct aiTexture;

namespace ks::modelio {

// Decodes one embedded texture to 8-bit RGBA, top row first: PNG, JPEG, TGA, BMP and the other formats
// stb_image reads, or assimp's uncompressed BGRA texels. An Error naming `path` and the texture for data that
// does not decode, a size of zero, or more than `max_pixels` pixels.
Result<EmbeddedImage> decode_embedded_texture(const aiTexture& texture, const std::string& name,
                                              const std::filesystem::path& path, std::uint64_t max_pixels);

// Every texture the materials of `model` name that is inside the file: the material's reference becomes "*N"
// and model.images[N] holds the decoded pixels (model.images has one slot per embedded texture; the ones no
// material uses stay empty). A "*N" beyond the file's embedded textures or one that does not decode is an
// Error naming the file, the material and the texture.
Result<void> load_embedded_textures(const aiScene& scene, ImportedModel& model, const ImportLimits& limits);

} // namespace ks::modelio
