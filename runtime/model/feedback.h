#pragma once
// The game's hit and impact feedback as plain logic, without GL or ImGui: the red damage-direction arcs
// round the crosshair, camera shake from explosions, the red flash of a hit robot and the short-lived
// muzzle-flash lights. runtime/app/world_view.cpp feeds the game's events into a Feedback and reads what to
// draw (the lights as render::Light, the tint as render::MeshInstance::tint); runtime/app/hud_feedback.cpp
// draws the arcs. Fixed-size arrays: nothing here allocates.
#include "core/math.h"
#include "game/game.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace ks::runtime::feedback {

// --- Damage direction -------------------------------------------------------------------------------------

inline constexpr float kDamageArcSeconds = 1.0f;

// Where damage from `source` shows on the ring round the crosshair for a player whose eye is at `eye` with
// view `yaw` (0 faces -z, positive turns left): radians clockwise from straight up, so 0 is ahead, -π/2 the
// left, +π/2 the right and ±π behind. Nothing when the source is at the player or straight above or below.
std::optional<float> damage_arc_angle(float yaw, const Vec3& eye, const Vec3& source);

// An arc's opacity `age` seconds after the hit: 1, fading out (ease-out) to 0 at kDamageArcSeconds.
float damage_arc_strength(float age);

struct DamageArc {
    float angle = 0.0f;    // damage_arc_angle
    float strength = 0.0f; // damage_arc_strength
};

// --- Camera shake -----------------------------------------------------------------------------------------

inline constexpr float kShakeSeconds = 0.5f;
inline constexpr float kShakeMaxRadians = 0.035f; // about 2°, at strength 1
inline constexpr float kRobotDeathShakeRadius = 2.0f;

// How hard an explosion of blast `radius` shakes a camera `distance` away: 1 for the main level's gas
// cylinder (radius 7) at its centre, falling with the square of distance to 0 at 4 radii + 6; robot
// deaths (radius 0) shake like a radius-2 blast: a little, and only close by.
float shake_strength(float distance, float radius);

// 1 at the blast, easing to 0 at kShakeSeconds and after.
float shake_envelope(float age);

struct ShakeAngles {
    float yaw = 0.0f, pitch = 0.0f, roll = 0.0f; // radians, added to the view camera
};

// A smooth, deterministic shake: each axis a sum of two sines whose frequencies (7-23 Hz) and phases come
// from `seed`, scaled by `strength` and the envelope at `age`.
ShakeAngles shake_offset(std::uint32_t seed, float age, float strength);

// --- Robot hit flash --------------------------------------------------------------------------------------

// The red light a robot gives off (render::MeshInstance::tint) with `flash_left` seconds of its hit flash
// (game::Robot::hit_flash) left: full red at the hit, fading with the square to nothing after 1 s.
Vec3 hit_tint(float flash_left);

// --- Muzzle-flash light -----------------------------------------------------------------------------------

inline constexpr float kMuzzleLightSeconds = 0.06f;

// A muzzle light's brightness `age` seconds after the shot: full, falling linearly to 0 at 60 ms.
float muzzle_light_intensity(float age);

// A muzzle flash's point light: the renderer's render::Light of type Point, dynamic (not in the light map).
struct MuzzleLight {
    Vec3 position{0.0f};
    Vec3 color{0.0f};
    float intensity = 0.0f;
    float range = 0.0f;
};
// The point light of a shot at `position` (the rifle tip, or a robot's hand tip: redder, shorter reach).
MuzzleLight muzzle_light(const Vec3& position, float age, bool robot);

// --- The running effects ----------------------------------------------------------------------------------

class Feedback {
  public:
    static constexpr std::size_t kMaxArcs = 8, kMaxShakes = 8, kMaxLights = 12;

    // Ages every effect by `dt` seconds and drops the finished ones. Call once per game step, before
    // on_event for that step's events.
    void update(float dt);

    // Takes one game event; `eye` is the player's eye now (how far an explosion is).
    void on_event(const game::Event& e, const Vec3& eye);

    // The live arcs for a player at `eye` looking along `yaw` (updated as they turn and move): written to
    // `out`, returns how many.
    std::size_t damage_arcs(float yaw, const Vec3& eye, std::array<DamageArc, kMaxArcs>& out) const;

    // The sum of the live shakes, `extra` seconds after the last update (the frame's interpolation).
    ShakeAngles shake(float extra = 0.0f) const;

    // The live muzzle lights `extra` seconds after the last update, oldest shot first: written to `out`,
    // returns how many (the world view puts them first in the frame's lights).
    std::size_t muzzle_lights(std::array<MuzzleLight, kMaxLights>& out, float extra = 0.0f) const;

    std::size_t live_arcs() const { return arc_count_; }
    std::size_t live_shakes() const { return shake_count_; }
    std::size_t live_lights() const { return light_count_; }
    void clear() { arc_count_ = shake_count_ = light_count_ = 0; }

  private:
    struct Arc {
        Vec3 source{0.0f};
        float age = 0.0f;
    };
    struct Shake {
        std::uint32_t seed = 0;
        float strength = 0.0f;
        float age = 0.0f;
    };
    struct Flash {
        Vec3 position{0.0f};
        bool robot = false;
        float age = 0.0f;
    };

    // A hit from (nearly) the same direction as a live arc renews that arc instead of stacking a second.
    void add_arc(const Vec3& source, const Vec3& eye);

    std::array<Arc, kMaxArcs> arcs_{};
    std::array<Shake, kMaxShakes> shakes_{};
    std::array<Flash, kMaxLights> lights_{};
    std::size_t arc_count_ = 0, shake_count_ = 0, light_count_ = 0;
    std::uint32_t next_seed_ = 1;
};

} // namespace ks::runtime::feedback
