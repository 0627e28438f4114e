#pragma once
// Editing a level's logic (links and objectives), window-free. The Editor's methods (editor.h, implemented in
// edit_logic.h) name a list of links by its owner; the helpers here check a link against its source and
// keep link targets and kill lists pointing at what they meant when an entity or an objective is renamed.
#include "core/result.h"
#include "level/level.h"
#include "level/logic_names.h"

#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ks::editor {

class LevelChange;

// Who owns a list of links: an entity (by id), an objective (by id string) or the level (on_start).
struct LinkOwner {
    enum class Kind { Entity, Objective, Level } kind = Kind::Level;
    int entity_id = 0;
    std::string objective_id;
    static LinkOwner entity(int id);
    static LinkOwner objective(std::string id);
    static LinkOwner level();
    bool operator==(const LinkOwner&) const = default;
};

// "\"text\"": how messages quote a name.
std::string in_quotes(std::string_view s);
// An error "no WHAT INDEX on OWNER" (with the valid range) unless 0 <= index < size.
Result<void> check_index(int index, size_t size, const std::string& what, const std::string& owner);

// The events an owner's links may listen to: an entity's type's (level/logic_names.h), on_complete for an
// objective, on_start for the level.
std::span<const level::LinkEvent> owner_events(const level::Level& level, const LinkOwner& owner);
// "door 12 (\"Gate\")", "objective \"clear_hall\"", "the level": how messages name an owner.
std::string owner_subject(const level::Level& level, const LinkOwner& owner);

// What the editor refuses in a link whatever the rest of the level holds: an event `events` does not hold
// (with a did-you-mean), an unknown action, a negative, NaN or over-an-hour delay. The target may name
// nothing yet (a draft); validation reports it.
Result<void> check_link(const level::Link& link, std::span<const level::LinkEvent> events,
                        std::string_view source);

// Old name -> new name, for entity names (link targets of entity actions, kill lists) and objective ids
// (link targets of `complete`).
struct TargetRenames {
    std::unordered_map<std::string, std::string> entities, objectives;
    bool empty() const { return entities.empty() && objectives.empty(); }
};
// Rewrites the targets in `links` that `renames` covers; returns whether any changed.
bool retarget_links(std::vector<level::Link>& links, const TargetRenames& renames);
// Adds to `change` the updates that make every link and kill list of `level` (as `change` leaves it) follow
// `renames`, so a rename and its re-targeting are one undo step.
void add_retargets(const level::Level& level, const TargetRenames& renames, LevelChange& change);
// The entity renames in `change` whose old name was unique in `level` (before the change) and whose new
// name is not empty: the targets that follow them are added to `change` (add_retargets).
void follow_entity_renames(const level::Level& level, LevelChange& change);

// A name no entity of `level` has: `base` followed by "_1", "_2", ... (the first free one).
std::string unique_entity_name(const level::Level& level, std::string_view base);

} // namespace ks::editor
