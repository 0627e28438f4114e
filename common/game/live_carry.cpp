// The live play-test's carry (live_carry.h): each system of a game built on the edited level takes over,
// from the same system of the running game, the state of every entity that still exists, with the rule
// live_update.h states. Kept in one file so the whole rule reads in one place; each function writes only
// its own class's state (and, for robots a spawner carries, asks the robot system to add them).
#include "game/live_carry.h"

#include "game/game.h"

#include <algorithm>
#include <memory>

namespace ks::game {

LevelEdit::LevelEdit(const level::Level& before, const level::Level& edited)
    : before_(index_entities(before)), edited_(index_entities(edited)) {}

LevelEdit::EntityIndex LevelEdit::index_entities(const level::Level& level) {
    EntityIndex index;
    for (const level::Entity& e : level.entities) index.emplace(e.id, &e);
    return index;
}

bool LevelEdit::moved(int entity_id) const {
    const level::Entity& now = *edited_.at(entity_id);
    const auto it = before_.find(entity_id);
    return it == before_.end() || it->second->position != now.position ||
           it->second->rotation != now.rotation;
}

int Game::carry_from(const Game& previous, const LevelEdit& edit) {
    core_.rng = previous.core_.rng;
    core_.steps = previous.core_.steps;
    core_.phase = previous.core_.phase;
    core_.phase_time = previous.core_.phase_time;
    core_.paused = previous.core_.paused;
    core_.events.clear();
    player_.carry_from(previous.player_);
    int kept = robots_.carry_from(previous.robots_, edit);
    spawners_.carry_from(previous.spawners_, edit);
    kept += interactables_.carry_from(previous.interactables_, edit, robots_.navigation());
    kept += explosives_.carry_from(previous.explosives_, edit);
    logic_.carry_from(previous.logic_, edit);
    return kept;
}

void PlayerSystem::carry_from(const PlayerSystem& previous) {
    const PlayerState& old = previous.player_;
    const physics::BodyId body = player_.body;
    player_ = old;
    player_.body = body;
    teleport(old.feet, old.yaw, old.pitch);
    core_.world.character(body).movement.velocity = old.velocity;
}

int RobotSystem::carry_from(const RobotSystem& previous, const LevelEdit& edit) {
    int kept = 0;
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        const int id = robots_[i].entity_id;
        if (!edit.existed(id)) continue; // new in the edit (a spawned robot's id is never a level id)
        for (std::size_t j = 0; j < previous.robots_.size(); ++j)
            if (previous.robots_[j].entity_id == id) {
                carry_robot(i, previous, j, !edit.moved(id));
                ++kept;
                break;
            }
    }
    killed_ = previous.killed_;
    return kept;
}

void RobotSystem::carry_robot(std::size_t index, const RobotSystem& previous, std::size_t previous_index,
                              bool keep_place) {
    const Robot& old = previous.robots_[previous_index];
    Robot& r = robots_[index];
    const Robot fresh = r;
    const Vec3 body_offset = core_.world.transform(r.body).position - r.feet;
    r = old;
    r.entity_id = fresh.entity_id;
    r.body = fresh.body;
    r.props = fresh.props;
    if (!keep_place) {
        r.feet = fresh.feet;
        r.yaw = fresh.yaw;
        r.patrol = fresh.patrol;
    }
    r.path.clear(); // planned on the old mesh: planned again
    r.path.reserve(kMaxPathCorners);
    r.path_next = 0;
    r.replan_in = 0.0f;
    physics::World& world = core_.world;
    world.set_transform(r.body, {r.feet + body_offset, Quat(1, 0, 0, 0)});
    world.character(r.body).movement.velocity =
        keep_place ? previous.core_.world.character(old.body).movement.velocity : Vec3(0.0f);
    if (r.mode == RobotMode::Dead) world.set_enabled(r.body, false);
    if (&previous.animations() == &animations()) { // one clip set: the player copies
        anim::Player& player = anims_[index];      // (its references cannot be assigned)
        std::destroy_at(&player);
        std::construct_at(&player, previous.anims_[previous_index]);
    }
}

void Spawners::carry_from(const Spawners& previous, const LevelEdit& edit) {
    const RobotSystem& previous_robots = previous.robots_;
    for (SpawnerState& now : spawners_) {
        const SpawnerState* old = find_by_entity(previous.spawners(), now.entity_id);
        if (!old || !edit.existed(now.entity_id)) continue;
        now.left = old->left;
        now.next_step = old->next_step;
        now.started = old->started;
        for (std::uint32_t index : old->robots) {
            const Robot& robot = previous_robots.robots()[index];
            if (!robot.alive()) continue;
            level::Entity entity;
            entity.id = next_robot_id_++;
            entity.name = now.name;
            entity.position = robot.feet;
            entity.rotation = Vec3(degrees(robot.yaw), 0.0f, 0.0f);
            entity.props = now.robot;
            if (!robots_.add(entity)) continue; // no room for its body: it is not carried
            const std::size_t added = robots_.robots().size() - 1;
            robots_.carry_robot(added, previous_robots, index, true);
            now.robots.push_back(static_cast<std::uint32_t>(added));
        }
    }
}

int Interactables::carry_from(const Interactables& previous, const LevelEdit& edit,
                              nav::NavMesh* navigation) {
    int kept = 0;
    for (Door& d : doors_) {
        const Door* old = find_by_entity(previous.doors(), d.entity_id);
        if (!old || !edit.existed(d.entity_id)) continue;
        d.progress = old->progress;
        d.opening = old->opening;
        d.locked = old->locked;
        d.player_inside = old->player_inside;
        for (int side = 0; side < 2; ++side)
            core_.world.set_transform(d.leaves[side], d.leaf_transform(side));
        if (navigation && d.progress > 0.0f) navigation->set_door_open(d.entity_id, true);
        ++kept;
    }
    for (Light& l : lights_)
        if (const Light* old = find_by_entity(previous.lights(), l.entity_id);
            old && edit.existed(l.entity_id)) {
            l.on = old->on;
            ++kept;
        }
    for (Pickup& k : pickups_)
        if (const Pickup* old = find_by_entity(previous.pickups(), k.entity_id);
            old && edit.existed(k.entity_id)) {
            k.taken = old->taken;
            if (k.taken) core_.world.set_enabled(k.trigger, false);
            ++kept;
        }
    return kept;
}

int Explosives::carry_from(const Explosives& previous, const LevelEdit& edit) {
    int kept = 0;
    for (Cylinder& c : cylinders_)
        if (const Cylinder* old = find_by_entity(previous.cylinders(), c.entity_id);
            old && edit.existed(c.entity_id)) {
            c.fuse = old->fuse;
            c.exploded = old->exploded;
            if (c.exploded) core_.world.set_enabled(c.body, false);
            ++kept;
        }
    return kept;
}

void LevelLogic::carry_from(const LevelLogic& previous, const LevelEdit& edit) {
    // A carried robot already dead has had its on_death (one still dying has it at the next step).
    const auto robots = robots_.robots();
    for (std::size_t i = 0; i < robots.size(); ++i)
        if (robots[i].mode == RobotMode::Dead) {
            if (robot_dead_.size() <= i) robot_dead_.resize(i + 1, false);
            robot_dead_[i] = true;
        }
    started_ = previous.started_;
    for (ObjectiveState& o : objectives_)
        for (const ObjectiveState& was : previous.objectives_)
            if (was.id == o.id) o.completed = was.completed;
    for (TriggerState& t : triggers_)
        if (const TriggerState* was = find_by_entity(previous.triggers(), t.entity_id);
            was && edit.existed(t.entity_id)) {
            t.enabled = was->enabled;
            t.occupied = was->occupied;
        }
    // A link is kept when the edit left its owner, event, action and target as they were.
    const auto same_link = [](const LogicLink& a, const LogicLink& b) {
        return a.source_end == b.source_end && a.event == b.event && a.action == b.action &&
               a.target_end == b.target_end;
    };
    // A once link that fired stays fired while the edit kept it.
    for (LogicLink& l : links_)
        for (const LogicLink& was : previous.links_)
            if (was.fired && same_link(was, l)) l.fired = true;
    // A delayed action still waiting goes on, at its due step and in its order, while its link is kept (the
    // hall trigger's spawns when the designer moves a spawner at the break).
    for (const Pending& p : previous.pending_) {
        const LogicLink& was = previous.links_[p.link];
        for (std::uint32_t k = 0; k < links_.size(); ++k)
            if (same_link(was, links_[k])) {
                pending_.push_back({p.due, p.sequence, k});
                break;
            }
    }
    std::make_heap(pending_.begin(), pending_.end(), Pending::later);
    sequence_ = previous.sequence_;
    if (previous.message_.visible() && edit.remains(previous.message_.entity_id))
        for (const MessageEntity& m : messages_)
            if (m.entity_id == previous.message_.entity_id) {
                message_ = previous.message_;
                message_.text = m.text;
            }
    uses_locks_ = uses_locks_ || previous.uses_locks_;
    objectives_dirty_ = true; // kill conditions over the carried robots are checked again
}

} // namespace ks::game
