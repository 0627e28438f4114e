// Spawners: robots made during play, with the spawner's robot properties, through the same add_robot as the
// level's own. Each stands on the robots' navigation mesh (the nearest point to the spawner, or to a point
// on a ring around it when a robot or the player stands there), one every `interval` seconds, while fewer
// than `max_alive` of the spawner's robots live. The robot arrays grow; everything that holds a robot holds
// its index (physics user data, the logic's kill lists), never a pointer, so growth is safe between steps.
#include "game/game.h"

#include <cmath>

namespace ks::game {
namespace {

// How far from a candidate point the mesh is searched (sideways; up and down 4, a storey's stairs).
constexpr float kSpawnReach = 1.5f;
constexpr float kSpawnRings[] = {0.0f, 2.5f, 5.0f};

} // namespace

void Game::update_spawners() {
    for (SpawnerState& s : logic_.spawners_) {
        if (s.left <= 0 || s.stuck || steps_ < s.next_step) continue;
        int alive = 0;
        for (std::uint32_t r : s.robots) alive += robots_[r].alive() ? 1 : 0;
        if (alive >= s.max_alive) continue; // the next comes as soon as one of them dies
        if (robots_.size() >= LevelLogic::kMaxRobots) {
            s.stuck = true;
            logic_.report("spawner \"" + s.name + "\": the game holds " +
                          std::to_string(LevelLogic::kMaxRobots) +
                          " robots, the most it may; it makes no more");
            continue;
        }
        if (!spawn_robot(s)) continue; // no room now: it tries again next step
        --s.left;
        s.next_step = steps_ + s.interval_steps;
    }
}

bool Game::spawn_spot_clear(const Vec3& feet) const {
    auto near = [&](const Vec3& other, float reach) {
        const Vec3 d = other - feet;
        return std::abs(d.y) < settings_.robot_height && d.x * d.x + d.z * d.z < reach * reach;
    };
    const float robot_reach = 2.0f * settings_.robot_radius + 0.2f;
    for (const Robot& r : robots_)
        if (r.alive() && near(r.feet, robot_reach)) return false;
    return !near(player_.feet, settings_.player_radius + settings_.robot_radius + 0.2f);
}

std::optional<Vec3> Game::spawn_point(const SpawnerState& s) {
    for (float radius : kSpawnRings) {
        const int candidates = radius > 0.0f ? 8 : 1;
        for (int k = 0; k < candidates; ++k) {
            const float angle = static_cast<float>(k) * kPi * 0.25f;
            const Vec3 wanted = s.position + Vec3(std::cos(angle), 0.0f, std::sin(angle)) * radius;
            const auto on_mesh = navigation_->nearest_point(wanted, Vec3(kSpawnReach, 4.0f, kSpawnReach));
            if (on_mesh && spawn_spot_clear(*on_mesh)) return on_mesh;
        }
    }
    return std::nullopt;
}

bool Game::spawn_robot(SpawnerState& s) {
    if (!navigation_ || !navigation_->nearest_point(s.position, Vec3(kSpawnReach, 4.0f, kSpawnReach))) {
        s.stuck = true; // the mesh never changes where it lies: this spawner can never spawn
        logic_.report("spawner \"" + s.name + "\": " +
                      (navigation_ ? "no walkable ground within " +
                                         std::to_string(static_cast<int>(kSpawnReach)) + " units of it"
                                   : "the level has no navigation mesh (" + navigation_error_ + ")") +
                      ", so it makes no robots");
        return false;
    }
    const auto point = spawn_point(s);
    if (!point) return false;
    level::Entity entity;
    entity.id = logic_.next_robot_id_++;
    entity.name = s.name;
    entity.position = *point;
    entity.rotation = Vec3(s.yaw_degrees, 0.0f, 0.0f);
    entity.props = s.robot;
    if (auto added = add_robot(entity); !added) {
        s.stuck = true;
        logic_.report("spawner \"" + s.name + "\": " + added.error().message);
        return false;
    }
    const auto index = static_cast<std::uint32_t>(robots_.size() - 1);
    robots_.back().path.reserve(kMaxPathCorners);
    s.robots.push_back(index);
    logic_.robot_dead_.push_back(false);
    events_.push_back(
        {EventType::RobotSpawned, *point, Vec3(0.0f), entity.id, static_cast<float>(s.entity_id), {}});
    return true;
}

} // namespace ks::game
