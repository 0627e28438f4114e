#include "level/level_migrate.h"

#include "level/level.h"
#include "level/shutdown_objective.h"

namespace ks::level {
namespace {

using Json = nlohmann::ordered_json;

// Version 0 (the prototype's format) kept entities under "objects" and gave each a single "yaw" number
// instead of the [yaw, pitch, roll] "rotation" triple.
void migrate_0_to_1(Json& document) {
    if (document.is_object() && document.contains("objects") && !document.contains("entities")) {
        // Rebuild the object so that "entities" takes the place of "objects" in the key order.
        Json renamed = Json::object();
        for (auto& [key, value] : document.items())
            renamed[key == "objects" ? "entities" : key] = std::move(value);
        document = std::move(renamed);
    }
    auto entities = document.find("entities");
    if (entities == document.end() || !entities->is_array()) return;
    for (Json& entity : *entities) {
        if (!entity.is_object()) continue;
        auto yaw = entity.find("yaw");
        if (yaw == entity.end()) continue;
        if (!entity.contains("rotation")) entity["rotation"] = Json::array({*yaw, 0, 0});
        entity.erase("yaw");
    }
}

// Version 1 had no level logic: using a control panel won the level. Version 2 wins when every objective is
// complete, and a panel does only what its links say; so a version-1 level gets the objective it always had
// (shut the simulation down) and each panel a link completing it. Keys that version 1 ignored as unknown
// ("objectives", "links") are dropped, so the level plays exactly as it did.
void migrate_1_to_2(Json& document) {
    if (!document.is_object()) return;
    document.erase("objectives");
    document.erase("links");
    auto entities = document.find("entities");
    if (entities == document.end() || !entities->is_array()) return;
    bool has_panel = false;
    for (Json& entity : *entities) {
        if (!entity.is_object()) continue;
        entity.erase("links");
        auto type = entity.find("type");
        if (type == entity.end() || *type != "control_panel") continue;
        has_panel = true;
        entity["links"] = Json::array({Json{{"event", "on_use"},
                                            {"target", kShutdownObjective},
                                            {"action", "complete"},
                                            {"delay", 0},
                                            {"once", false}}});
    }
    if (has_panel)
        document["objectives"] =
            Json::array({Json{{"id", kShutdownObjective}, {"text", kShutdownObjectiveText}}});
}

// Version 3 added the brush entity. A version-2 file has none (its readers refused the type), so every entity
// reads as it did and the document needs no change; the step exists so the version says which types a file
// may hold, and a version-2 file is saved as version 3.
void migrate_2_to_3(Json&) {}

// Version 4 added the model entity; like 2 -> 3, a version-3 file reads unchanged.
void migrate_3_to_4(Json&) {}

} // namespace

const std::vector<Migration>& migrations() {
    static const std::vector<Migration> table = {
        {0, "\"objects\" renamed \"entities\"; an entity's \"yaw\" number became \"rotation\": [yaw, 0, 0]",
         &migrate_0_to_1},
        {1,
         "the control panel's win became the objective \"shutdown\", completed by each panel's on_use link",
         &migrate_1_to_2},
        {2, "the brush entity type was added (nothing in a version-2 level changes)", &migrate_2_to_3, false},
        {3, "the model entity type was added (nothing in a version-3 level changes)", &migrate_3_to_4, false},
    };
    return table;
}

std::vector<std::string> migrate(Json& document, int version) {
    std::vector<std::string> applied;
    for (int v = version; v < kFormatVersion; ++v) {
        const Migration& step = migrations().at(static_cast<size_t>(v));
        step.apply(document);
        if (step.changes_document)
            applied.push_back("version " + std::to_string(v) + " -> " + std::to_string(v + 1) + ": " +
                              step.summary);
    }
    return applied;
}

} // namespace ks::level
