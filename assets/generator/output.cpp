#include "output.h"

#include "shapes.h"

#include "audio/wav.h"
#include "core/files.h"

#include <cmath>
#include <cstdio>

namespace ks::assetgen {
namespace fs = std::filesystem;

namespace {
Result<void> ensure_folder(const fs::path& folder) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec)
        return Error("cannot create the output folder: " + ec.message(), Location{folder.string()},
                     "pass --out a folder you can write to");
    return ok();
}
} // namespace

Result<void> Output::texture(const std::string& name, const Image& image, PngChannels channels) {
    const fs::path path = root_ / "textures" / (name + ".png");
    KS_ASSETGEN_TRY(ensure_folder(path.parent_path()));
    KS_ASSETGEN_TRY(write_png(path, image, channels));
    written_.push_back(path);
    texture_names_.insert(name);
    if (keep_images_) textures_[name] = image;
    return ok();
}

Result<void> Output::icon(const std::string& name, const Image& image) {
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    const fs::path path = root_ / "icons" / "hicolor" / size / "apps" / (name + ".png");
    KS_ASSETGEN_TRY(ensure_folder(path.parent_path()));
    KS_ASSETGEN_TRY(write_png(path, image, PngChannels::Rgba));
    written_.push_back(path);
    return ok();
}

Result<void> Output::material(const std::string& name, const MaterialMaps& maps) {
    KS_ASSETGEN_TRY(texture(name + "_basecolor", maps.basecolor, PngChannels::Rgb));
    KS_ASSETGEN_TRY(texture(name + "_normal", maps.normal, PngChannels::Rgb));
    KS_ASSETGEN_TRY(texture(name + "_orm", maps.orm, PngChannels::Rgb));
    if (maps.emissive) KS_ASSETGEN_TRY(texture(name + "_emissive", *maps.emissive, PngChannels::Rgb));
    if (maps.height) KS_ASSETGEN_TRY(texture(name + "_height", grey(*maps.height), PngChannels::Grey));
    return ok();
}

Result<void> Output::model(const Model& model) {
    const fs::path folder = root_ / "models";
    KS_ASSETGEN_TRY(ensure_folder(folder));
    KS_ASSETGEN_TRY(write_gltf(model, folder));
    written_.push_back(folder / (model.name() + ".gltf"));
    written_.push_back(folder / (model.name() + ".bin"));
    models_.push_back(model);
    return ok();
}

namespace {
// A deviation in the sidecar: rounded up to 1e-5 units, so the written figure still bounds it, and printed
// the same by every build of the generator.
std::string deviation_text(float deviation) {
    char text[32];
    std::snprintf(text, sizeof text, "%.5f", std::ceil(static_cast<double>(deviation) * 1e5 - 1e-6) / 1e5);
    return text;
}
} // namespace

Result<void> Output::model_levels(const std::function<Model()>& build) {
    Model full = build();
    const std::string name = full.name();
    KS_ASSETGEN_TRY(model(full));
    std::size_t kept_triangles = full.triangle_count();
    std::string levels = "    {\"file\": \"" + name +
                         ".gltf\", \"deviation\": 0, \"triangles\": " + std::to_string(kept_triangles) + "}";
    int written_levels = 0;
    const auto [low, high] = full.bounds();
    const float diagonal = glm::length(high - low);
    for (const float fraction : kLevelTolerances) {
        Model coarse = [&] {
            const DetailScope scope(Detail{fraction * diagonal});
            return build();
        }();
        const std::size_t triangles = coarse.triangle_count();
        if (static_cast<double>(triangles) >= kLevelMinSaving * static_cast<double>(kept_triangles)) continue;
        kept_triangles = triangles;
        coarse.set_name(name + "_lod" + std::to_string(++written_levels));
        const fs::path folder = root_ / "models";
        KS_ASSETGEN_TRY(write_gltf(coarse, folder));
        written_.push_back(folder / (coarse.name() + ".gltf"));
        written_.push_back(folder / (coarse.name() + ".bin"));
        levels += ",\n    {\"file\": \"" + coarse.name() +
                  ".gltf\", \"deviation\": " + deviation_text(coarse.deviation()) +
                  ", \"triangles\": " + std::to_string(triangles) + "}";
    }
    const fs::path sidecar = root_ / "models" / (name + ".lods.json");
    const std::string text =
        "{\n  \"format\": \"killswitch-model-lods\",\n  \"version\": 1,\n  \"model\": \"" + name +
        ".gltf\",\n  \"levels\": [\n" + levels + "\n  ]\n}\n";
    if (auto written = files::write_atomic(sidecar, text); !written) return written.error();
    written_.push_back(sidecar);
    return ok();
}

Result<void> Output::sound(const std::string& name, std::vector<std::int16_t> samples) {
    if (designer_sounds_.count(name) > 0) {
        kept_sounds_.push_back(name);
        return ok();
    }
    const fs::path path = root_ / "sounds" / (name + ".wav");
    KS_ASSETGEN_TRY(ensure_folder(path.parent_path()));
    audio::SoundData data;
    data.sample_rate = 48000;
    data.channels = 1;
    data.samples = std::move(samples);
    KS_ASSETGEN_TRY(audio::write_wav(path, data));
    written_.push_back(path);
    sounds_[name] = std::move(data.samples);
    return ok();
}

const Image* Output::find_texture(const std::string& name) const {
    auto it = textures_.find(name);
    return it == textures_.end() ? nullptr : &it->second;
}

} // namespace ks::assetgen
