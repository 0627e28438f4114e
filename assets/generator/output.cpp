#include "output.h"

#include "audio/wav.h"

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
