#pragma once
// The autoplay bot: plays a level through with the same Input a keyboard produces. It walks a nav grid
// (built once from the level through physics queries) toward the control panel, opens the doors on its
// way, turns to and shoots every robot it can see (aiming at a human-like turn rate and click rate), and
// presses E at the panel. Its own randomness (unsticking) comes from its own seeded Rng, and it reads
// nothing but the game's state, so a run with a given seed is reproducible and its inputs replayable.
#include "core/random.h"
#include "game/game.h"
#include "game/nav_grid.h"

#include <vector>

namespace ks::game {

struct AutoplaySettings {
    float turn_rate = 10.0f;      // rad/s, like a quick mouse flick
    float fire_interval = 0.15f;  // seconds between clicks
    float engage_range = 40.0f;   // robots farther than this are ignored
    float aim_tolerance = 0.6f;   // fire when the crosshair is within this fraction of the robot's radius
    float replan_interval = 1.0f; // seconds
};

class Autoplay {
  public:
    Autoplay(const Game& game, std::uint64_t seed, AutoplaySettings settings = {});
    Input decide(const Game& game);
    const NavGrid& grid() const { return grid_; }
    const std::vector<Vec3>& path() const { return path_; }

  private:
    int pick_target(const Game& game) const;
    void aim_at(const Game& game, const Vec3& point, Input& in, float& yaw_error, float& pitch_error) const;
    Vec3 goal(const Game& game) const;

    AutoplaySettings settings_;
    Rng rng_;
    NavGrid grid_;
    std::vector<Vec3> path_;
    std::size_t waypoint_ = 0;
    float since_plan_ = 1e9f;
    float fire_wait_ = 0.0f;
    float interact_wait_ = 0.0f;
    Vec3 stuck_anchor_{0.0f};
    float stuck_time_ = 0.0f;
    float unstick_time_ = 0.0f;
    float unstick_side_ = 1.0f;
};

} // namespace ks::game
