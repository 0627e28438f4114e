// Spawners (spawners.h). The robot arrays grow; everything that holds a robot holds its index (physics user
// data, the logic's kill lists), never a pointer, so growth is safe between steps.
#include "game/spawners.h"

#include "game/level_logic.h"
#include "game/player_system.h"
#include "game/robot_system.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

// How far from a candidate point the mesh is searched (sideways; up and down 4, a storey's stairs).
constexpr float kSpawnReach = 1.5f;
constexpr float kSpawnRings[] = {0.0f, 2.5f, 5.0f};

SpawnerState make_spawner(const level::Entity& e, const level::SpawnerProps& s, double step) {
    SpawnerState state;
    state.entity_id = e.id;
    state.name = e.name;
    state.robot = s.robot;
    state.robot.dummy = false; // a spawner makes fighting robots (the checks report a dummy)
    state.position = e.position;
    state.yaw_degrees = e.rotation.x;
    state.count = std::max(1, s.count);
    state.max_alive = std::max(1, s.max_alive);
    const double interval =
        std::isfinite(s.interval) ? std::clamp(static_cast<double>(s.interval), 0.0, 600.0) : 0.0;
    state.interval_steps = std::llround(interval / step);
    state.robots.reserve(static_cast<std::size_t>(state.count));
    return state;
}

} // namespace

Spawners::Spawners(GameCore& core, PlayerSystem& player, RobotSystem& robots)
    : core_(core), player_(player), robots_(robots) {}

void Spawners::build(const level::Level& level) {
    int largest_id = 0;
    for (const level::Entity& e : level.entities) {
        largest_id = std::max(largest_id, e.id);
        if (const auto* s = e.try_as<level::SpawnerProps>())
            spawners_.push_back(make_spawner(e, *s, core_.settings.step));
    }
    next_robot_id_ = std::max(level.next_id, largest_id + 1);
}

void Spawners::start(std::size_t spawner) {
    SpawnerState& s = spawners_[spawner];
    if (s.left > 0) return; // a wave is under way: it goes on as it was
    s.left = s.count;
    s.next_step = core_.steps;
    s.started = true;
}

void Spawners::update(LevelLogic& logic) {
    for (SpawnerState& s : spawners_) {
        if (s.left <= 0 || s.stuck || core_.steps < s.next_step) continue;
        int alive = 0;
        for (std::uint32_t r : s.robots) alive += robots_.robots()[r].alive() ? 1 : 0;
        if (alive >= s.max_alive) continue; // the next comes as soon as one of them dies
        if (robots_.robots().size() >= kMaxRobots) {
            s.stuck = true;
            logic.report("spawner \"" + s.name + "\": the game holds " + std::to_string(kMaxRobots) +
                         " robots, the most it may; it makes no more");
            continue;
        }
        if (!spawn_robot(s, logic)) continue; // no room now: it tries again next step
        --s.left;
        s.next_step = core_.steps + s.interval_steps;
    }
}

bool Spawners::spawn_spot_clear(const Vec3& feet) const {
    const GameSettings& settings = core_.settings;
    auto near = [&](const Vec3& other, float reach) {
        const Vec3 d = other - feet;
        return std::abs(d.y) < settings.robot_height && d.x * d.x + d.z * d.z < reach * reach;
    };
    const float robot_reach = 2.0f * settings.robot_radius + 0.2f;
    for (const Robot& r : robots_.robots())
        if (r.alive() && near(r.feet, robot_reach)) return false;
    return !near(player_.state().feet, settings.player_radius + settings.robot_radius + 0.2f);
}

std::optional<Vec3> Spawners::spawn_point(const SpawnerState& s) {
    nav::NavMesh& navigation = *robots_.navigation();
    for (float radius : kSpawnRings) {
        const int candidates = radius > 0.0f ? 8 : 1;
        for (int k = 0; k < candidates; ++k) {
            const float angle = static_cast<float>(k) * kPi * 0.25f;
            const Vec3 wanted = s.position + Vec3(std::cos(angle), 0.0f, std::sin(angle)) * radius;
            const auto on_mesh = navigation.nearest_point(wanted, Vec3(kSpawnReach, 4.0f, kSpawnReach));
            if (on_mesh && spawn_spot_clear(*on_mesh)) return on_mesh;
        }
    }
    return std::nullopt;
}

bool Spawners::has_ground(SpawnerState& s, LevelLogic& logic) {
    nav::NavMesh* navigation = robots_.navigation();
    if (navigation && navigation->nearest_point(s.position, Vec3(kSpawnReach, 4.0f, kSpawnReach)))
        return true;
    s.stuck = true; // the mesh never changes where it lies: this spawner can never spawn
    logic.report("spawner \"" + s.name + "\": " +
                 (navigation ? "no walkable ground within " + std::to_string(static_cast<int>(kSpawnReach)) +
                                   " units of it"
                             : "the level has no navigation mesh (" + robots_.navigation_error() + ")") +
                 ", so it makes no robots; move it over a floor robots can walk on");
    return false;
}

void Spawners::check_ground(LevelLogic& logic) {
    for (SpawnerState& s : spawners_)
        if (!s.stuck) has_ground(s, logic);
}

bool Spawners::spawn_robot(SpawnerState& s, LevelLogic& logic) {
    if (!has_ground(s, logic)) return false;
    const auto point = spawn_point(s);
    if (!point) return false;
    level::Entity entity;
    entity.id = next_robot_id_++;
    entity.name = s.name;
    entity.position = *point;
    entity.rotation = Vec3(s.yaw_degrees, 0.0f, 0.0f);
    entity.props = s.robot;
    if (auto added = robots_.add(entity); !added) {
        s.stuck = true;
        logic.report("spawner \"" + s.name + "\": " + added.error().message);
        return false;
    }
    s.robots.push_back(static_cast<std::uint32_t>(robots_.robots().size() - 1));
    core_.events.push_back(
        {EventType::RobotSpawned, *point, Vec3(0.0f), entity.id, static_cast<float>(s.entity_id), {}});
    return true;
}

} // namespace ks::game
