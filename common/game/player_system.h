#pragma once
// The player: the body the input drives, the rifle's shot (which hurts robots and sets off gas cylinders),
// damage with the shield first, what pickups add, footsteps and landings, and the death camera.
#include "core/result.h"
#include "game/game_core.h"

#include <optional>

namespace ks::game {

class LevelEdit; // live_carry.h
class RobotSystem;
class Explosives;

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

enum class PickupKind : std::uint8_t { Health, Ammo, Shield };

// The death camera (reference: eye drops to the body centre in 0.3 s Quadratic.In, then camera.rotation to
// (x π/4, z π/2) in 0.3 s Bounce.InOut, then 1 s until the death menu). three.js's rotation.z = +π/2 turns
// the camera's up to its left: the soldier falls onto his left side, the world turns clockwise on screen.
struct DeathCamera {
    float eye_drop = 0.0f; // subtract from the eye height
    float pitch = 0.0f;    // added to the view pitch (+π/4: looks up, as the reference's x)
    float roll = 0.0f; // geometry::Camera's roll (positive leans the head right): −π/2, a fall to the left
    bool menu_ready = false;
};

class PlayerSystem {
  public:
    // The shot hurts `robots` and sets off `explosives`; neither is used before the first step.
    PlayerSystem(GameCore& core, RobotSystem& robots, Explosives& explosives);

    Result<void> add(const level::Level& level, float gravity);
    const PlayerState& state() const { return player_; }
    const Vec3& start() const { return start_; }

    // Before the physics step: view, walking, jump and the shot.
    void update(const Input& input, float dt);
    // After it: where the body went, footsteps and landings.
    void read_back(float dt);
    void damage(float amount);
    void damage(float amount, const Vec3& source);
    // An explosion's horizontal push (fading) and upward kick.
    void knock(const Vec3& push, float lift);
    // What a pickup of `kind` adds (capped at the maximum), or nothing when the player is at the maximum.
    std::optional<float> take(PickupKind kind, float amount);
    void teleport(const Vec3& feet, float yaw, float pitch);
    DeathCamera death_camera() const;
    // The live play-test's rebuild (live_carry.h): the running game's player, all of it but the body (a
    // moved player start does not move a player already playing).
    void carry_from(const PlayerSystem& previous);

  private:
    void feet_events(bool was_grounded, const Vec3& old_velocity, const Vec3& ground_normal, float dt);
    void fire_shot();

    GameCore& core_;
    RobotSystem& robots_;
    Explosives& explosives_;
    PlayerState player_;
    Vec3 start_{0.0f};
};

} // namespace ks::game
