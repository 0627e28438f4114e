// The level logic's part of a step (after everything else has moved): due actions, the level's on_start,
// the message's clock, trigger volumes, then the cascade -- this step's game events become link events,
// ready actions run and set off more (through the other systems' interfaces). The Game then runs the
// spawners, and check_won wins when every objective is complete.
#include "game/interactables.h"
#include "game/level_logic.h"
#include "game/player_system.h"
#include "game/robot_system.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ks::game {

using level::LinkAction;
using level::LinkEvent;

void LevelLogic::step(float dt) {
    begin_step();
    if (!std::exchange(started_, true)) {
        record_event({LogicEnd::Kind::Level, -1}, LinkEvent::OnStart);
        fire(level_links_, LinkEvent::OnStart);
    }
    if (message_.visible()) message_.time_left = std::max(0.0f, message_.time_left - dt);
    test_triggers();
    run_cascade(0);
}

void LevelLogic::check_won() {
    if (core_.playing() && all_objectives_complete()) core_.set_phase(Phase::Won, player_.state().feet);
}

void LevelLogic::run_cascade(std::size_t cursor) {
    while (core_.playing()) {
        translate_events(cursor);
        note_deaths();
        if (std::exchange(objectives_dirty_, false)) check_kill_objectives();
        if (cursor < core_.events.size()) continue; // a completed objective said so: its events come first
        std::uint32_t link = 0;
        if (!next_ready(link)) return;
        record_action(links_[link], static_cast<int>(link));
        apply_action(links_[link]);
    }
}

// The game's own events that are link events. Robot deaths are found by note_deaths instead: a robot can be
// killed between steps (a test, the editor), and its death must still count.
void LevelLogic::translate_events(std::size_t& cursor) {
    for (; cursor < core_.events.size(); ++cursor) {
        const Event& e = core_.events[cursor];
        switch (e.type) {
        case EventType::DoorToggled:
            fire_entity(e.entity, e.amount > 0.5f ? LinkEvent::OnOpen : LinkEvent::OnClose);
            break;
        case EventType::Used:
            fire_entity(e.entity, LinkEvent::OnUse);
            break;
        case EventType::PickupTaken:
            fire_entity(e.entity, LinkEvent::OnPickup);
            break;
        case EventType::RobotAlerted:
            fire_entity(e.entity, LinkEvent::OnAlert);
            break;
        default:
            break;
        }
    }
}

void LevelLogic::note_deaths() {
    const auto robots = robots_.robots();
    if (robot_dead_.size() < robots.size()) robot_dead_.resize(robots.size(), false); // spawned robots
    for (std::size_t i = 0; i < robots.size(); ++i) {
        if (robots[i].alive() || robot_dead_[i]) continue;
        robot_dead_[i] = true;
        objectives_dirty_ = true;
        fire_entity(robots[i].entity_id, LinkEvent::OnDeath);
    }
}

// A character is inside when its upright axis, feet to head, passes through the box.
bool LevelLogic::trigger_holds(const TriggerState& t) const {
    auto inside = [&](const Vec3& feet, float height) {
        const Vec3 local = t.frame.to_local(feet);
        return std::abs(local.x) <= t.size.x * 0.5f && std::abs(local.z) <= t.size.z * 0.5f &&
               local.y <= t.size.y && local.y + height >= 0.0f;
    };
    if (t.who != TriggerWho::Robots && inside(player_.state().feet, core_.settings.player_height))
        return true;
    if (t.who == TriggerWho::Player) return false;
    const auto robots = robots_.robots();
    return std::any_of(robots.begin(), robots.end(), [&](const Robot& r) {
        return r.alive() && inside(r.feet, core_.settings.robot_height);
    });
}

void LevelLogic::test_triggers() {
    for (TriggerState& t : triggers_) {
        if (!t.enabled) continue;
        const bool occupied = trigger_holds(t);
        if (occupied == t.occupied) continue;
        t.occupied = occupied;
        fire_entity(t.entity_id, occupied ? LinkEvent::OnEnter : LinkEvent::OnExit);
    }
}

void LevelLogic::apply_action(const LogicLink& link) {
    const std::size_t i = link.target_index;
    switch (link.action) {
    case LinkAction::Open:
    case LinkAction::Close:
    case LinkAction::Toggle:
        if (link.target == LogicTarget::Door) {
            const Door& d = interactables_.doors()[i];
            interactables_.set_door_opening(
                i, link.action == LinkAction::Toggle ? !d.opening : link.action == LinkAction::Open);
            return;
        }
        [[fallthrough]]; // a light's toggle
    case LinkAction::On:
    case LinkAction::Off: {
        const Light& l = interactables_.lights()[i];
        interactables_.set_light(i,
                                 link.action == LinkAction::Toggle ? !l.on : link.action == LinkAction::On);
        return;
    }
    case LinkAction::Lock:
    case LinkAction::Unlock:
        interactables_.set_door_locked(i, link.action == LinkAction::Lock);
        return;
    case LinkAction::Enable:
    case LinkAction::Disable: {
        TriggerState& t = triggers_[i];
        t.enabled = link.action == LinkAction::Enable;
        if (!t.enabled) t.occupied = false; // enabled again, it notices whoever stands in it then
        return;
    }
    case LinkAction::Activate:
    case LinkAction::Alert:
        robots_.wake(i, link.action == LinkAction::Alert);
        return;
    case LinkAction::Kill: {
        const Robot& r = robots_.robots()[i];
        if (r.alive()) robots_.damage(i, r.health, false);
        return;
    }
    case LinkAction::Spawn:
        spawners_.start(i);
        return;
    case LinkAction::Show: {
        const MessageEntity& m = messages_[i];
        message_ = {m.entity_id, m.text, m.duration, m.duration};
        core_.events.push_back(
            {EventType::MessageShown, player_.state().eye(), Vec3(0.0f), m.entity_id, m.duration, m.text});
        return;
    }
    case LinkAction::Play: {
        const SoundEntity& s = sounds_[i];
        core_.events.push_back(
            {EventType::SoundPlayed, s.position, Vec3(s.radius, 0.0f, 0.0f), s.entity_id, s.volume, s.sound});
        return;
    }
    case LinkAction::Complete:
        complete_objective_at(i);
        return;
    case LinkAction::Win:
        core_.set_phase(Phase::Won, player_.state().feet);
        return;
    case LinkAction::Lose: // the simulation ends as when the player dies
        core_.set_phase(Phase::Dead, player_.state().feet);
        return;
    case LinkAction::Count:
        return;
    }
}

void LevelLogic::complete_objective_at(std::size_t index) {
    ObjectiveState& o = objectives_[index];
    if (o.completed) return;
    o.completed = true;
    record_event({LogicEnd::Kind::Objective, static_cast<int>(index)}, LinkEvent::OnComplete);
    core_.events.push_back({EventType::ObjectiveCompleted, player_.state().feet, Vec3(0.0f), -1,
                            static_cast<float>(index), o.id});
    fire(o.links, LinkEvent::OnComplete);
}

void LevelLogic::check_kill_objectives() {
    const auto robots = robots_.robots();
    auto dead = [&](std::uint32_t robot) { return !robots[robot].alive(); };
    for (std::size_t k = 0; k < objectives_.size(); ++k) {
        const ObjectiveState& o = objectives_[k];
        if (o.completed || !o.kill_condition) continue;
        const bool robots_dead = std::all_of(o.kill_robots.begin(), o.kill_robots.end(), dead);
        const bool spawners_done =
            std::all_of(o.kill_spawners.begin(), o.kill_spawners.end(), [&](std::uint32_t s) {
                const SpawnerState& spawner = spawners_.spawners()[s];
                return spawner.started && spawner.left == 0 &&
                       std::all_of(spawner.robots.begin(), spawner.robots.end(), dead);
            });
        if (robots_dead && spawners_done) complete_objective_at(k);
    }
}

bool LevelLogic::run_action(level::LinkAction action, int target) {
    LogicLink link;
    link.action = action;
    switch (level::target_kind(action)) {
    case level::TargetKind::Objective:
        return false; // complete_objective names it
    case level::TargetKind::Level:
        link.target = LogicTarget::Level;
        link.target_end = {LogicEnd::Kind::Level, -1};
        break;
    case level::TargetKind::Entity: {
        auto find = [&](const auto& records, LogicTarget kind, level::EntityType type) {
            for (std::size_t i = 0; i < records.size(); ++i) {
                if (records[i].entity_id != target) continue;
                link.target = kind;
                link.target_index = static_cast<std::uint32_t>(i);
                link.target_end = {LogicEnd::Kind::Entity, target};
                return level::entity_takes(type, action);
            }
            return false;
        };
        using level::EntityType;
        if (!find(interactables_.doors(), LogicTarget::Door, EntityType::Door) &&
            !find(interactables_.lights(), LogicTarget::Light, EntityType::TopLight) &&
            !find(triggers_, LogicTarget::Trigger, EntityType::Trigger) &&
            !find(robots_.robots(), LogicTarget::Robot, EntityType::Robot) &&
            !find(spawners_.spawners(), LogicTarget::Spawner, EntityType::Spawner) &&
            !find(messages_, LogicTarget::Message, EntityType::Message) &&
            !find(sounds_, LogicTarget::Sound, EntityType::Sound))
            return false;
        break;
    }
    }
    if (!core_.playing()) return true;
    reset_budget();
    const std::size_t cursor = core_.events.size();
    record_action(link, -1);
    apply_action(link);
    run_cascade(cursor);
    check_won();
    return true;
}

bool LevelLogic::complete_objective(std::string_view id) {
    for (std::size_t k = 0; k < objectives_.size(); ++k) {
        if (objectives_[k].id != id) continue;
        if (!core_.playing()) return true;
        reset_budget();
        const std::size_t cursor = core_.events.size();
        complete_objective_at(k);
        run_cascade(cursor);
        check_won();
        return true;
    }
    return false;
}

} // namespace ks::game
