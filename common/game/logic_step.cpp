// The level logic's part of a step (after everything else has moved): due actions, the level's on_start,
// the message's clock, trigger volumes, then the cascade -- this step's game events become link events,
// ready actions run and set off more -- then the spawners, and the win when every objective is complete.
#include "game/game.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ks::game {

using level::LinkAction;
using level::LinkEvent;

void Game::update_logic(float dt) {
    if (phase_ != Phase::Playing) return; // won or lost: nothing more happens
    logic_.begin_step(steps_);
    if (!std::exchange(logic_.started_, true)) logic_.fire(logic_.level_links_, LinkEvent::OnStart, steps_);
    ShownMessage& message = logic_.message_;
    if (message.visible()) message.time_left = std::max(0.0f, message.time_left - dt);
    test_triggers();
    run_logic_cascade(0);
    update_spawners();
    if (phase_ == Phase::Playing && logic_.all_objectives_complete()) set_phase(Phase::Won);
}

void Game::run_logic_cascade(std::size_t cursor) {
    while (phase_ == Phase::Playing) {
        translate_events(cursor);
        note_deaths();
        if (std::exchange(logic_.objectives_dirty_, false)) check_kill_objectives();
        if (cursor < events_.size()) continue; // a completed objective said so: its events come first
        std::uint32_t link = 0;
        if (!logic_.next_ready(link)) return;
        apply_action(logic_.links_[link]);
    }
}

// The game's own events that are link events. Robot deaths are found by note_deaths instead: a robot can be
// killed between steps (a test, the editor), and its death must still count.
void Game::translate_events(std::size_t& cursor) {
    for (; cursor < events_.size(); ++cursor) {
        const Event& e = events_[cursor];
        switch (e.type) {
        case EventType::DoorToggled:
            logic_.fire_entity(e.entity, e.amount > 0.5f ? LinkEvent::OnOpen : LinkEvent::OnClose, steps_);
            break;
        case EventType::Used:
            logic_.fire_entity(e.entity, LinkEvent::OnUse, steps_);
            break;
        case EventType::PickupTaken:
            logic_.fire_entity(e.entity, LinkEvent::OnPickup, steps_);
            break;
        case EventType::RobotAlerted:
            logic_.fire_entity(e.entity, LinkEvent::OnAlert, steps_);
            break;
        default:
            break;
        }
    }
}

void Game::note_deaths() {
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        if (robots_[i].alive() || logic_.robot_dead_[i]) continue;
        logic_.robot_dead_[i] = true;
        logic_.objectives_dirty_ = true;
        logic_.fire_entity(robots_[i].entity_id, LinkEvent::OnDeath, steps_);
    }
}

// A character is inside when its upright axis, feet to head, passes through the box.
bool Game::trigger_holds(const TriggerState& t) const {
    auto inside = [&](const Vec3& feet, float height) {
        const Vec3 local = t.frame.to_local(feet);
        return std::abs(local.x) <= t.size.x * 0.5f && std::abs(local.z) <= t.size.z * 0.5f &&
               local.y <= t.size.y && local.y + height >= 0.0f;
    };
    if (t.who != TriggerWho::Robots && inside(player_.feet, settings_.player_height)) return true;
    if (t.who == TriggerWho::Player) return false;
    return std::any_of(robots_.begin(), robots_.end(),
                       [&](const Robot& r) { return r.alive() && inside(r.feet, settings_.robot_height); });
}

void Game::test_triggers() {
    for (TriggerState& t : logic_.triggers_) {
        if (!t.enabled) continue;
        const bool occupied = trigger_holds(t);
        if (occupied == t.occupied) continue;
        t.occupied = occupied;
        logic_.fire_entity(t.entity_id, occupied ? LinkEvent::OnEnter : LinkEvent::OnExit, steps_);
    }
}

void Game::apply_action(const LogicLink& link) {
    const std::size_t i = link.target_index;
    switch (link.action) {
    case LinkAction::Open:
    case LinkAction::Close:
    case LinkAction::Toggle:
        if (link.target == LogicTarget::Door) {
            Door& d = doors_[i];
            set_door_opening(d, link.action == LinkAction::Toggle ? !d.opening
                                                                  : link.action == LinkAction::Open);
            return;
        }
        [[fallthrough]]; // a light's toggle
    case LinkAction::On:
    case LinkAction::Off: {
        Light& l = lights_[i];
        const bool on = link.action == LinkAction::Toggle ? !l.on : link.action == LinkAction::On;
        if (l.on == on) return;
        l.on = on;
        push(EventType::LightToggled, l.position, l.entity_id, on ? 1.0f : 0.0f);
        return;
    }
    case LinkAction::Lock:
    case LinkAction::Unlock:
        doors_[i].locked = link.action == LinkAction::Lock;
        return;
    case LinkAction::Enable:
    case LinkAction::Disable: {
        TriggerState& t = logic_.triggers_[i];
        t.enabled = link.action == LinkAction::Enable;
        if (!t.enabled) t.occupied = false; // enabled again, it notices whoever stands in it then
        return;
    }
    case LinkAction::Activate:
    case LinkAction::Alert: {
        Robot& r = robots_[i];
        if (!r.alive()) return; // a dead robot takes no orders
        r.dormant = false;
        if (link.action == LinkAction::Alert) { // it knows where the player is: fights, or goes to look
            r.angry = std::max(r.angry, r.props.angry_duration);
            r.heard = true;
            r.last_known = player_.feet;
        }
        return;
    }
    case LinkAction::Kill:
        if (robots_[i].alive()) damage_robot(i, robots_[i].health, false);
        return;
    case LinkAction::Spawn: {
        SpawnerState& s = logic_.spawners_[i];
        if (s.left > 0) return; // a wave is under way: it goes on as it was
        s.left = s.count;
        s.next_step = steps_;
        s.started = true;
        return;
    }
    case LinkAction::Show: {
        const MessageEntity& m = logic_.messages_[i];
        logic_.message_ = {m.entity_id, m.text, m.duration, m.duration};
        events_.push_back(
            {EventType::MessageShown, player_.eye(), Vec3(0.0f), m.entity_id, m.duration, m.text});
        return;
    }
    case LinkAction::Play: {
        const SoundEntity& s = logic_.sounds_[i];
        events_.push_back(
            {EventType::SoundPlayed, s.position, Vec3(s.radius, 0.0f, 0.0f), s.entity_id, s.volume, s.sound});
        return;
    }
    case LinkAction::Complete:
        complete_objective_at(i);
        return;
    case LinkAction::Win:
        set_phase(Phase::Won);
        return;
    case LinkAction::Lose: // the simulation ends as when the player dies
        set_phase(Phase::Dead);
        return;
    case LinkAction::Count:
        return;
    }
}

void Game::complete_objective_at(std::size_t index) {
    ObjectiveState& o = logic_.objectives_[index];
    if (o.completed) return;
    o.completed = true;
    events_.push_back(
        {EventType::ObjectiveCompleted, player_.feet, Vec3(0.0f), -1, static_cast<float>(index), o.id});
    logic_.fire(o.links, LinkEvent::OnComplete, steps_);
}

void Game::check_kill_objectives() {
    auto dead = [&](std::uint32_t robot) { return !robots_[robot].alive(); };
    for (std::size_t k = 0; k < logic_.objectives_.size(); ++k) {
        const ObjectiveState& o = logic_.objectives_[k];
        if (o.completed || !o.kill_condition) continue;
        const bool robots_dead = std::all_of(o.kill_robots.begin(), o.kill_robots.end(), dead);
        const bool spawners_done =
            std::all_of(o.kill_spawners.begin(), o.kill_spawners.end(), [&](std::uint32_t s) {
                const SpawnerState& spawner = logic_.spawners_[s];
                return spawner.started && spawner.left == 0 &&
                       std::all_of(spawner.robots.begin(), spawner.robots.end(), dead);
            });
        if (robots_dead && spawners_done) complete_objective_at(k);
    }
}

// A dormant robot stands where it is, blind and deaf; any damage wakes it (and then it acts this step).
void Game::hold_dormant(std::size_t index, float dt) {
    Robot& r = robots_[index];
    if (!r.alive() || r.angry > 0.0f || r.health < r.props.health) {
        r.dormant = false;
        return;
    }
    r.heard = false;
    r.hit_flash = std::max(0.0f, r.hit_flash - dt);
    r.knockback *= std::exp(-settings_.knockback_decay * dt);
    auto& mv = world_.character(r.body).movement;
    mv.velocity.x = r.knockback.x;
    mv.velocity.z = r.knockback.z;
}

bool Game::run_action(level::LinkAction action, int target) {
    LogicLink link;
    link.action = action;
    switch (level::target_kind(action)) {
    case level::TargetKind::Objective:
        return false; // complete_objective names it
    case level::TargetKind::Level:
        link.target = LogicTarget::Level;
        break;
    case level::TargetKind::Entity: {
        auto find = [&](const auto& records, LogicTarget kind, level::EntityType type) {
            for (std::size_t i = 0; i < records.size(); ++i) {
                if (records[i].entity_id != target) continue;
                link.target = kind;
                link.target_index = static_cast<std::uint32_t>(i);
                return level::entity_takes(type, action);
            }
            return false;
        };
        using level::EntityType;
        if (!find(doors_, LogicTarget::Door, EntityType::Door) &&
            !find(lights_, LogicTarget::Light, EntityType::TopLight) &&
            !find(logic_.triggers_, LogicTarget::Trigger, EntityType::Trigger) &&
            !find(robots_, LogicTarget::Robot, EntityType::Robot) &&
            !find(logic_.spawners_, LogicTarget::Spawner, EntityType::Spawner) &&
            !find(logic_.messages_, LogicTarget::Message, EntityType::Message) &&
            !find(logic_.sounds_, LogicTarget::Sound, EntityType::Sound))
            return false;
        break;
    }
    }
    if (phase_ != Phase::Playing) return true;
    logic_.reset_budget();
    const std::size_t cursor = events_.size();
    apply_action(link);
    run_logic_cascade(cursor);
    if (phase_ == Phase::Playing && logic_.all_objectives_complete()) set_phase(Phase::Won);
    return true;
}

bool Game::complete_objective(std::string_view id) {
    for (std::size_t k = 0; k < logic_.objectives_.size(); ++k) {
        if (logic_.objectives_[k].id != id) continue;
        if (phase_ != Phase::Playing) return true;
        logic_.reset_budget();
        const std::size_t cursor = events_.size();
        complete_objective_at(k);
        run_logic_cascade(cursor);
        if (phase_ == Phase::Playing && logic_.all_objectives_complete()) set_phase(Phase::Won);
        return true;
    }
    return false;
}

} // namespace ks::game
