#pragma once
// The robots (seed-facts §5.2): their records and animation players, the AI (wander or patrol, alert, chase,
// aim and shoot, hunt and search along the navigation mesh), their shots, damage and death, and the
// navigation mesh they walk (whose door polygons the doors open and close). Randomness is drawn from the
// shared Rng in robot index order. Robots made during play (spawners) are added like the level's own; the
// arrays grow, so everything that holds a robot holds its index, never a pointer.
#include "anim/clip_io.h"
#include "anim/player.h"
#include "core/result.h"
#include "game/game_core.h"
#include "game/patrol.h"
#include "level/entity_shapes.h"
#include "nav/nav_mesh.h"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

class LevelEdit; // live_carry.h
class PlayerSystem;
class Explosives;
struct Door;

// The robot's shot (the ray, the RobotShot event, the damage) happens when its `shooting` clip passes an
// event of this name, so animators time the shot in the clip; a shooting clip without one fires at its start.
inline constexpr std::string_view kMuzzleFlashEvent = "muzzle_flash";

// The robot model's yaw (the level's yaw + 90°): one conversion for every view, kept with the entity shapes.
using level::robot_model_yaw;

// Idle: wander or patrol. Alert, Chase, Aim, Shoot: fighting the player it sees (or is angry with). Hunt:
// lost the player (or heard a shot): walks the navigation mesh to the last known position. Search: looks
// around there until its search time runs out, then back to Idle.
enum class RobotMode : std::uint8_t { Idle, Alert, Chase, Aim, Shoot, Dying, Dead, Hunt, Search };

// Seconds a robot shows it was hit (the runtime tints it red, fading), as the reference's 1 s flash.
inline constexpr float kRobotHitFlashSeconds = 1.0f;

// The most corners a robot's path keeps (its vector is reserved once, so following allocates nothing).
inline constexpr std::size_t kMaxPathCorners = 256;

struct Robot {
    int entity_id = 0;
    physics::BodyId body;
    level::RobotProps props;
    Vec3 feet{0.0f};
    float yaw = 0.0f; // facing, level convention (0 faces -z); the model's +X points this way
    float health = 100.0f;
    RobotMode mode = RobotMode::Idle;
    float mode_time = 0.0f;
    float angry = 0.0f;     // seconds of anger left
    float cooldown = 0.0f;  // seconds until the next shot may fire
    float hit_flash = 0.0f; // seconds left of the hit flash (kRobotHitFlashSeconds at a hit)
    Vec3 knockback{0.0f};
    // Idle wander (reference: turn ±(0.5..1)·π/2 over 1.4 s, then drive at 2.4 decaying over 3.2-4 s).
    bool wander_turning = true;
    float wander_from = 0.0f, wander_to = 0.0f, wander_length = 1.4f;
    bool collided = false;
    // Along props.patrol, walked instead of the wander while idle when the robot has one.
    PatrolProgress patrol;
    // Hunting and searching: where the player was last seen or heard, and the seconds of search left.
    Vec3 last_known{0.0f};
    float hunt_left = 0.0f;
    bool heard = false; // a sound reached it this step (RobotSystem::hear_sound)
    Vec3 search_point{0.0f};
    bool dormant = false; // stands still, blind and deaf, until a link activates or alerts it or it is hurt
    // The path being followed on the navigation mesh (corners), the goal it was planned for, the next
    // corner and the seconds until it is planned again.
    std::vector<Vec3> path;
    Vec3 path_goal{0.0f};
    std::size_t path_next = 0;
    float replan_in = 0.0f;
    // Model yaw for the renderer: the level yaw + 90° (the reference's rotY; the model faces +X).
    float model_yaw() const { return robot_model_yaw(yaw); }
    bool alive() const { return mode != RobotMode::Dying && mode != RobotMode::Dead; }
};

// The robots' navigation mesh of `level`, as every Game builds it (nav::robot_nav_settings with the
// character controller's climb and slope).
Result<std::unique_ptr<nav::NavMesh>> build_robot_navigation(const level::Level& level);

class RobotSystem {
  public:
    // Robots shoot at `player` and set off `explosives`; neither is used before the first step.
    RobotSystem(GameCore& core, PlayerSystem& player, Explosives& explosives,
                std::shared_ptr<const anim::AnimationLibrary> animations);

    // The clips and the hand node the AI plays and shoots from; an error names the missing one.
    Result<void> find_clips();
    // Room for `count` robots, and the gravity their bodies fall with.
    void prepare(std::size_t count, float gravity);
    Result<void> add(const level::Entity& e);
    // The mesh of the level (a copy of `source` when given), with the doors' polygons as the doors stand.
    void build_navigation(const level::Level& level, std::shared_ptr<const nav::NavMesh> source,
                          std::span<const Door> doors);

    // Before the physics step: every robot's AI (or a dormant robot's stillness), in index order.
    void update(float dt);
    // After it: where the bodies went, the animations and their clip events, falls out of the level.
    void read_back(float dt);
    void damage(std::size_t index, float amount, bool by_player);
    // A link's activate (or alert: it also knows where the player is); a dead robot takes no orders.
    void wake(std::size_t index, bool alert);
    // An explosion's horizontal push (fading).
    void knock(std::size_t index, const Vec3& push) { robots_[index].knockback = push; }
    // It walked into something sideways (its next wander turns further).
    void bumped(std::size_t index) { robots_[index].collided = true; }
    // A shot or an explosion at `source`: idle and searching robots whose hearing radius reaches it along
    // the mesh go to look.
    void hear_sound(const Vec3& source);
    // The live play-test's rebuild (live_carry.h): the level's robots the edit kept take over their state
    // in `previous` (their place too unless the edit moved them), and the kill count; returns how many.
    int carry_from(const RobotSystem& previous, const LevelEdit& edit);
    // Robot `index` takes over robot `previous_index` of `previous`: its state and animation, and its place
    // unless not `keep_place` (then it stands where the level puts it); its path is planned again.
    void carry_robot(std::size_t index, const RobotSystem& previous, std::size_t previous_index,
                     bool keep_place);

    std::span<const Robot> robots() const { return robots_; }
    const anim::Player& animation(std::size_t index) const { return anims_[index]; }
    // World position of the right hand's tip (the robot's muzzle) in its current pose.
    Vec3 muzzle(std::size_t index) const;
    int killed() const { return killed_; }
    const anim::AnimationLibrary& animations() const { return *animations_; }
    // The robots' navigation mesh; null when it could not be built (navigation_error() says why).
    nav::NavMesh* navigation() { return navigation_.get(); }
    const nav::NavMesh* navigation() const { return navigation_.get(); }
    const std::string& navigation_error() const { return navigation_error_; }

  private:
    void warn_missing_event_sounds(const std::string& source) const;
    void update_robot(std::size_t index, float dt);
    void hold_dormant(std::size_t index, float dt);
    void wander(Robot& r, float dt);
    void walk_patrol(Robot& r, float dt);
    void fire(std::size_t index);
    // The step's clip events of robot `index` (after its animation advanced): cues, and the shot.
    void clip_events(std::size_t index);
    bool sees_player(const Robot& r) const;
    bool engaged(const Robot& r, float distance, bool same_level) const;
    bool has_clear_shot(const Robot& r) const;
    bool line_to_player(const Robot& r, float height) const;
    void fight(std::size_t index, float distance, float dt);
    void start_hunt(std::size_t index);
    void hunt(std::size_t index, float dt);
    void stop_hunting(std::size_t index);
    // The horizontal velocity that walks `r` along the mesh toward `goal` at `speed` (zero without a mesh,
    // a path, or once there).
    Vec3 follow_path(Robot& r, const Vec3& goal, float speed, float dt);
    bool path_finished(const Robot& r) const;
    Vec3 separation(const Robot& r) const;

    GameCore& core_;
    PlayerSystem& player_;
    Explosives& explosives_;
    std::shared_ptr<const anim::AnimationLibrary> animations_;
    std::vector<Robot> robots_;
    std::vector<anim::Player> anims_;          // parallel to robots_
    std::unique_ptr<nav::NavMesh> navigation_; // null when the level has none (robots stand guard)
    std::string navigation_error_;
    float gravity_ = -25.0f; // the level's, given to every robot body
    int killed_ = 0;
    struct Clips {
        int idle = -1, alert = -1, shoot_pose = -1, shooting = -1, shoot_pose_reverse = -1, death = -1;
    } clips_;
    int hand_tip_node_ = -1;
    bool shot_on_event_ = true; // the shooting clip has a kMuzzleFlashEvent (else it fires at its start)
    float alert_length_ = 0.6f, aim_length_ = 0.3f, death_length_ = 1.8f;
};

} // namespace ks::game
