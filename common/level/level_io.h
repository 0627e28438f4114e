#pragma once
// Loading and saving level files (format v2). Loading validates everything and reports every problem at
// once (file, line:column where known, JSON path, what would be valid); saving is deterministic so that
// load -> save -> load -> save is byte-identical.
#include "core/result.h"
#include "level/level.h"

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace ks::level {

struct Diagnostic {
    enum class Severity { Warning, Error } severity = Severity::Error;
    Error error; // message, location (file, line, column, JSON path), hint
    // The logic findings a tool can offer a fix for (the editor's quick fixes); Other for everything else.
    // DanglingTarget: a link target or kill-list name that names nothing; LogicLoop: a zero-delay loop (the
    // path is one link of it); ObjectiveNeverCompletes: the path is the objective (nothing completes it) or
    // a kill-list name (a spawner nothing starts); LockedDoor: a locked door nothing frees; DisabledTrigger: a
    // trigger with links that starts disabled and that no link enables. UnknownTexture: a
    // texture field naming no surface material in assets/textures (level/texture_names.h).
    enum class Kind {
        Other,
        DanglingTarget,
        LogicLoop,
        ObjectiveNeverCompletes,
        LockedDoor,
        DisabledTrigger,
        UnknownTexture
    } kind = Kind::Other;
    // DanglingTarget, UnknownTexture: the name that would resolve ("did you mean"), or ""
    std::string suggestion{};
};

struct LoadReport {
    std::vector<Diagnostic> diagnostics; // every warning and error found, in document order
    bool has_errors() const;
    int error_count() const;
    int warning_count() const;
    std::string str() const; // one diagnostic per line
};

// Parses and validates. On any error the Result holds one combined Error listing all of them; `report`, when
// given, receives every diagnostic (warnings too) either way.
Result<Level> load_level_string(std::string_view text, const std::string& file_name,
                                LoadReport* report = nullptr);
Result<Level> load_level_file(const std::filesystem::path& path, LoadReport* report = nullptr);

// Deterministic text: stable key order, entities in their order, floats printed shortest round-trip.
std::string save_level_string(const Level& level);
// Atomic write (core/files). Refuses nothing: validation is the caller's business (the editor saves drafts).
Result<void> save_level_file(const std::filesystem::path& path, const Level& level);

// One entity as JSON (the editor's copy/paste format), and back with the same validation as a level file.
nlohmann::json entity_to_json(const Entity& entity);
Result<Entity> entity_from_json(const nlohmann::json& json, const std::string& context,
                                LoadReport* report = nullptr);

// Semantic checks on an in-memory level (ranges, NaN, duplicate ids, next_id > every id, ...), the same
// ones the loader runs after parsing. The editor calls it live.
LoadReport validate(const Level& level, const std::string& file_name = {});

} // namespace ks::level
