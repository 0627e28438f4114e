// FNV-1a over every piece of simulation state, so two runs (or a run and its replay) can be compared with
// one number. Floats are hashed by their bits: equal hashes mean bit-identical states. Each system's state
// is read through its read-only interface, in the order the recorded hashes were made with; a new system
// appends its state at the end (docs/architecture.md, "Game systems"), only where it holds any, so levels
// without it hash as before.
#include "game/game.h"

#include <algorithm>
#include <cstring>

namespace ks::game {
namespace {

class Hasher {
  public:
    template <class T>
    void add(const T& value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char b : bytes) h_ = (h_ ^ b) * 0x100000001b3ull;
    }
    void add(const Vec3& v) {
        add(v.x);
        add(v.y);
        add(v.z);
    }
    void add(bool b) { add(static_cast<unsigned char>(b)); }
    std::uint64_t value() const { return h_; }

  private:
    std::uint64_t h_ = 0xcbf29ce484222325ull;
};

} // namespace

std::uint64_t Game::state_hash() const {
    Hasher h;
    h.add(core_.steps);
    h.add(static_cast<int>(core_.phase));
    h.add(core_.paused);
    h.add(core_.rng.state());
    const PlayerState& p = player_.state();
    const physics::World& world = core_.world;
    h.add(world.transform(p.body).position);
    h.add(world.character(p.body).movement.velocity);
    h.add(p.knockback);
    h.add(p.yaw);
    h.add(p.pitch);
    h.add(p.health);
    h.add(p.shield);
    h.add(p.ammo);
    h.add(p.shots);
    h.add(p.damage_taken);
    const auto robots = robots_.robots();
    for (std::size_t i = 0; i < robots.size(); ++i) {
        const Robot& r = robots[i];
        h.add(world.transform(r.body).position);
        h.add(world.character(r.body).movement.velocity);
        h.add(r.yaw);
        h.add(r.health);
        h.add(static_cast<int>(r.mode));
        h.add(r.mode_time);
        h.add(r.angry);
        h.add(r.cooldown);
        h.add(r.wander_to);
        h.add(r.wander_length);
        h.add(r.last_known);
        h.add(r.hunt_left);
        h.add(r.search_point);
        h.add(r.path_goal);
        h.add(static_cast<int>(r.path_next));
        h.add(static_cast<int>(r.path.size()));
        h.add(r.replan_in);
        if (r.props.patrol.active()) { // robots without a route hash exactly as before patrols existed
            h.add(r.patrol.target);
            h.add(r.patrol.direction);
            h.add(r.patrol.waiting);
        }
        if (r.props.dormant) h.add(r.dormant); // as patrols: robots that never slept hash as before
        h.add(robots_.animation(i).ticks());
        h.add(robots_.animation(i).current_clip());
    }
    for (const Door& d : interactables_.doors()) {
        h.add(d.progress);
        h.add(d.opening);
    }
    for (const Light& l : interactables_.lights()) h.add(l.on);
    for (const Pickup& k : interactables_.pickups()) h.add(k.taken);
    for (const Cylinder& c : explosives_.cylinders()) {
        h.add(c.exploded);
        h.add(c.fuse);
    }
    h.add(interactables_.caption().visible());
    h.add(interactables_.caption().owner());
    // The level logic, only where it holds state: a level without any (the main level, whose one objective
    // completes in the step it is won, which the phase already says) hashes as before the logic existed.
    const auto objectives = logic_.objectives();
    const auto completed =
        std::count_if(objectives.begin(), objectives.end(), [](const auto& o) { return o.completed; });
    if (completed > 0 && completed < static_cast<std::ptrdiff_t>(objectives.size()))
        for (const ObjectiveState& o : objectives) h.add(o.completed);
    const auto links = logic_.links();
    for (std::size_t k = 0; k < links.size(); ++k)
        if (links[k].once && links[k].fired) h.add(static_cast<std::uint32_t>(k));
    for (const LevelLogic::Pending& p : logic_.pending()) {
        h.add(p.due);
        h.add(p.sequence);
        h.add(p.link);
    }
    for (const TriggerState& t : logic_.triggers()) {
        h.add(t.enabled);
        h.add(t.occupied);
    }
    for (const SpawnerState& s : logic_.spawners()) {
        h.add(s.left);
        h.add(s.next_step);
        h.add(s.started);
    }
    if (logic_.message().visible()) {
        h.add(logic_.message().entity_id);
        h.add(logic_.message().time_left);
    }
    if (logic_.uses_locks())
        for (const Door& d : interactables_.doors()) h.add(d.locked);
    return h.value();
}

} // namespace ks::game
