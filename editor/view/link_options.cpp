#include "view/link_options.h"

#include "level/diagnostics.h"

#include <algorithm>

namespace ks::editor {

namespace {
std::string entity_label(const level::Entity& e) {
    const std::string type(level::type_name(e.type()));
    if (e.name.empty()) return type + " #" + std::to_string(e.id) + " (unnamed)";
    return e.name + " (" + type + ")";
}

// The one entity called `name`, or null (none, or several).
const level::Entity* unique_entity(const level::Level& level, std::string_view name) {
    if (name.empty()) return nullptr;
    const level::Entity* found = nullptr;
    for (const auto& e : level.entities) {
        if (e.name != name) continue;
        if (found) return nullptr;
        found = &e;
    }
    return found;
}

bool has_objective(const level::Level& level, std::string_view id) {
    return std::any_of(level.objectives.begin(), level.objectives.end(),
                       [&](const level::Objective& o) { return o.id == id; });
}
} // namespace

std::vector<TargetOption> target_options(const level::Level& level) {
    std::vector<TargetOption> out;
    for (const auto& o : level.objectives)
        out.push_back({level::TargetKind::Objective, o.id, 0, "objective " + o.id});
    out.push_back({level::TargetKind::Level, std::string(level::kLevelTarget), 0, "level"});
    for (const auto& e : level.entities)
        if (!level::entity_actions(e.type()).empty())
            out.push_back({level::TargetKind::Entity, e.name, e.id, entity_label(e)});
    return out;
}

level::TargetKind link_target_kind(const level::Level& level, const level::Link& link) {
    if (auto action = level::action_from_name(link.action)) return level::target_kind(*action);
    if (link.target == level::kLevelTarget) return level::TargetKind::Level;
    if (has_objective(level, link.target) && !unique_entity(level, link.target))
        return level::TargetKind::Objective;
    return level::TargetKind::Entity;
}

std::vector<std::string> target_actions(const level::Level& level, level::TargetKind kind,
                                        std::string_view target) {
    switch (kind) {
    case level::TargetKind::Level:
        return {"win", "lose"};
    case level::TargetKind::Objective:
        return {"complete"};
    case level::TargetKind::Entity:
        break;
    }
    const level::Entity* e = unique_entity(level, target);
    return e ? level::action_names(level::entity_actions(e->type())) : std::vector<std::string>{};
}

std::string action_for_target(const std::vector<std::string>& actions, const std::string& current) {
    if (std::find(actions.begin(), actions.end(), current) != actions.end()) return current;
    return actions.empty() ? std::string() : actions.front();
}

std::string target_label(const level::Level& level, level::TargetKind kind, std::string_view target) {
    switch (kind) {
    case level::TargetKind::Level:
        return "level";
    case level::TargetKind::Objective:
        return "objective " + std::string(target);
    case level::TargetKind::Entity:
        break;
    }
    if (target.empty()) return "(no target)";
    if (const level::Entity* e = unique_entity(level, target)) return entity_label(*e);
    return "\"" + std::string(target) + "\"";
}

std::optional<std::string> pick_refusal(const level::Level& level, int entity_id) {
    const level::Entity* e = level.find(entity_id);
    if (!e) return "entity " + std::to_string(entity_id) + " does not exist";
    if (!level::entity_actions(e->type()).empty()) return std::nullopt;
    return level::entity_subject(*e) +
           " takes no action: pick a door, light, trigger, robot, spawner, message or sound";
}

std::vector<TargetOption> kill_options(const level::Level& level) {
    std::vector<TargetOption> out;
    for (const auto& e : level.entities)
        if (e.type() == level::EntityType::Robot || e.type() == level::EntityType::Spawner)
            out.push_back({level::TargetKind::Entity, e.name, e.id, entity_label(e)});
    return out;
}

std::optional<std::string> kill_refusal(const level::Level& level, int entity_id) {
    const level::Entity* e = level.find(entity_id);
    if (!e) return "entity " + std::to_string(entity_id) + " does not exist";
    if (e->type() == level::EntityType::Robot || e->type() == level::EntityType::Spawner) return std::nullopt;
    return level::entity_subject(*e) + " cannot be killed: pick a robot or a spawner";
}

std::vector<IncomingLink> incoming_links(const level::Level& level, int entity_id) {
    std::vector<IncomingLink> out;
    const level::Entity* target = level.find(entity_id);
    if (!target || target->name.empty()) return out;
    auto scan = [&](const std::vector<level::Link>& links, int source_entity, const std::string& source) {
        for (const auto& link : links)
            if (link.target == target->name && link_target_kind(level, link) == level::TargetKind::Entity)
                out.push_back({source_entity, source, link_label(link)});
    };
    for (const auto& e : level.entities) scan(e.links, e.id, entity_label(e));
    for (const auto& o : level.objectives) scan(o.links, 0, "objective " + o.id);
    scan(level.links, 0, "level");
    return out;
}

std::string link_label(const level::Link& link) {
    return link.event + " -> " + link.action;
}

} // namespace ks::editor
