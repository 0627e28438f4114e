#pragma once
// The autoplay bot: plays a level through with the same Input a keyboard produces. It plans on a navigation
// mesh built for the player's body with every door open (build_autoplay_mesh). What it walks to comes from
// the level's logic (GoalPlanner, autoplay_goals.h): the panel to use, the trigger to enter, the robot to
// hunt, the pickup to take, the door to open, or where to wait for a locked door. It walks the path's
// corners there, opens each closed door with E as it reaches it, turns to and shoots every robot it can see
// (aiming at a human-like turn rate and click rate), and presses E at the panel or floor light its goal
// names. Its own randomness (unsticking) comes from its own seeded Rng, and it reads nothing but the game's
// state and its mesh, so a run with a given seed is reproducible and its inputs replayable.
#include "core/random.h"
#include "game/autoplay_goals.h"
#include "game/game.h"
#include "nav/nav_mesh.h"

#include <memory>
#include <vector>

namespace ks::game {

// How the bot plays. The defaults are the "perfect" profile (it sees, turns and hits at once); the other
// profiles (game/bot_profiles.h) are people, their numbers from published human figures (docs/game.md).
struct AutoplaySettings {
    float turn_rate = 10.0f;     // rad/s, like a quick mouse flick
    float fire_interval = 0.15f; // seconds between clicks
    // Seconds from a robot coming into sight to the bot's first turn toward it (it carries on with what it
    // was doing meanwhile); a robot out of sight for less than kTargetMemory keeps its reaction.
    float reaction_time = 0.0f;
    // Radians: each shot is aimed at a point off the robot's centre by a normal draw of this deviation in
    // yaw and in pitch (drawn again after every shot and at every new target).
    float aim_error = 0.0f;
    // Seconds the bot stands and looks around whenever it heads for a new goal (a new player does not know
    // the way, and looks before walking on).
    float look_around = 0.0f;
    // Radians either side of the view direction (horizontally) inside which the bot notices a robot; a
    // robot that just hit it is noticed anywhere (the HUD's damage arc points at it). π: all round.
    float view_half_angle = kPi;
    float engage_range = 40.0f;   // robots farther than this are ignored
    float aim_tolerance = 0.6f;   // fire when the crosshair is within this fraction of the robot's radius
    float replan_interval = 1.0f; // seconds
    // Touching a gas cylinder sets it off, and a path bends around an obstacle as close as the body allows:
    // the bot's mesh widens every cylinder by this much so its paths keep clear of them.
    float cylinder_keep_out = 1.5f;
};

// The mesh the bot plans on: nav::player_nav_settings with the character controller's climb and slope,
// every door open, gas cylinders widened by `cylinder_keep_out`. It never changes after the build, so one
// mesh serves every bot on the level in turn (the soak's rounds), one bot at a time.
Result<std::shared_ptr<nav::NavMesh>> build_autoplay_mesh(const level::Level& level, float cylinder_keep_out);

class Autoplay {
  public:
    // The bot for `game`, created from `level`, on a mesh of its own.
    static Result<Autoplay> create(const level::Level& level, const Game& game, std::uint64_t seed,
                                   AutoplaySettings settings = {});
    // The bot on a mesh from build_autoplay_mesh for the level `game` was created from.
    Autoplay(const Game& game, std::shared_ptr<nav::NavMesh> mesh, std::uint64_t seed,
             AutoplaySettings settings = {});

    Input decide(const Game& game);
    // The corners of the current plan (the first is where the bot stood when it planned).
    const std::vector<Vec3>& path() const { return path_; }
    const nav::NavMesh& mesh() const { return *mesh_; }
    // What the bot is after now (chosen at its first decide, then again each replan interval and whenever
    // the game's events say the logic moved on).
    const BotGoal& goal() const { return goal_; }

  private:
    int pick_target(const Game& game) const;
    // Whether the bot would notice robot `r` where it stands (in view, or it just shot the bot).
    bool noticed(const Game& game, const Robot& r, const Vec3& to_robot) const;
    // Turns toward `point`, `offset` radians (yaw, pitch) off it, at the turn rate.
    void aim_at(const Game& game, const Vec3& point, Input& in, float& yaw_error, float& pitch_error,
                Vec2 offset = Vec2(0.0f)) const;
    // Whether the bot has reacted to robot `target` yet (it counts the time it has seen it).
    bool reacted(int target, float dt);
    void draw_aim_offset();
    // Standing at a new goal, sweeping the view; false when done (or the profile never looks around).
    bool look_around(float dt, Input& in);
    void fight(const Game& game, int target, Input& in);
    // Marks the goal for choosing again when this step's events may have changed what is needed.
    void notice_events(const Game& game);
    void refresh_goal(const Game& game);
    // Faces the panel or floor light the goal names and presses E; false when E would not reach it.
    bool use_goal(const Game& game, Input& in);
    void follow_path(const Game& game);
    // Whether the rest of the plan, over its next `length` units, passes within `radius` of `point` (x, z).
    bool path_passes_near(const Vec3& from, const Vec3& point, float radius, float length) const;
    bool open_door_on_path(const Game& game, Input& in);
    void unstick(const Game& game, Input& in);

    AutoplaySettings settings_;
    Rng rng_;
    std::shared_ptr<nav::NavMesh> mesh_;
    GoalPlanner planner_;
    BotGoal goal_;
    bool goal_stale_ = true;
    float since_goal_ = 0.0f;
    std::vector<Vec3> path_;
    std::size_t waypoint_ = 0;
    float since_plan_ = 1e9f;
    float fire_wait_ = 0.0f;
    float interact_wait_ = 0.0f;
    Vec3 stuck_anchor_{0.0f};
    float stuck_time_ = 0.0f;
    float unstick_time_ = 0.0f;
    float unstick_side_ = 1.0f;
    int target_ = -1;          // the robot reacted to or being reacted to
    float target_seen_ = 0.0f; // seconds it has been in sight
    float target_lost_ = 0.0f; // seconds since it was last in sight
    Vec2 aim_offset_{0.0f};    // the present shot's aim error (yaw, pitch)
    float looking_left_ = 0.0f, look_direction_ = 1.0f;
    Vec3 shot_from_{0.0f};    // where the last shot that hurt the bot came from (a robot's hand)
    float since_shot_ = 1e9f; // seconds since then
};

// A robot out of the bot's sight for less than this is still the one it reacted to.
inline constexpr float kTargetMemory = 1.0f;

} // namespace ks::game
