#include "level/level_migrate.h"

#include "level/level.h"

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

} // namespace

const std::vector<Migration>& migrations() {
    static const std::vector<Migration> table = {
        {0, "\"objects\" renamed \"entities\"; an entity's \"yaw\" number became \"rotation\": [yaw, 0, 0]",
         &migrate_0_to_1},
    };
    return table;
}

std::vector<std::string> migrate(Json& document, int version) {
    std::vector<std::string> applied;
    for (int v = version; v < kFormatVersion; ++v) {
        const Migration& step = migrations().at(static_cast<size_t>(v));
        step.apply(document);
        applied.push_back("version " + std::to_string(v) + " -> " + std::to_string(v + 1) + ": " +
                          step.summary);
    }
    return applied;
}

} // namespace ks::level
