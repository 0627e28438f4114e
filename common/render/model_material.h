#pragma once
// A render material from a model file's material (modelio::ImportedMaterial): the one conversion that the
// shipped models (load_model) and designers' models (upload_imported_model) share. Internal to render.
#include "modelio/model_import.h"
#include "render/material.h"
#include "render/texture_cache.h"

#include <filesystem>
#include <functional>
#include <string>

namespace ks::render {

// A map by the name the material gives it: a file beside the model, or ("*N") the file's own image N.
using MapSource = std::function<const Texture&(const std::string& name, ColorSpace space)>;

// Factors, sides and maps (through `maps`; any placeholder marks the material), and the fast path's
// one-lookup map (base x occlusion, metalness in alpha: TextureCache::get_occluded_base) when the base and
// ORM maps are both files in `dir`; a file's own images keep the two lookups.
Material make_model_material(const modelio::ImportedMaterial& src, const std::filesystem::path& dir,
                             TextureCache& textures, const MapSource& maps);

} // namespace ks::render
