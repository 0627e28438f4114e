#pragma once
// The texture names a level may use: the surface materials in assets/textures, each a set of
// <name>_basecolor.png and <name>_height.png (docs/assets.md, "Surface materials"; the models' own textures
// have no height map). This is the one list of known names: the loader's check, the editor's texture rule
// and its texture browser all read it, so a material the generator adds is known everywhere at once.
#include "level/diagnostics.h"
#include "level/level.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::level {

// Whether a string field holds a texture name: every type's field called "texture" (walls, floors, stairs).
bool is_texture_field(std::string_view field_name);

// The surface materials in `folder`, sorted; empty when the folder is missing or cannot be read.
std::vector<std::string> surface_texture_names_in(const std::filesystem::path& folder);
// surface_texture_names_in(assets/textures), the folder found through core/paths; listed once per process
// (the folder belongs to the asset generator and does not change while a program runs).
const std::vector<std::string>& shipped_texture_names();

// The texture names of an entity's fields, with the field's path below the entity's props: "texture", or
// a brush face's "faces[3].material" (none for types without textures).
struct TextureField {
    std::string field;
    const std::string* name;
};
std::vector<TextureField> texture_fields(const Entity& entity);

// A warning for every texture field naming no material in `known`, at its JSON path, naming the entity,
// with the closest known name as the did-you-mean (tagged Diagnostic::Kind::UnknownTexture, suggestion set)
// or the list of known names. An empty name is the format's error, not this one; an empty `known` (no
// assets found) checks nothing. `source_index` as in check_level.
void check_texture_names(const Level& level, const std::vector<std::string>& known, DiagnosticSink& sink,
                         const std::vector<size_t>& source_index = {});

} // namespace ks::level
