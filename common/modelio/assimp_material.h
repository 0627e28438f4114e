#pragma once
// A model file's material as assimp reads it, in modelio's terms: factors, sides and texture names. The one
// reading that designers' models (import_model) and the shipped models (render's load_model) share.
#include "modelio/model_import.h"

struct aiMaterial;

namespace ks::modelio {

// Base colour (glTF's factor, else the diffuse colour), emissive times its strength, metallic and roughness
// factors, doubleSided (true where the file cannot say), and the texture names of the base colour, normal,
// metal-roughness (ORM) and emissive maps as the file writes them ("*N": the file's own image N).
ImportedMaterial read_material(const aiMaterial& material);

} // namespace ks::modelio
