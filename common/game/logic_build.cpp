// The level logic's tables, built once at Game::create: every link resolved to the game record it acts on,
// objectives with their kill lists, triggers, messages and sound emitters (the spawners build their own). A
// level that was validated resolves completely; one that was not (an editor draft) loses only the links that
// do not resolve, each reported in logic().problems().
#include "game/interactables.h"
#include "game/level_logic.h"
#include "game/robot_system.h"

#include "level/logic_checks.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

using level::EntityType;
using level::LinkAction;

template <class Records>
std::optional<std::uint32_t> index_of(const Records& records, int entity_id) {
    for (std::size_t i = 0; i < records.size(); ++i)
        if (records[i].entity_id == entity_id) return static_cast<std::uint32_t>(i);
    return std::nullopt;
}

TriggerState make_trigger(const level::Entity& e, const level::TriggerProps& t) {
    const TriggerWho who = t.who.value == "robots" ? TriggerWho::Robots
                           : t.who.value == "both" ? TriggerWho::Both
                                                   : TriggerWho::Player;
    return {e.id, level::upright_frame(e), t.size, who, t.enabled, false};
}

// The game's records a link may act on, by kind.
struct Records {
    std::span<const Door> doors;
    std::span<const Light> lights;
    std::span<const Robot> robots;
    std::span<const TriggerState> triggers;
    std::span<const SpawnerState> spawners;
    std::span<const MessageEntity> messages;
    std::span<const SoundEntity> sounds;
};

// Resolves `link` into `out`, or says in `problem` why it cannot be.
bool resolve_link(const level::Link& link, const level::Level& level, const level::NameIndex& names,
                  const Records& records, double step, LogicLink& out, std::string& problem) {
    const auto event = level::event_from_name(link.event);
    const auto action = level::action_from_name(link.action);
    if (!event || !action) return problem = "unknown event or action", false;
    if (!std::isfinite(link.delay) || link.delay < 0.0f) return problem = "bad delay", false;
    out.event = *event;
    out.action = *action;
    out.once = link.once;
    // Rounded to whole steps, but a positive delay is never rounded to none: a designer who wrote 0.004 s
    // meant "later", and a zero-step chain of door links would loop within one step (the loop check, which
    // reads the file, only warns about delays of exactly 0).
    out.delay_steps = std::llround(std::min(static_cast<double>(link.delay), level::kMaxLinkDelay) / step);
    if (link.delay > 0.0f) out.delay_steps = std::max<long long>(out.delay_steps, 1);
    switch (level::target_kind(*action)) {
    case level::TargetKind::Level:
        out.target = LogicTarget::Level;
        out.target_end = {LogicEnd::Kind::Level, -1};
        return true;
    case level::TargetKind::Objective: {
        const auto& objectives = level.objectives;
        const auto it = std::find_if(objectives.begin(), objectives.end(),
                                     [&](const level::Objective& o) { return o.id == link.target; });
        if (it == objectives.end()) return problem = "no such objective", false;
        out.target = LogicTarget::Objective;
        out.target_index = static_cast<std::uint32_t>(it - objectives.begin());
        out.target_end = {LogicEnd::Kind::Objective, static_cast<int>(out.target_index)};
        return true;
    }
    case level::TargetKind::Entity:
        break;
    }
    const auto found = names.find(link.target);
    if (found.size() != 1)
        return problem = found.empty() ? "no entity of that name" : "the name is not unique", false;
    const level::Entity& target = level.entities[found.front()];
    if (!level::entity_takes(target.type(), *action))
        return problem = "the target does not take the action", false;
    std::optional<std::uint32_t> index;
    switch (target.type()) {
    case EntityType::Door:
        out.target = LogicTarget::Door, index = index_of(records.doors, target.id);
        break;
    case EntityType::FloorLight:
    case EntityType::TopLight:
        out.target = LogicTarget::Light, index = index_of(records.lights, target.id);
        break;
    case EntityType::Trigger:
        out.target = LogicTarget::Trigger, index = index_of(records.triggers, target.id);
        break;
    case EntityType::Robot:
        out.target = LogicTarget::Robot, index = index_of(records.robots, target.id);
        break;
    case EntityType::Spawner:
        out.target = LogicTarget::Spawner, index = index_of(records.spawners, target.id);
        break;
    case EntityType::Message:
        out.target = LogicTarget::Message, index = index_of(records.messages, target.id);
        break;
    case EntityType::Sound:
        out.target = LogicTarget::Sound, index = index_of(records.sounds, target.id);
        break;
    default:
        break;
    }
    if (!index) return problem = "the target is not in the game (an animation dummy?)", false;
    out.target_index = *index;
    out.target_end = {LogicEnd::Kind::Entity, target.id};
    return true;
}

} // namespace

void LevelLogic::build(const level::Level& level) {
    const double step = core_.settings.step;
    for (const level::Entity& e : level.entities) {
        if (const auto* t = e.try_as<level::TriggerProps>())
            triggers_.push_back(make_trigger(e, *t));
        else if (const auto* m = e.try_as<level::MessageProps>())
            messages_.push_back({e.id, m->text, m->duration});
        else if (const auto* sound = e.try_as<level::SoundProps>())
            sounds_.push_back({e.id, sound->sound.value, e.position, sound->volume, sound->radius});
        else if (const auto* door = e.try_as<level::DoorProps>(); door && door->locked)
            uses_locks_ = true;
    }
    robot_dead_.assign(robots_.robots().size(), false);

    const level::NameIndex names(level);
    const Records records{interactables_.doors(),
                          interactables_.lights(),
                          robots_.robots(),
                          triggers_,
                          spawners_.spawners(),
                          messages_,
                          sounds_};
    auto add_links = [&](const std::vector<level::Link>& links, std::span<const level::LinkEvent> emitted,
                         std::string_view owner, LogicEnd owner_end) {
        LinkRange range{static_cast<std::uint32_t>(links_.size()), 0};
        for (const level::Link& link : links) {
            if (range.count >= static_cast<std::uint32_t>(level::kMaxLinks)) break;
            LogicLink resolved;
            std::string problem;
            if (!resolve_link(link, level, names, records, step, resolved, problem)) {
                report(std::string(owner) + ": link " + link.event + " -> " + link.action + " " +
                       link.target + ": " + problem + " (the link is ignored)");
                continue;
            }
            if (std::find(emitted.begin(), emitted.end(), resolved.event) == emitted.end()) {
                report(std::string(owner) + " does not emit " + link.event + " (the link is ignored)");
                continue;
            }
            if (resolved.action == LinkAction::Lock || resolved.action == LinkAction::Unlock)
                uses_locks_ = true;
            resolved.source_end = owner_end;
            links_.push_back(resolved);
            ++range.count;
        }
        return range;
    };

    for (const level::Objective& o : level.objectives) {
        ObjectiveState state;
        state.id = o.id;
        state.text = o.text;
        state.kill_condition = !o.kill.empty();
        for (const std::string& name : o.kill) {
            const auto found = names.find(name);
            const int id = found.size() == 1 ? level.entities[found.front()].id : 0;
            if (const auto robot = index_of(records.robots, id)) {
                state.kill_robots.push_back(*robot);
            } else if (const auto spawner = index_of(records.spawners, id)) {
                state.kill_spawners.push_back(*spawner);
            } else {
                state.kill_condition = false;
                report("objective \"" + o.id + "\": nothing to kill is called \"" + name +
                       "\", so killing cannot complete it");
            }
        }
        objectives_.push_back(std::move(state));
    }
    for (std::size_t i = 0; i < level.objectives.size(); ++i) {
        const std::array events{level::kObjectiveEvent};
        objectives_[i].links =
            add_links(level.objectives[i].links, events, "objective \"" + level.objectives[i].id + "\"",
                      {LogicEnd::Kind::Objective, static_cast<int>(i)});
    }
    const std::array level_events{level::kLevelEvent};
    level_links_ = add_links(level.links, level_events, "the level", {LogicEnd::Kind::Level, -1});
    for (const level::Entity& e : level.entities) {
        if (e.links.empty()) continue;
        const LinkRange range = add_links(e.links, level::entity_events(e.type()), level::entity_subject(e),
                                          {LogicEnd::Kind::Entity, e.id});
        if (range.count > 0) entity_links_[e.id] = range;
    }
    ready_.reserve(2 * static_cast<std::size_t>(LevelLogic::kMaxActionsPerStep));
    pending_.reserve(LevelLogic::kMaxPending);
}

} // namespace ks::game
