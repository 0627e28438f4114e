#pragma once
// What the inspector's link rows offer, window-free (level/logic_names.h is the vocabulary): the events a
// source emits, the targets a link may name (objectives, the level, and every entity that takes at least one
// action, unnamed ones too: they are named when picked), the actions the chosen target takes, and what a pick
// in the viewport does with the entity it hits.
#include "level/level.h"
#include "level/logic_names.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

// One entry of a link's target list.
struct TargetOption {
    level::TargetKind kind = level::TargetKind::Entity;
    std::string target; // what the link's `target` becomes: the entity's name, the objective's id, "level"
    int entity_id = 0;  // an entity: its id (its name may be empty: ensure_link_name names it on pick)
    std::string label;  // "Exit door (door)", "door #12 (unnamed)", "objective clear_hall", "level"
};

// The objectives, then the level, then the entities that take an action, in level order.
std::vector<TargetOption> target_options(const level::Level& level);

// What a link's target names, read from its action when that is known (complete: an objective; win and
// lose: the level), else from the name itself ("level", an objective's id, else an entity).
level::TargetKind link_target_kind(const level::Level& level, const level::Link& link);

// The actions the link's target takes: an entity's by its type (none when the name resolves to no entity or
// to several), complete for an objective, win and lose for the level.
std::vector<std::string> target_actions(const level::Level& level, level::TargetKind kind,
                                        std::string_view target);

// The action a link keeps when its target changes: its own if the new target takes it, else the new
// target's first action (empty when it takes none).
std::string action_for_target(const std::vector<std::string>& actions, const std::string& current);

// The label a link's current target shows in its combo: as in target_options, or the raw name (a dangling
// target) in quotes.
std::string target_label(const level::Level& level, level::TargetKind kind, std::string_view target);

// A pick in the viewport that hit `entity_id`: nullopt when the entity takes an action (the pick goes on),
// else why the link stays as it is ("wall #3 \"North\" takes no action: ...").
std::optional<std::string> pick_refusal(const level::Level& level, int entity_id);

// The robots and spawners an objective's kill list may name, in level order (unnamed ones too: they are
// named when chosen).
std::vector<TargetOption> kill_options(const level::Level& level);
// As pick_refusal, for a kill list: nullopt for a robot or a spawner.
std::optional<std::string> kill_refusal(const level::Level& level, int entity_id);

// A link that acts on an entity, seen from that entity (the inspector's "Incoming" list).
struct IncomingLink {
    int source_entity = 0; // 0: an objective's or the level's link
    std::string source;    // "Hall trigger (trigger)", "objective clear_hall", "level"
    std::string label;     // "on_enter -> spawn"
};
// Every link in the level whose target is the entity (by its name: none when it has no name).
std::vector<IncomingLink> incoming_links(const level::Level& level, int entity_id);

// "on_enter -> open" (the editor's font has no arrow glyph).
std::string link_label(const level::Link& link);

} // namespace ks::editor
