#pragma once
// Models and surface materials by name, loaded once from assets/ and shared by every scene: model "robot"
// is assets/models/robot.gltf; surface "concrete" is
// assets/textures/concrete_{basecolor,normal,orm,height}.png.
#include "render/material.h"
#include "render/model.h"
#include "render/texture_cache.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace ks::render {

class AssetLibrary {
  public:
    explicit AssetLibrary(std::filesystem::path assets_root);

    TextureCache& textures() { return textures_; }
    // A model by name or by path (ending in .gltf/.glb/.obj); a placeholder cube when it cannot load.
    const Model& model(const std::string& name_or_path) { return model_levels(name_or_path).full(); }
    // The same with its levels of detail: those its level list (model_lod_list.h: robot.lods.json beside
    // robot.gltf, written by the asset generator) names, each with the same nodes as the model. No list:
    // one level. A list or a level that cannot be read, or a level with other nodes, is one warning naming
    // the file, and the model is drawn with the levels before it.
    const ModelLevels& model_levels(const std::string& name_or_path);
    // A model entity's file (level::ModelProps::file) read through modelio, with its levels of detail:
    // rebuilt when the file changed on disk since (modelio's import cache says so); the marker cube (one
    // level), and one warning, when it cannot be read.
    const ModelLevels& level_model(const std::string& file);
    // A level surface material; a missing base colour gives the placeholder (one warning).
    const Material& surface(const std::string& name);
    int next_material_id() { return next_material_id_++; }
    const std::filesystem::path& root() const { return root_; }

  private:
    std::filesystem::path root_;
    TextureCache textures_;
    int next_material_id_ = 1;
    std::map<std::string, ModelLevels> models_;
    std::map<std::string, std::unique_ptr<Material>> surfaces_;
    struct LevelModel {
        std::shared_ptr<const void> source; // the import it was built from; null for the marker
        std::string error;                  // the marker's reason
        ModelLevels model;
    };
    std::map<std::string, LevelModel> level_models_;
};

} // namespace ks::render
