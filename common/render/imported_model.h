#pragma once
// A designer's model (modelio::ImportedModel, node transforms already baked) as a drawable Model: one root
// node holding every mesh, its materials' factors and texture files (relative to the model's folder) through
// the texture cache; textures embedded in the file ("*N": a .glb's images) from the import's decoded pixels.
#include "modelio/model_import.h"
#include "render/model.h"

#include <memory>

namespace ks::render {

class TextureCache;

// The full model and one Model per level of detail the import holds (ImportedModel::lods), every level with
// the same materials (the same ids, so the renderer batches them together).
ModelLevels model_levels_from_import(const modelio::ImportedModel& imported, TextureCache& textures,
                                     int& next_material_id);

// The drawn marker of a model whose file cannot be read: the magenta-checker cube standing on its origin
// (side 1, as level::model_bounding_shape's box).
std::unique_ptr<Model> marker_model(const std::string& name, TextureCache& textures, int& next_material_id);

} // namespace ks::render
