#pragma once
// The game rules, headless and deterministic. A Game is built from a level and composed of systems, each
// with its own state and header: the player (player_system.h), the robots and their navigation mesh
// (robot_system.h), doors, lights, pickups and panels with E and its caption (interactables.h), gas
// cylinders (explosives.h), spawners (spawners.h) and the level logic (level_logic.h), all sharing one
// GameCore (game_core.h: settings, physics World, Rng, events, phase). The Game builds them, advances them
// one fixed step per Input in a fixed order (Game::step, game_step.cpp), routes what the physics reported
// to them, and hashes their state. The runtime reads everything here read-only and turns the events
// (cleared each step) into particles, flashes and recoil; the game never calls rendering and never reads a
// clock. All randomness comes from one seeded Rng, drawn in a fixed order (robots in index order).
// docs/architecture.md, "Game systems", says where a new system goes.
#include "anim/clip_io.h"
#include "anim/player.h"
#include "core/result.h"
#include "game/caption.h"
#include "game/explosives.h"
#include "game/game_core.h"
#include "game/game_types.h"
#include "game/interactables.h"
#include "game/level_logic.h"
#include "game/player_system.h"
#include "game/robot_system.h"
#include "game/spawners.h"
#include "level/entity_shapes.h"
#include "level/level.h"
#include "nav/nav_mesh.h"
#include "physics/world.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

class LevelEdit; // live_carry.h

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

class Game {
  public:
    // Builds the world from the level. Errors (bad shapes, missing clips) name the entity.
    static Result<std::unique_ptr<Game>> create(const level::Level& level, GameOptions options = {});
    Game(const Game&) = delete;
    Game& operator=(const Game&) = delete;

    // One fixed step. Non-finite or absurd input is sanitised. Clears and refills events().
    void step(const Input& input);

    Phase phase() const { return core_.phase; }
    bool paused() const { return core_.paused; }
    double time() const { return static_cast<double>(core_.steps) * core_.settings.step; }
    std::int64_t steps() const { return core_.steps; }
    double phase_time() const { return core_.phase_time; }
    std::span<const Event> events() const { return core_.events; }

    // The systems' state, read-only (each system's header says what its records hold).
    const PlayerState& player() const { return player_.state(); }
    std::span<const Robot> robots() const { return robots_.robots(); }
    const anim::Pose& robot_pose(std::size_t index) const { return robots_.animation(index).pose(); }
    int robot_animation_clip(std::size_t index) const { return robots_.animation(index).current_clip(); }
    std::span<const Door> doors() const { return interactables_.doors(); }
    std::span<const Light> lights() const { return interactables_.lights(); }
    std::span<const Pickup> pickups() const { return interactables_.pickups(); }
    float pickup_spin() const { return static_cast<float>(time()) * kPi * 0.5f; } // π/2 rad/s
    std::span<const Cylinder> cylinders() const { return explosives_.cylinders(); }
    const std::vector<Panel>& panels() const { return interactables_.panels(); }
    const Caption& caption() const { return interactables_.caption(); }
    DeathCamera death_camera() const { return player_.death_camera(); }
    int robots_killed() const { return robots_.killed(); }
    const GameSettings& settings() const { return core_.settings; }
    const physics::World& world() const { return core_.world; }
    // Whether level geometry (walls, floors, closed door leaves: what blocks sight) lies on the straight line
    // between two points. Characters, pickups and triggers do not count. For sound occlusion.
    bool line_blocked(const Vec3& from, const Vec3& to) const { return core_.line_blocked(from, to); }
    // The robots' navigation mesh; null when it could not be built (navigation_error() says why).
    const nav::NavMesh* navigation() const { return robots_.navigation(); }
    const std::string& navigation_error() const { return robots_.navigation_error(); }
    // Bounds of the level's static geometry (walls, floors, stairs, props).
    const geometry::Aabb& level_bounds() const { return level_bounds_; }
    const Vec3& player_start() const { return player_.start(); }
    const anim::AnimationLibrary& animations() const { return robots_.animations(); }
    // World position of the right hand's tip (the robot's muzzle) in its current pose.
    Vec3 robot_muzzle(std::size_t index) const { return robots_.muzzle(index); }
    // The entity E would act on now (level id), or -1.
    int interact_target() const { return interactables_.interact_target(); }
    // FNV-1a over the whole simulation state (positions, velocities, health, timers, modes, the Rng).
    std::uint64_t state_hash() const;
    // The level's logic: objectives (the HUD's list), the message on screen, triggers, spawners, problems.
    const LevelLogic& logic() const { return logic_; }

    // Direct effects, also used by tests to stage scenarios. Damage from `source` (a robot's hand tip, a
    // blast centre) says so in its PlayerDamaged event; without one the event points nowhere.
    void damage_player(float amount) { player_.damage(amount); }
    void damage_player(float amount, const Vec3& source) { player_.damage(amount, source); }
    void damage_robot(std::size_t index, float amount, bool by_player) {
        robots_.damage(index, amount, by_player);
    }
    void explode_cylinder(std::size_t index) { explosives_.explode(index); }
    void teleport_player(const Vec3& feet, float yaw, float pitch = 0.0f) {
        player_.teleport(feet, yaw, pitch);
    }
    // Runs a link action now, as a link would (the editor's "try it" and tests): `target` is an entity id,
    // or -1 for the level; objectives are named by complete_objective. Returns false when the entity does
    // not take the action.
    bool run_action(level::LinkAction action, int target) { return logic_.run_action(action, target); }
    bool complete_objective(std::string_view id) { return logic_.complete_objective(id); }

    // The live play-test's rebuild (live_update.h): this game, just built on the edited level, takes over
    // `previous`'s state for everything `edit` kept, system by system. Returns how many entities kept it.
    int carry_from(const Game& previous, const LevelEdit& edit);

  private:
    explicit Game(GameOptions options);
    Result<void> build(const level::Level& level);
    // Walls, floors, props, lights, cylinders and panels: a static body each (and their systems' records).
    Result<void> add_entity(const level::Entity& e);
    // Trigger events and contacts from the physics step, to the systems they concern.
    void handle_physics_events();

    // The systems, in the order they are built; each holds references to the ones it acts on.
    GameCore core_;
    PlayerSystem player_;
    RobotSystem robots_;
    Interactables interactables_;
    Explosives explosives_;
    Spawners spawners_;
    LevelLogic logic_;
    geometry::Aabb level_bounds_ = geometry::Aabb::empty();
    std::shared_ptr<const nav::NavMesh> navigation_source_; // GameOptions::navigation, until the build
};

} // namespace ks::game
