// The live play-test's rebuild (live_update.h): a new game on the edited level, then the running game's
// state of every entity that still exists copied in, system by system, with the rule the header states.
#include "game/live_update.h"

#include <algorithm>
#include <memory>
#include <unordered_map>
#include <unordered_set>

namespace ks::game {
namespace {

using EntityIndex = std::unordered_map<int, const level::Entity*>;

EntityIndex index_entities(const level::Level& level) {
    EntityIndex index;
    for (const level::Entity& e : level.entities) index.emplace(e.id, &e);
    return index;
}

// The edit moved it: its place or turn in the file changed (or it is new).
bool placement_edited(const EntityIndex& before, const level::Entity& now) {
    const auto it = before.find(now.id);
    return it == before.end() || it->second->position != now.position || it->second->rotation != now.rotation;
}

template <class Record>
const Record* find_by_entity(std::span<const Record> records, int entity_id) {
    for (const Record& r : records)
        if (r.entity_id == entity_id) return &r;
    return nullptr;
}

// What the navigation mesh is built from (nav/nav_input.cpp): doors, brushes, models and every entity with
// a solid shape.
bool shapes_navigation(const level::Entity& e) {
    const auto type = e.type();
    return type == level::EntityType::Door || type == level::EntityType::Brush ||
           type == level::EntityType::Model || level::static_solid_shape(e).has_value();
}

// The edit left the mesh's input as it was: the same solids, in the same order, with the same place and
// props (names and links do not matter to it), and the same level settings.
bool same_navigation_input(const level::Level& a, const level::Level& b) {
    if (!(a.settings == b.settings)) return false;
    auto next = [](const level::Level& lv, std::size_t& i) -> const level::Entity* {
        while (i < lv.entities.size() && !shapes_navigation(lv.entities[i])) ++i;
        return i < lv.entities.size() ? &lv.entities[i++] : nullptr;
    };
    std::size_t i = 0, k = 0;
    for (;;) {
        const level::Entity* x = next(a, i);
        const level::Entity* y = next(b, k);
        if (!x || !y) return x == y;
        if (x->id != y->id || x->position != y->position || x->rotation != y->rotation ||
            !(x->props == y->props))
            return false;
    }
}

} // namespace

// Friend of the Game and its systems (one line in each header): the only code that writes their state
// from outside their own step.
struct LiveCarry {
    const Game& from;
    Game& to;
    const EntityIndex before;
    const EntityIndex edited;

    void core() {
        GameCore& c = to.core_;
        c.rng = from.core_.rng;
        c.steps = from.core_.steps;
        c.phase = from.core_.phase;
        c.phase_time = from.core_.phase_time;
        c.paused = from.core_.paused;
        c.events.clear();
    }

    void player() {
        const PlayerState& old = from.player_.player_;
        PlayerState& p = to.player_.player_;
        const physics::BodyId body = p.body;
        p = old;
        p.body = body;
        to.player_.teleport(old.feet, old.yaw, old.pitch);
        to.core_.world.character(body).movement.velocity = old.velocity;
    }

    // A robot's state onto robot `index` of the new game (its body placed, its animation carried).
    void robot_state(std::size_t index, const Robot& old, std::size_t old_index, bool keep_place) {
        Robot& r = to.robots_.robots_[index];
        const Robot fresh = r;
        const Vec3 body_offset = to.core_.world.transform(r.body).position - r.feet;
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
        physics::World& world = to.core_.world;
        world.set_transform(r.body, {r.feet + body_offset, Quat(1, 0, 0, 0)});
        world.character(r.body).movement.velocity =
            keep_place ? from.core_.world.character(old.body).movement.velocity : Vec3(0.0f);
        if (r.mode == RobotMode::Dead) world.set_enabled(r.body, false);
        if (&from.robots_.animations() == &to.robots_.animations()) { // one clip set: the player copies
            anim::Player& player = to.robots_.anims_[index];          // (its references cannot be assigned)
            std::destroy_at(&player);
            std::construct_at(&player, from.robots_.anims_[old_index]);
        }
        if (!r.alive()) mark_dead(index);
    }

    void mark_dead(std::size_t index) {
        auto& dead = to.logic_.robot_dead_;
        if (dead.size() <= index) dead.resize(index + 1, false);
        dead[index] = to.robots_.robots_[index].mode == RobotMode::Dead || dead[index];
    }

    // The level's own robots, by id. Robots the running game's spawners made are handled by spawners().
    int level_robots() {
        int kept = 0;
        const auto old = from.robots();
        for (std::size_t i = 0; i < to.robots_.robots_.size(); ++i) {
            const int id = to.robots_.robots_[i].entity_id;
            if (!before.contains(id)) continue; // new in the edit (a spawned robot's id is never a level id)
            for (std::size_t j = 0; j < old.size(); ++j)
                if (old[j].entity_id == id) {
                    robot_state(i, old[j], j, !placement_edited(before, *edited.at(id)));
                    ++kept;
                    break;
                }
        }
        to.robots_.killed_ = from.robots_.killed_;
        return kept;
    }

    void spawners() {
        Spawners& s = to.spawners_;
        for (SpawnerState& now : s.spawners_) {
            const SpawnerState* old = find_by_entity(from.logic().spawners(), now.entity_id);
            if (!old || !before.contains(now.entity_id)) continue;
            now.left = old->left;
            now.next_step = old->next_step;
            now.started = old->started;
            for (std::uint32_t index : old->robots) {
                const Robot& robot = from.robots()[index];
                if (!robot.alive()) continue;
                level::Entity entity;
                entity.id = s.next_robot_id_++;
                entity.name = now.name;
                entity.position = robot.feet;
                entity.rotation = Vec3(degrees(robot.yaw), 0.0f, 0.0f);
                entity.props = now.robot;
                if (!to.robots_.add(entity)) continue; // no room for its body: it is not carried
                const std::size_t added = to.robots_.robots_.size() - 1;
                robot_state(added, robot, index, true);
                now.robots.push_back(static_cast<std::uint32_t>(added));
            }
        }
    }

    int interactables() {
        int kept = 0;
        Interactables& it = to.interactables_;
        for (Door& d : it.doors_) {
            const Door* old = find_by_entity(from.doors(), d.entity_id);
            if (!old || !before.contains(d.entity_id)) continue;
            d.progress = old->progress;
            d.opening = old->opening;
            d.locked = old->locked;
            d.player_inside = old->player_inside;
            for (int side = 0; side < 2; ++side)
                to.core_.world.set_transform(d.leaves[side], d.leaf_transform(side));
            if (nav::NavMesh* mesh = to.robots_.navigation(); mesh && d.progress > 0.0f)
                mesh->set_door_open(d.entity_id, true);
            ++kept;
        }
        for (Light& l : it.lights_)
            if (const Light* old = find_by_entity(from.lights(), l.entity_id);
                old && before.contains(l.entity_id)) {
                l.on = old->on;
                ++kept;
            }
        for (Pickup& k : it.pickups_)
            if (const Pickup* old = find_by_entity(from.pickups(), k.entity_id);
                old && before.contains(k.entity_id)) {
                k.taken = old->taken;
                if (k.taken) to.core_.world.set_enabled(k.trigger, false);
                ++kept;
            }
        for (Cylinder& c : to.explosives_.cylinders_)
            if (const Cylinder* old = find_by_entity(from.cylinders(), c.entity_id);
                old && before.contains(c.entity_id)) {
                c.fuse = old->fuse;
                c.exploded = old->exploded;
                if (c.exploded) to.core_.world.set_enabled(c.body, false);
                ++kept;
            }
        return kept;
    }

    void logic() {
        LevelLogic& now = to.logic_;
        const LevelLogic& old = from.logic_;
        now.started_ = old.started_;
        for (ObjectiveState& o : now.objectives_)
            for (const ObjectiveState& was : old.objectives_)
                if (was.id == o.id) o.completed = was.completed;
        for (TriggerState& t : now.triggers_)
            if (const TriggerState* was = find_by_entity(old.triggers(), t.entity_id);
                was && before.contains(t.entity_id)) {
                t.enabled = was->enabled;
                t.occupied = was->occupied;
            }
        // A once link that fired stays fired while the edit kept it (same owner, event, action and target).
        for (LogicLink& l : now.links_)
            for (const LogicLink& was : old.links_)
                if (was.fired && was.source_end == l.source_end && was.event == l.event &&
                    was.action == l.action && was.target_end == l.target_end)
                    l.fired = true;
        if (old.message_.visible() && edited.contains(old.message_.entity_id))
            for (const MessageEntity& m : now.messages_)
                if (m.entity_id == old.message_.entity_id) {
                    now.message_ = old.message_;
                    now.message_.text = m.text;
                }
        now.uses_locks_ = now.uses_locks_ || old.uses_locks_;
        now.objectives_dirty_ = true; // kill conditions over the carried robots are checked again
    }
};

std::string LiveRebuild::summary() const {
    return std::to_string(kept) + " entities kept their state, " + std::to_string(added) + " added, " +
           std::to_string(removed) + " removed";
}

Result<LiveRebuild> rebuild_for_edit(const Game& running, const level::Level& before,
                                     const level::Level& edited, GameOptions options) {
    // An edit that left the solids alone (robots, lights, links, spawners, triggers...) keeps the mesh:
    // the build copies the running game's (a view of it, not owned: it is copied before create returns).
    if (!options.navigation && running.navigation() && same_navigation_input(before, edited))
        options.navigation =
            std::shared_ptr<const nav::NavMesh>(std::shared_ptr<void>(), running.navigation());
    auto built = Game::create(edited, std::move(options));
    if (!built) return built.error();
    LiveRebuild out;
    out.game = std::move(*built);
    LiveCarry carry{running, *out.game, index_entities(before), index_entities(edited)};
    carry.core();
    carry.player();
    out.kept = carry.level_robots();
    carry.spawners();
    out.kept += carry.interactables();
    carry.logic();
    for (const level::Entity& e : edited.entities) out.added += carry.before.contains(e.id) ? 0 : 1;
    for (const level::Entity& e : before.entities) out.removed += carry.edited.contains(e.id) ? 0 : 1;
    return out;
}

} // namespace ks::game
