#pragma once
// Where a level's model files are, and reading each one once. A level names a model by a file name relative
// to a models folder ("crates/crate.glb"): the shipped assets/models first (so a shipped level is the same on
// every machine), then the designer's own models folder in the user data folder (core/paths.h).
#include "modelio/model_import.h"

#include <filesystem>
#include <memory>
#include <string_view>

namespace ks::modelio {

// user_data_dir()/models; empty when there is no user data folder.
std::filesystem::path user_models_dir();

// A model name as a level writes it: not empty, relative, '/' between folders, no "." or ".." parts, no
// backslash, and one of supported_extensions(). The Error says which rule is broken (no location: the caller
// names the entity and field).
Result<void> check_model_name(std::string_view name);

// The file `name` stands for: assets/models/name where it exists, else user_models_dir()/name where that
// exists, else the shipped path (so a message names where it was looked for first).
std::filesystem::path resolve_model_file(std::string_view name);

// import_model through a cache keyed by the file's path, size and modification time: a level that places a
// model many times reads it once, and a file changed on disk is read again. Failures are cached the same way.
// The import is kept in draw order (optimize_draw_order) with its levels of detail (build_lods). Safe to
// call from several threads.
Result<std::shared_ptr<const ImportedModel>> import_cached(const std::filesystem::path& path);

} // namespace ks::modelio
