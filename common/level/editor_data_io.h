#pragma once
// The level file's "editor" section (level/editor_data.h) to and from JSON. Reading never fails: a wrong
// type, an unknown field, an id that names no entity or group is a warning naming its JSON path, and that
// part is left out (a designer's layers are worth keeping even when one entry is broken, and the game does
// not need any of it).
#include "level/diagnostics.h"
#include "level/editor_data.h"
#include "level/level.h"

#include <nlohmann/json.hpp>

namespace ks::level {

// Empty data writes nothing: callers leave the "editor" key out (files without layers stay as they were).
nlohmann::ordered_json write_editor_data(const EditorData& data);
EditorData read_editor_data(const nlohmann::ordered_json& json, const std::string& path,
                            DiagnosticSink& sink);
// Drops what names no entity of `level` (or no group of `data`), entities listed twice (a second layer,
// a second group) and group cycles, each with a warning at `path`; sorts the id lists.
void reconcile_editor_data(EditorData& data, const Level& level, const std::string& path,
                           DiagnosticSink& sink);

} // namespace ks::level
