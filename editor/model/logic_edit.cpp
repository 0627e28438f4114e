#include "model/logic_edit.h"

#include "jsonio/number_text.h"
#include "jsonio/suggest.h"
#include "level/diagnostics.h"
#include "level/logic_checks.h"
#include "model/command.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ks::editor {
namespace {
using level::LinkAction;
using level::TargetKind;

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
    const std::string near = jsonio::closest_match(word, candidates);
    return near.empty() ? std::string() : "did you mean " + in_quotes(near) + "? ";
}

// What a link's target names, from its action; an unknown action leaves it open (both could be meant).
bool targets_entity(const level::Link& link) {
    const auto action = level::action_from_name(link.action);
    return !action || level::target_kind(*action) == TargetKind::Entity;
}
bool targets_objective(const level::Link& link) {
    const auto action = level::action_from_name(link.action);
    return !action || level::target_kind(*action) == TargetKind::Objective;
}

const std::string* renamed(const std::unordered_map<std::string, std::string>& names,
                           const std::string& old) {
    auto it = names.find(old);
    return it == names.end() ? nullptr : &it->second;
}

bool retarget_kills(std::vector<std::string>& kill, const TargetRenames& renames) {
    bool changed = false;
    for (std::string& name : kill)
        if (const std::string* now = renamed(renames.entities, name)) name = *now, changed = true;
    return changed;
}

// The current state of entity `e` in `change` (its pending after-copy), or null when the change leaves it.
level::Entity* pending_update(LevelChange& change, int id) {
    for (EntityUpdate& u : change.updates)
        if (u.after.id == id) return &u.after;
    return nullptr;
}
} // namespace

std::string in_quotes(std::string_view s) {
    return "\"" + std::string(s) + "\"";
}

Result<void> check_index(int index, size_t size, const std::string& what, const std::string& owner) {
    if (index >= 0 && static_cast<size_t>(index) < size) return ok();
    return Error("no " + what + " " + std::to_string(index) + " on " + owner, Location{},
                 size == 0
                     ? owner + " has none"
                     : "valid: 0 .. " + std::to_string(size - 1) + " (" + std::to_string(size) + " in all)");
}

LinkOwner LinkOwner::entity(int id) {
    LinkOwner owner;
    owner.kind = Kind::Entity;
    owner.entity_id = id;
    return owner;
}

LinkOwner LinkOwner::objective(std::string id) {
    LinkOwner owner;
    owner.kind = Kind::Objective;
    owner.objective_id = std::move(id);
    return owner;
}

LinkOwner LinkOwner::level() {
    return LinkOwner{};
}

std::span<const level::LinkEvent> owner_events(const level::Level& level, const LinkOwner& owner) {
    static constexpr std::array kLevelEvents{level::kLevelEvent};
    static constexpr std::array kObjectiveEvents{level::kObjectiveEvent};
    switch (owner.kind) {
    case LinkOwner::Kind::Entity:
        if (const level::Entity* e = level.find(owner.entity_id)) return level::entity_events(e->type());
        return {};
    case LinkOwner::Kind::Objective:
        return kObjectiveEvents;
    case LinkOwner::Kind::Level:
        return kLevelEvents;
    }
    return {};
}

std::string owner_subject(const level::Level& level, const LinkOwner& owner) {
    switch (owner.kind) {
    case LinkOwner::Kind::Entity:
        if (const level::Entity* e = level.find(owner.entity_id)) return level::entity_subject(*e);
        return "entity " + std::to_string(owner.entity_id);
    case LinkOwner::Kind::Objective:
        return "objective " + in_quotes(owner.objective_id);
    case LinkOwner::Kind::Level:
        return "the level";
    }
    return {};
}

Result<void> check_link(const level::Link& link, std::span<const level::LinkEvent> events,
                        std::string_view source) {
    const std::vector<std::string> event_names = level::event_names(events);
    if (events.empty())
        return Error(std::string(source) + " emits no events, so its links would never fire", Location{},
                     "links belong on triggers, robots, doors, floor lights, control panels, pickups, "
                     "objectives and the level");
    const auto event = level::event_from_name(link.event);
    if (!event || std::find(events.begin(), events.end(), *event) == events.end())
        return Error((event ? std::string(source) + " does not emit " : std::string("unknown event ")) +
                         in_quotes(link.event),
                     Location{},
                     did_you_mean(link.event, event_names) + std::string(source) +
                         " emits: " + jsonio::join(event_names));
    if (!level::action_from_name(link.action)) {
        const std::vector<std::string> actions = level::action_names(level::all_actions());
        return Error("unknown action " + in_quotes(link.action), Location{},
                     did_you_mean(link.action, actions) + "actions: " + jsonio::join(actions));
    }
    if (!std::isfinite(link.delay) || link.delay < 0.0f ||
        link.delay > static_cast<float>(level::kMaxLinkDelay))
        return Error(std::isfinite(link.delay)
                         ? "delay " + jsonio::format_readable(jsonio::float_to_double(link.delay)) +
                               " is out of range"
                         : std::string("the delay is not a finite number"),
                     Location{},
                     "valid: 0 .. " + jsonio::format_readable(level::kMaxLinkDelay) +
                         " s, the seconds between the event and the action");
    return ok();
}

bool retarget_links(std::vector<level::Link>& links, const TargetRenames& renames) {
    bool changed = false;
    for (level::Link& link : links) {
        const std::string* now = nullptr;
        if (targets_entity(link)) now = renamed(renames.entities, link.target);
        if (!now && targets_objective(link)) now = renamed(renames.objectives, link.target);
        if (now) link.target = *now, changed = true;
    }
    return changed;
}

void add_retargets(const level::Level& level, const TargetRenames& renames, LevelChange& change) {
    if (renames.empty()) return;
    for (const level::Entity& e : level.entities) {
        if (e.links.empty()) continue;
        if (level::Entity* pending = pending_update(change, e.id)) {
            retarget_links(pending->links, renames);
            continue;
        }
        level::Entity after = e;
        if (retarget_links(after.links, renames)) change.updates.push_back({e, std::move(after)});
    }
    std::vector<level::Link> links = change.level_links ? change.level_links->after : level.links;
    if (retarget_links(links, renames))
        change.level_links = Change<std::vector<level::Link>>{
            change.level_links ? change.level_links->before : level.links, std::move(links)};
    std::vector<level::Objective> objectives =
        change.objectives ? change.objectives->after : level.objectives;
    bool objectives_changed = false;
    for (level::Objective& o : objectives) {
        objectives_changed |= retarget_links(o.links, renames);
        objectives_changed |= retarget_kills(o.kill, renames);
    }
    if (objectives_changed)
        change.objectives = Change<std::vector<level::Objective>>{
            change.objectives ? change.objectives->before : level.objectives, std::move(objectives)};
}

void follow_entity_renames(const level::Level& level, LevelChange& change) {
    TargetRenames renames;
    for (const EntityUpdate& u : change.updates)
        if (u.before.name != u.after.name && !u.before.name.empty() && !u.after.name.empty())
            renames.entities.emplace(u.before.name, u.after.name);
    if (renames.empty()) return;
    // A name two entities share targets nothing for sure: links naming it stay as they are (the checks
    // report them as ambiguous either way).
    const level::NameIndex names(level);
    std::erase_if(renames.entities, [&](const auto& rename) { return names.find(rename.first).size() != 1; });
    add_retargets(level, renames, change);
}

std::string unique_entity_name(const level::Level& level, std::string_view base) {
    const level::NameIndex names(level);
    for (int n = 1;; ++n) {
        std::string candidate = std::string(base) + "_" + std::to_string(n);
        if (names.find(candidate).empty()) return candidate;
    }
}

} // namespace ks::editor
