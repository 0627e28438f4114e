#pragma once
// Spawners: robots made during play (a link's spawn starts a wave), with the spawner's robot properties,
// through RobotSystem::add like the level's own. Each stands on the robots' navigation mesh (the nearest
// point to the spawner, or to a point on a ring around it when a robot or the player stands there), one
// every `interval` seconds, while fewer than `max_alive` of the spawner's robots live.
#include "game/game_core.h"
#include "level/level.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ks::game {

class LevelEdit; // live_carry.h
class LevelLogic;
class PlayerSystem;
class RobotSystem;

struct SpawnerState {
    int entity_id = 0;
    std::string name;
    level::RobotProps robot;
    Vec3 position{0.0f};
    float yaw_degrees = 0.0f;
    int count = 1, max_alive = 1;
    std::int64_t interval_steps = 0; // the interval rounded to whole steps
    int left = 0;                    // robots still to make in the current wave
    std::int64_t next_step = 0;      // the step from which the next may be made
    bool started = false;
    bool stuck = false; // no navigation mesh, or no walkable ground near it: it can never make a robot
    std::vector<std::uint32_t> robots; // indices into Game::robots() of those it made
};

class Spawners {
  public:
    static constexpr std::size_t kMaxRobots = 1024; // spawners stop making robots past this many in the game

    // New robots keep clear of `player` and of the living `robots`.
    Spawners(GameCore& core, PlayerSystem& player, RobotSystem& robots);

    // The level's spawners; spawned robots get entity ids after every id in the level.
    void build(const level::Level& level);
    // A link's spawn: a wave of `count` starts now (one under way goes on as it was).
    void start(std::size_t spawner);
    // At the level's start (after the navigation mesh is built): a spawner with no walkable ground near it
    // can never make a robot, which is said now in `logic`'s problems rather than when a link first starts
    // it, and it is marked stuck.
    void check_ground(LevelLogic& logic);
    // Makes the robots that are due; what can never work is said once in `logic`'s problems.
    void update(LevelLogic& logic);
    // The live play-test's rebuild (live_carry.h): the spawners the edit kept go on with their wave, and
    // their robots still alive in `previous` come along (added to this game's robots).
    void carry_from(const Spawners& previous, const LevelEdit& edit);
    std::span<const SpawnerState> spawners() const { return spawners_; }

  private:
    bool spawn_robot(SpawnerState& s, LevelLogic& logic);
    // False (and `s` stuck, the reason reported) when no navigation mesh lies within reach of it.
    bool has_ground(SpawnerState& s, LevelLogic& logic);
    std::optional<Vec3> spawn_point(const SpawnerState& s);
    bool spawn_spot_clear(const Vec3& feet) const;

    GameCore& core_;
    PlayerSystem& player_;
    RobotSystem& robots_;
    std::vector<SpawnerState> spawners_;
    int next_robot_id_ = 1; // entity ids of spawned robots, after the level's
};

} // namespace ks::game
