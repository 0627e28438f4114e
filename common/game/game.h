#pragma once
// The game rules, headless and deterministic. A Game is built from a level: it owns the physics World and
// every entity in contiguous arrays, advances one fixed step per Input, and appends what happened to an
// event list (cleared each step) that the runtime turns into particles, flashes and recoil. Everything the
// renderer draws is exposed read-only here; the game never calls rendering and never reads a clock.
// All randomness comes from one seeded Rng, drawn in a fixed order (robots in index order).
#include "anim/clip_io.h"
#include "anim/player.h"
#include "core/random.h"
#include "core/result.h"
#include "game/caption.h"
#include "game/game_types.h"
#include "game/level_logic.h"
#include "game/patrol.h"
#include "level/entity_shapes.h"
#include "level/level.h"
#include "nav/nav_mesh.h"
#include "physics/world.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

// What a physics body belongs to (kept in BodyDesc::user_data as kind << 32 | index).
enum class BodyKind : std::uint8_t {
    None,
    Player,
    Robot,
    Cylinder,
    DoorLeaf,
    DoorSensor,
    Pickup,
    Panel,
    Scenery
};
inline std::uint64_t pack_user(BodyKind kind, std::uint32_t index) {
    return static_cast<std::uint64_t>(kind) << 32 | index;
}
inline BodyKind user_kind(std::uint64_t user) {
    return static_cast<BodyKind>(user >> 32);
}
inline std::uint32_t user_index(std::uint64_t user) {
    return static_cast<std::uint32_t>(user);
}

// The robot's shot (the ray, the RobotShot event, the damage) happens when its `shooting` clip passes an
// event of this name, so animators time the shot in the clip; a shooting clip without one fires at its start.
inline constexpr std::string_view kMuzzleFlashEvent = "muzzle_flash";

// The robot model's yaw (the level's yaw + 90°): one conversion for every view, kept with the entity shapes.
using level::robot_model_yaw;

struct PlayerState {
    physics::BodyId body;
    Vec3 feet{0.0f};
    Vec3 velocity{0.0f};
    Vec3 knockback{0.0f}; // horizontal push from explosions, fading
    float yaw = 0.0f;     // radians, 0 faces -z, positive turns left
    float pitch = 0.0f;   // radians, clamped to ±π/2
    float health = 100.0f, shield = 0.0f;
    int ammo = 150;
    bool grounded = false;
    float damage_flash = 0.0f; // seconds left of the red flash
    float hit_marker = 0.0f;   // seconds left of the hit marker
    float recoil = 0.0f;       // seconds since the last shot (large = at rest)
    int shots = 0;
    int hits = 0; // shots that hit a live robot: accuracy is hits / shots (a statistic: not hashed)
    float damage_taken = 0.0f;
    float stride = 0.0f;   // ground distance walked since the last footstep (sound only; not hashed)
    float air_time = 0.0f; // seconds since the feet left the ground (sound only; not hashed)
    Vec3 eye() const { return feet + Vec3(0, 3.0f, 0); }
    Vec3 view_direction() const;
};

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
    bool heard = false; // a sound reached it this step (Game::hear_sound)
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

struct Door {
    int entity_id = 0;
    level::DoorProps props;
    geometry::Transform frame; // bottom centre, door yaw
    physics::BodyId leaves[2], sensor;
    float progress = 0.0f; // 0 closed .. 1 open (linear in time, as the reference)
    bool opening = false;  // where it is heading
    bool locked = false;   // the player's E does nothing (links still open and close it)
    bool player_inside = false;
    float leaf_offset() const { return level::door_leaf_slide(props, progress); } // each leaf slides this far
    // Where leaf `side` (0: local -x, 1: +x) is at the current progress (level::door_leaf_centre).
    geometry::Transform leaf_transform(int side) const {
        return {frame.to_world(level::door_leaf_centre(props, side, progress)), frame.rotation};
    }
};

struct Light {
    int entity_id = 0;
    bool floor = false; // floor lights toggle with E; top lights are fixed
    level::LightProps props;
    Vec3 position{0.0f}; // bottom centre (floor) or fixture (top)
    float yaw = 0.0f;
    float cone_angle = 35.0f;
    bool on = true;
    float intensity() const { return on ? props.intensity : 0.0f; }
    float emissive() const { return on ? 1.5f : 0.0f; }
};

enum class PickupKind : std::uint8_t { Health, Ammo, Shield };

struct Pickup {
    int entity_id = 0;
    PickupKind kind = PickupKind::Health;
    float amount = 10.0f;
    Vec3 centre{0.0f};
    physics::BodyId trigger;
    bool taken = false;
};

struct Cylinder {
    int entity_id = 0;
    level::GasCylinderProps props;
    Vec3 centre{0.0f};
    float yaw = 0.0f;
    physics::BodyId body;
    float fuse = -1.0f; // seconds until it explodes; < 0 when not lit
    bool exploded = false;
};

struct Panel {
    int entity_id = 0;
    Vec3 centre{0.0f};
    Vec3 size{0.0f};
    float yaw = 0.0f;
    physics::BodyId body;
};

// The death camera (reference: eye drops to the body centre in 0.3 s Quadratic.In, then camera.rotation to
// (x π/4, z π/2) in 0.3 s Bounce.InOut, then 1 s until the death menu). three.js's rotation.z = +π/2 turns
// the camera's up to its left: the soldier falls onto his left side, the world turns clockwise on screen.
struct DeathCamera {
    float eye_drop = 0.0f; // subtract from the eye height
    float pitch = 0.0f;    // added to the view pitch (+π/4: looks up, as the reference's x)
    float roll = 0.0f; // geometry::Camera's roll (positive leans the head right): −π/2, a fall to the left
    bool menu_ready = false;
};

struct GameOptions {
    std::uint64_t seed = 1;
    GameSettings settings;
    // Robot clips and rig; loaded from assets/animations/robot.json when null.
    std::shared_ptr<const anim::AnimationLibrary> animations;
    // The robots' navigation mesh of this level (build_robot_navigation): the game walks a copy of it (its
    // doors open and close) instead of building its own, which is most of a game's build. For many games
    // of one level (the play-test analysis); built when null.
    std::shared_ptr<const nav::NavMesh> navigation;
};

// The robots' navigation mesh of `level`, as every Game builds it (nav::robot_nav_settings with the
// character controller's climb and slope).
Result<std::unique_ptr<nav::NavMesh>> build_robot_navigation(const level::Level& level);

class Game {
  public:
    // Builds the world from the level. Errors (bad shapes, missing clips) name the entity.
    static Result<std::unique_ptr<Game>> create(const level::Level& level, GameOptions options = {});
    Game(const Game&) = delete;
    Game& operator=(const Game&) = delete;

    // One fixed step. Non-finite or absurd input is sanitised. Clears and refills events().
    void step(const Input& input);

    Phase phase() const { return phase_; }
    bool paused() const { return paused_; }
    double time() const { return static_cast<double>(steps_) * settings_.step; }
    std::int64_t steps() const { return steps_; }
    double phase_time() const { return phase_time_; }
    std::span<const Event> events() const { return events_; }

    const PlayerState& player() const { return player_; }
    std::span<const Robot> robots() const { return robots_; }
    const anim::Pose& robot_pose(std::size_t index) const { return robot_anims_[index].pose(); }
    int robot_animation_clip(std::size_t index) const { return robot_anims_[index].current_clip(); }
    std::span<const Door> doors() const { return doors_; }
    std::span<const Light> lights() const { return lights_; }
    std::span<const Pickup> pickups() const { return pickups_; }
    float pickup_spin() const { return static_cast<float>(time()) * kPi * 0.5f; } // π/2 rad/s
    std::span<const Cylinder> cylinders() const { return cylinders_; }
    const std::vector<Panel>& panels() const { return panels_; }
    const Caption& caption() const { return caption_; }
    DeathCamera death_camera() const;
    int robots_killed() const { return robots_killed_; }
    const GameSettings& settings() const { return settings_; }
    const physics::World& world() const { return world_; }
    // Whether level geometry (walls, floors, closed door leaves: what blocks sight) lies on the straight line
    // between two points. Characters, pickups and triggers do not count. For sound occlusion.
    bool line_blocked(const Vec3& from, const Vec3& to) const;
    // The robots' navigation mesh; null when it could not be built (navigation_error() says why).
    const nav::NavMesh* navigation() const { return navigation_.get(); }
    const std::string& navigation_error() const { return navigation_error_; }
    // Bounds of the level's static geometry (walls, floors, stairs, props).
    const geometry::Aabb& level_bounds() const { return level_bounds_; }
    const Vec3& player_start() const { return player_start_; }
    const anim::AnimationLibrary& animations() const { return *animations_; }
    // World position of the right hand's tip (the robot's muzzle) in its current pose.
    Vec3 robot_muzzle(std::size_t index) const;
    // The entity E would act on now (level id), or -1.
    int interact_target() const { return interact_target_; }
    // FNV-1a over the whole simulation state (positions, velocities, health, timers, modes, the Rng).
    std::uint64_t state_hash() const;
    // The level's logic: objectives (the HUD's list), the message on screen, triggers, spawners, problems.
    const LevelLogic& logic() const { return logic_; }

    // Direct effects, also used by tests to stage scenarios. Damage from `source` (a robot's hand tip, a
    // blast centre) says so in its PlayerDamaged event; without one the event points nowhere.
    void damage_player(float amount);
    void damage_player(float amount, const Vec3& source);
    void damage_robot(std::size_t index, float amount, bool by_player);
    void explode_cylinder(std::size_t index);
    void teleport_player(const Vec3& feet, float yaw, float pitch = 0.0f);
    // Runs a link action now, as a link would (the editor's "try it" and tests): `target` is an entity id,
    // or -1 for the level; objectives are named by complete_objective. Returns false when the entity does
    // not take the action.
    bool run_action(level::LinkAction action, int target);
    bool complete_objective(std::string_view id);

  private:
    explicit Game(GameOptions options);
    Result<void> build(const level::Level& level);
    Result<void> find_clips();
    Result<void> add_entity(const level::Entity& e);
    Result<void> add_door(const level::Entity& e);
    Result<void> add_robot(const level::Entity& e);
    Result<void> add_pickup(const level::Entity& e);
    Result<void> add_player(const level::Level& level);
    Result<physics::BodyId> add_body(const physics::BodyDesc& desc, const level::Entity& e);
    void update_player(const Input& input, float dt);
    void player_feet_events(bool was_grounded, const Vec3& old_velocity, const Vec3& ground_normal, float dt);
    void fire_player_shot();
    void update_robot(std::size_t index, float dt);
    void robot_wander(Robot& r, std::size_t index, float dt);
    void walk_patrol(Robot& r, float dt);
    void robot_fire(std::size_t index);
    // The step's clip events of robot `index` (after its animation advanced): cues, and the shot.
    void robot_clip_events(std::size_t index);
    bool robot_sees_player(const Robot& r) const;
    void update_doors(float dt);
    void update_cylinders(float dt);
    void handle_physics_events();
    void update_interaction(const Input& input);
    void interact(int entity_id);
    void take_pickup(Pickup& p);
    void set_door_opening(Door& d, bool opening);
    // Level logic (logic_build.cpp, logic_step.cpp, spawners.cpp).
    void build_logic(const level::Level& level);
    void update_logic(float dt);
    // Runs ready actions and what they set off until nothing is left (or the step's budget is spent); the
    // game's events from `cursor` on are new to the logic.
    void run_logic_cascade(std::size_t cursor);
    void translate_events(std::size_t& cursor);
    void note_deaths();
    void test_triggers();
    bool trigger_holds(const TriggerState& t) const;
    void apply_action(const LogicLink& link);
    void complete_objective_at(std::size_t index);
    void check_kill_objectives();
    void update_spawners();
    bool spawn_robot(SpawnerState& s);
    std::optional<Vec3> spawn_point(const SpawnerState& s);
    bool spawn_spot_clear(const Vec3& feet) const;
    void hold_dormant(std::size_t index, float dt);
    void set_phase(Phase phase);
    void push(EventType type, Vec3 position = Vec3(0.0f), int entity = -1, float amount = 0.0f,
              Vec3 end = Vec3(0.0f));
    void push_cue(EventType type, Vec3 position, int entity, std::string_view cue);
    // Closest shootable hit along a ray, skipping `ignore` and (for robot shots) every robot.
    bool shoot_ray(const geometry::Ray& ray, physics::BodyId ignore, bool skip_robots, physics::RayHit& hit);
    // Robot AI pieces (robots.cpp, robot_hunt.cpp).
    bool robot_engaged(const Robot& r, float distance, bool same_level) const;
    bool robot_has_clear_shot(const Robot& r) const;
    bool robot_line_to_player(const Robot& r, float height) const;
    void robot_fight(std::size_t index, float distance, float dt);
    void start_hunt(std::size_t index);
    void robot_hunt(std::size_t index, float dt);
    void stop_hunting(std::size_t index);
    // Navigation (robot_navigation.cpp).
    void build_navigation(const level::Level& level);
    void update_door_navigation(const Door& d, float previous_progress);
    // The horizontal velocity that walks `r` along the mesh toward `goal` at `speed` (zero without a mesh,
    // a path, or once there).
    Vec3 follow_path(Robot& r, const Vec3& goal, float speed, float dt);
    bool path_finished(const Robot& r) const;
    Vec3 robot_separation(const Robot& r) const;
    // A shot or an explosion at `source`: idle and searching robots whose hearing radius reaches it along
    // the mesh go to look.
    void hear_sound(const Vec3& source);

    GameSettings settings_;
    std::shared_ptr<const anim::AnimationLibrary> animations_;
    Rng rng_;
    physics::World world_;
    PlayerState player_;
    std::vector<Robot> robots_;
    std::vector<anim::Player> robot_anims_; // parallel to robots_
    std::vector<Door> doors_;
    std::vector<Light> lights_;
    std::vector<Pickup> pickups_;
    std::vector<Cylinder> cylinders_;
    std::vector<Panel> panels_;
    LevelLogic logic_;
    Caption caption_;
    std::unique_ptr<nav::NavMesh> navigation_; // null when the level has none (robots stand guard)
    std::shared_ptr<const nav::NavMesh> navigation_source_; // GameOptions::navigation, until the build
    std::string navigation_error_;
    geometry::Aabb level_bounds_ = geometry::Aabb::empty();
    Vec3 player_start_{0.0f};
    float gravity_ = -25.0f; // the level's, given to every character body
    int interact_target_ = -1;
    Phase phase_ = Phase::Playing;
    double phase_time_ = 0.0;
    bool paused_ = false;
    std::int64_t steps_ = 0;
    int robots_killed_ = 0;
    std::vector<Event> events_;
    struct Clips {
        int idle = -1, alert = -1, shoot_pose = -1, shooting = -1, shoot_pose_reverse = -1, death = -1;
    } clips_;
    int hand_tip_node_ = -1;
    bool shot_on_event_ = true; // the shooting clip has a kMuzzleFlashEvent (else it fires at its start)
    float alert_length_ = 0.6f, aim_length_ = 0.3f, death_length_ = 1.8f;
};

} // namespace ks::game
