#pragma once
// JSON (already parsed, already migrated to the current version) -> Level. Checks shapes and types: a wrong
// type, a missing required field, a number that is not finite, an unknown field. Every problem goes to the
// sink and the field keeps its default, so reading always finishes and reports everything. Range checks
// live in level_checks (they apply to in-memory levels too).
#include "level/diagnostics.h"
#include "level/level.h"

#include <nlohmann/json.hpp>
#include <optional>

namespace ks::level {

struct ReadLevel {
    Level level;
    // For each entity in level.entities, its index in the file's "entities" array (entities too broken to
    // build -- no id, unknown type -- are left out, so the two can differ).
    std::vector<size_t> source_index;
};

ReadLevel read_level(const nlohmann::ordered_json& document, DiagnosticSink& sink);
std::optional<Entity> read_entity(const nlohmann::ordered_json& json, const std::string& path,
                                  DiagnosticSink& sink);

} // namespace ks::level
