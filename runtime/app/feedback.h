#pragma once
// The game's hit and impact feedback as plain logic, without GL or ImGui: the red damage-direction arcs
// round the crosshair, camera shake from explosions, the red flash of a hit robot and the short-lived
// muzzle-flash lights. WorldView feeds the game's events into a Feedback and reads what to draw; the app
// draws the arcs (screens.cpp). Header-only so that tests/runtime/test_feedback.cpp checks it without a
// window. Fixed-size arrays: nothing here allocates.
#include "core/math.h"
#include "game/game.h"
#include "render/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace ks::runtime::feedback {

// --- Damage direction -------------------------------------------------------------------------------------

inline constexpr float kDamageArcSeconds = 1.0f;

// Where damage from `source` shows on the ring round the crosshair for a player whose eye is at `eye` with
// view `yaw` (0 faces -z, positive turns left): radians clockwise from straight up, so 0 is ahead, -π/2 the
// left, +π/2 the right and ±π behind. Nothing when the source is at the player or straight above or below.
inline std::optional<float> damage_arc_angle(float yaw, const Vec3& eye, const Vec3& source) {
    const Vec3 d = source - eye;
    const Vec3 forward(-std::sin(yaw), 0.0f, -std::cos(yaw));
    const Vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw));
    const float ahead = glm::dot(d, forward), aside = glm::dot(d, right);
    if (!is_finite(ahead) || !is_finite(aside) || ahead * ahead + aside * aside < 1e-4f) return std::nullopt;
    return std::atan2(aside, ahead);
}

// An arc's opacity `age` seconds after the hit: 1, fading out (ease-out) to 0 at kDamageArcSeconds.
inline float damage_arc_strength(float age) {
    if (!(age >= 0.0f) || age >= kDamageArcSeconds) return 0.0f;
    const float k = 1.0f - age / kDamageArcSeconds;
    return k * (1.5f - 0.5f * k); // slower than linear at first, so a hit reads for most of the second
}

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
inline float shake_strength(float distance, float radius) {
    if (!is_finite(distance) || !is_finite(radius)) return 0.0f;
    const float r = radius > 0.0f ? std::min(radius, 50.0f) : kRobotDeathShakeRadius;
    const float size = std::clamp(r / 7.0f, 0.3f, 1.5f);
    const float falloff = std::clamp(1.0f - std::max(distance, 0.0f) / (4.0f * r + 6.0f), 0.0f, 1.0f);
    return size * falloff * falloff;
}

// 1 at the blast, easing to 0 at kShakeSeconds and after.
inline float shake_envelope(float age) {
    if (!(age >= 0.0f) || age >= kShakeSeconds) return 0.0f;
    const float k = 1.0f - age / kShakeSeconds;
    return k * k;
}

struct ShakeAngles {
    float yaw = 0.0f, pitch = 0.0f, roll = 0.0f; // radians, added to the view camera
};

// A smooth, deterministic shake: each axis a sum of two sines whose frequencies (7-23 Hz) and phases come
// from `seed`, scaled by `strength` and the envelope at `age`.
inline ShakeAngles shake_offset(std::uint32_t seed, float age, float strength) {
    const float a = kShakeMaxRadians * std::clamp(strength, 0.0f, 2.0f) * shake_envelope(age);
    if (!(a > 0.0f)) return {};
    std::uint32_t state = seed * 2654435761u + 0x9e3779b9u;
    auto next = [&state] { // xorshift32: a fraction in [0, 1)
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    auto wave = [&](float low_hz, float high_hz) {
        const float f1 = low_hz * (0.85f + 0.3f * next()), f2 = high_hz * (0.85f + 0.3f * next());
        const float p1 = 2.0f * kPi * next(), p2 = 2.0f * kPi * next();
        return 0.65f * std::sin(2.0f * kPi * f1 * age + p1) + 0.35f * std::sin(2.0f * kPi * f2 * age + p2);
    };
    ShakeAngles s;
    s.yaw = a * wave(11.0f, 19.0f);
    s.pitch = a * wave(13.0f, 23.0f);
    s.roll = 0.5f * a * wave(7.0f, 17.0f);
    return s;
}

// --- Robot hit flash --------------------------------------------------------------------------------------

// The red light a robot gives off (render::MeshInstance::tint) with `flash_left` seconds of its hit flash
// (game::Robot::hit_flash) left: full red at the hit, fading with the square to nothing after 1 s.
inline Vec3 hit_tint(float flash_left) {
    const float k =
        std::clamp(is_finite(flash_left) ? flash_left / game::kRobotHitFlashSeconds : 0.0f, 0.0f, 1.0f);
    return Vec3(1.0f, 0.0f, 0.0f) * (0.9f * k * k);
}

// --- Muzzle-flash light -----------------------------------------------------------------------------------

inline constexpr float kMuzzleLightSeconds = 0.06f;

// A muzzle light's brightness `age` seconds after the shot: full, falling linearly to 0 at 60 ms.
inline float muzzle_light_intensity(float age) {
    if (!(age >= 0.0f) || age >= kMuzzleLightSeconds) return 0.0f;
    return 3.0f * (1.0f - age / kMuzzleLightSeconds);
}

// The point light of a shot at `position` (the rifle tip, or a robot's hand tip: redder, shorter reach).
inline render::Light muzzle_light(const Vec3& position, float age, bool robot) {
    render::Light l;
    l.type = render::Light::Type::Point;
    l.position = position;
    l.color = robot ? Vec3(1.0f, 0.45f, 0.25f) : Vec3(1.0f, 0.72f, 0.4f);
    l.intensity = muzzle_light_intensity(age);
    l.range = robot ? 6.0f : 7.0f;
    l.dynamic = true; // not in the light map: the fast path adds it to baked walls per pixel
    return l;
}

// --- The running effects ----------------------------------------------------------------------------------

class Feedback {
  public:
    static constexpr std::size_t kMaxArcs = 8, kMaxShakes = 8, kMaxLights = 12;

    // Ages every effect by `dt` seconds and drops the finished ones. Call once per game step, before
    // on_event for that step's events.
    void update(float dt) {
        if (!(dt > 0.0f)) return;
        auto age = [dt](auto& items, std::size_t& count, float limit) {
            std::size_t kept = 0;
            for (std::size_t i = 0; i < count; ++i) {
                items[i].age += dt;
                if (items[i].age < limit) items[kept++] = items[i];
            }
            count = kept;
        };
        age(arcs_, arc_count_, kDamageArcSeconds);
        age(shakes_, shake_count_, kShakeSeconds);
        age(lights_, light_count_, kMuzzleLightSeconds);
    }

    // Takes one game event; `eye` is the player's eye now (how far an explosion is).
    void on_event(const game::Event& e, const Vec3& eye) {
        using game::EventType;
        switch (e.type) {
        case EventType::PlayerDamaged:
            // position = the source, end = the eye at the hit; the same point: no direction (a fall).
            if (glm::length(e.position - e.end) > 1e-3f) add_arc(e.position, eye);
            break;
        case EventType::Explosion: {
            const float strength = shake_strength(glm::length(e.position - eye), e.amount);
            if (strength > 0.0f)
                add(shakes_, shake_count_,
                    Shake{next_seed_++ ^ static_cast<std::uint32_t>(e.entity), strength, 0.0f});
            break;
        }
        case EventType::ShotFired:
        case EventType::RobotShot:
            add(lights_, light_count_, Flash{e.position, e.type == EventType::RobotShot, 0.0f});
            break;
        default:
            break;
        }
    }

    // The live arcs for a player at `eye` looking along `yaw` (updated as they turn and move): written to
    // `out`, returns how many.
    std::size_t damage_arcs(float yaw, const Vec3& eye, std::array<DamageArc, kMaxArcs>& out) const {
        std::size_t n = 0;
        for (std::size_t i = 0; i < arc_count_; ++i) {
            const auto angle = damage_arc_angle(yaw, eye, arcs_[i].source);
            const float strength = damage_arc_strength(arcs_[i].age);
            if (angle && strength > 0.0f) out[n++] = {*angle, strength};
        }
        return n;
    }

    // The sum of the live shakes, `extra` seconds after the last update (the frame's interpolation).
    ShakeAngles shake(float extra = 0.0f) const {
        ShakeAngles sum;
        for (std::size_t i = 0; i < shake_count_; ++i) {
            const ShakeAngles s = shake_offset(shakes_[i].seed, shakes_[i].age + extra, shakes_[i].strength);
            sum.yaw += s.yaw;
            sum.pitch += s.pitch;
            sum.roll += s.roll;
        }
        return sum;
    }

    // Puts the live muzzle lights at the front of `lights` (the renderer keeps the first lights in view when
    // there are too many). Allocates nothing once `lights` has room.
    void add_lights(std::vector<render::Light>& lights, float extra = 0.0f) const {
        std::size_t n = 0;
        for (std::size_t i = 0; i < light_count_; ++i)
            if (muzzle_light_intensity(lights_[i].age + extra) > 0.0f) ++n;
        lights.insert(lights.begin(), n, render::Light{});
        std::size_t k = 0;
        for (std::size_t i = 0; i < light_count_; ++i)
            if (muzzle_light_intensity(lights_[i].age + extra) > 0.0f)
                lights[k++] = muzzle_light(lights_[i].position, lights_[i].age + extra, lights_[i].robot);
    }

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

    // Appends `item`, or replaces the oldest when full.
    template <class T, std::size_t N>
    static void add(std::array<T, N>& items, std::size_t& count, const T& item) {
        if (count < N) {
            items[count++] = item;
            return;
        }
        auto oldest = std::max_element(items.begin(), items.end(),
                                       [](const T& a, const T& b) { return a.age < b.age; });
        *oldest = item;
    }

    // A hit from (nearly) the same direction as a live arc renews that arc instead of stacking a second.
    void add_arc(const Vec3& source, const Vec3& eye) {
        const auto bearing = damage_arc_angle(0.0f, eye, source);
        if (!bearing) return;
        for (std::size_t i = 0; i < arc_count_; ++i) {
            const auto other = damage_arc_angle(0.0f, eye, arcs_[i].source);
            if (other && std::abs(std::remainder(*other - *bearing, 2.0f * kPi)) < 0.25f) {
                arcs_[i] = {source, 0.0f};
                return;
            }
        }
        add(arcs_, arc_count_, Arc{source, 0.0f});
    }

    std::array<Arc, kMaxArcs> arcs_{};
    std::array<Shake, kMaxShakes> shakes_{};
    std::array<Flash, kMaxLights> lights_{};
    std::size_t arc_count_ = 0, shake_count_ = 0, light_count_ = 0;
    std::uint32_t next_seed_ = 1;
};

} // namespace ks::runtime::feedback
