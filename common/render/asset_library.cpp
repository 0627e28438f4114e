#include "render/asset_library.h"

#include "core/files.h"
#include "core/log.h"
#include "modelio/model_files.h"
#include "render/imported_model.h"
#include "render/model_lod_list.h"

#include <cmath>

namespace ks::render {

namespace fs = std::filesystem;

AssetLibrary::AssetLibrary(fs::path assets_root) : root_(std::move(assets_root)) {}

namespace {
// Adds the coarser levels `path`'s level list names to `levels` (holding the model itself), as far as they
// load with the model's nodes.
void add_listed_levels(const fs::path& path, ModelLevels& levels, TextureCache& textures,
                       int& next_material_id) {
    const fs::path list_path = model_lods_path(path);
    std::error_code ec;
    if (!fs::exists(list_path, ec)) return;
    const Model& full = levels.full();
    const float diagonal = glm::length(full.bounds.max - full.bounds.min);
    if (full.placeholder || !(diagonal > 0.0f) || !std::isfinite(diagonal)) return;
    auto text = files::read_text(list_path);
    auto list = text ? parse_model_lods(*text, list_path.string(), path.filename().string())
                     : Result<std::vector<ModelLodEntry>>(text.error());
    if (!list) {
        log::warn(list.error().str(), "; drawing ", path.string(), " without its levels of detail");
        return;
    }
    const std::vector<std::string> nodes = full.node_names();
    for (std::size_t i = 1; i < list->size(); ++i) {
        const ModelLodEntry& entry = (*list)[i];
        const fs::path level_path = path.parent_path() / entry.file;
        auto level = load_model(level_path, textures, next_material_id);
        if (level->placeholder) { // load_model has warned, naming the file
            log::warn(list_path.string(), ": level ", i, " (", entry.file,
                      ") cannot be drawn; the model keeps its finer levels only");
            return;
        }
        if (level->node_names() != nodes) {
            log::warn(
                level_path.string(), ": its nodes differ from ", path.filename().string(),
                "'s, so a pose could not move it; the model keeps its finer levels only (regenerate the "
                "models: ks_assetgen --out assets)");
            return;
        }
        levels.levels.push_back(std::move(level));
        levels.relative_errors.push_back(entry.deviation / diagonal);
    }
}
} // namespace

const ModelLevels& AssetLibrary::model_levels(const std::string& name_or_path) {
    if (auto it = models_.find(name_or_path); it != models_.end()) return it->second;
    fs::path path(name_or_path);
    bool is_path = path.has_extension();
    if (!is_path) path = root_ / "models" / (name_or_path + ".gltf");
    ModelLevels levels;
    levels.levels.push_back(load_model(path, textures_, next_material_id_));
    levels.relative_errors.push_back(0.0f);
    add_listed_levels(path, levels, textures_, next_material_id_);
    return models_.emplace(name_or_path, std::move(levels)).first->second;
}

const ModelLevels& AssetLibrary::level_model(const std::string& file) {
    Result<std::shared_ptr<const modelio::ImportedModel>> imported =
        modelio::check_model_name(file)
            ? modelio::import_cached(modelio::resolve_model_file(file))
            : Result<std::shared_ptr<const modelio::ImportedModel>>(modelio::check_model_name(file).error());
    LevelModel& slot = level_models_[file];
    if (imported) {
        if (!slot.model.levels.empty() && slot.source == *imported) return slot.model;
        slot = {*imported, {}, model_levels_from_import(**imported, textures_, next_material_id_)};
        return slot.model;
    }
    if (!slot.model.levels.empty() && !slot.source && slot.error == imported.error().str()) return slot.model;
    log::warn(imported.error().str(), "; drawing a marker cube in its place");
    slot = {nullptr, imported.error().str(), {}};
    slot.model.levels.push_back(placeholder_model(file, textures_, next_material_id_));
    slot.model.relative_errors = {0.0f};
    return slot.model;
}

const Material& AssetLibrary::surface(const std::string& name) {
    if (auto it = surfaces_.find(name); it != surfaces_.end()) return *it->second;
    auto mat = std::make_unique<Material>();
    mat->name = name;
    mat->id = next_material_id_++;
    const fs::path dir = root_ / "textures";
    auto optional = [&](const char* suffix, ColorSpace space) -> unsigned {
        fs::path p = dir / (name + suffix);
        std::error_code ec;
        if (!fs::exists(p, ec)) return 0;
        const Texture& t = textures_.get(p, space);
        if (t.placeholder) mat->placeholder = true;
        return t.id;
    };
    const Texture& base = textures_.get(dir / (name + "_basecolor.png"), ColorSpace::Srgb);
    mat->base_map = base.id;
    mat->placeholder = base.placeholder;
    mat->normal_map = optional("_normal.png", ColorSpace::Linear);
    mat->orm_map = optional("_orm.png", ColorSpace::Linear);
    mat->height_map = mat->normal_map ? 0 : optional("_height.png", ColorSpace::Linear);
    mat->emissive_map = optional("_emissive.png", ColorSpace::Srgb);
    if (mat->emissive_map) mat->emissive_factor = Vec3(1.0f);
    mat->metallic = 1.0f; // the ORM map's blue channel holds the metalness
    mat->roughness = 1.0f;
    if (!mat->orm_map) {
        mat->metallic = 0.0f;
        mat->roughness = 0.8f;
    } else if (!mat->placeholder) {
        const auto& occluded =
            textures_.get_occluded_base(dir / (name + "_basecolor.png"), dir / (name + "_orm.png"));
        mat->fast_base_map = occluded.id;
        mat->fast_metallic = occluded.mean_metallic;
    }
    return *surfaces_.emplace(name, std::move(mat)).first->second;
}

} // namespace ks::render
