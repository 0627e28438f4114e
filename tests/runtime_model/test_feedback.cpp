// The game's hit feedback (runtime/model/feedback.h) without a window: damage arcs point where the damage
// came from as the player turns and fade in 1 s, explosions shake the view less with distance and not at all
// after 0.5 s, a hit robot is red and then not, a shot lights its surroundings for a few steps. The particles
// and the game itself are tests/runtime/test_play_feedback.cpp's.
#include "game/game_test_levels.h"
#include "runtime/model/feedback.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace ks;
using namespace ks::runtime;
using namespace ks::runtime::feedback;

namespace {
constexpr float kStep = 1.0f / 120.0f;

game::Event damaged_from(const Vec3& source, const Vec3& eye) {
    game::Event e;
    e.type = game::EventType::PlayerDamaged;
    e.position = source;
    e.end = eye;
    e.amount = 10.0f;
    return e;
}

game::Event event_at(game::EventType type, const Vec3& position, float amount = 0.0f, int entity = -1) {
    game::Event e;
    e.type = type;
    e.position = position;
    e.amount = amount;
    e.entity = entity;
    return e;
}

std::size_t arcs_now(const Feedback& f, float yaw, std::array<DamageArc, Feedback::kMaxArcs>& out) {
    return f.damage_arcs(yaw, Vec3(0.0f, 3.0f, 0.0f), out);
}

// The largest shake angle over the first `seconds` of one explosion.
float peak_shake(float distance, float radius, float from = 0.0f, float seconds = 0.1f) {
    float peak = 0.0f;
    for (float t = from; t < from + seconds; t += 0.001f) {
        const ShakeAngles s = shake_offset(7, t, shake_strength(distance, radius));
        peak = std::max({peak, std::abs(s.yaw), std::abs(s.pitch), std::abs(s.roll)});
    }
    return peak;
}
} // namespace

TEST_CASE("damage arcs: a source to the left shows on the left, and follows the view as the player turns") {
    const Vec3 eye(0.0f, 3.0f, 0.0f);
    // Yaw 0 faces -z: -x is the left, +x the right, +z behind.
    CHECK(*damage_arc_angle(0.0f, eye, Vec3(-5, 2, 0)) == doctest::Approx(-kPi / 2));
    CHECK(*damage_arc_angle(0.0f, eye, Vec3(5, 3, 0)) == doctest::Approx(kPi / 2));
    CHECK(*damage_arc_angle(0.0f, eye, Vec3(0, 3, -5)) == doctest::Approx(0.0f));
    CHECK(std::abs(*damage_arc_angle(0.0f, eye, Vec3(0, 3, 5))) == doctest::Approx(kPi));
    // Turned left a quarter (facing -x), the same source is straight ahead; turned right, behind.
    CHECK(*damage_arc_angle(kPi / 2, eye, Vec3(-5, 2, 0)) == doctest::Approx(0.0f).epsilon(1e-5));
    CHECK(std::abs(*damage_arc_angle(-kPi / 2, eye, Vec3(-5, 2, 0))) == doctest::Approx(kPi));
    CHECK_FALSE(damage_arc_angle(0.0f, eye, eye + Vec3(0, 4, 0))); // straight above: no direction
    CHECK_FALSE(damage_arc_angle(0.0f, eye, Vec3(NAN, 0, 0)));

    Feedback f;
    std::array<DamageArc, Feedback::kMaxArcs> arcs;
    f.on_event(damaged_from(Vec3(-6, 2, 0), eye), eye);
    REQUIRE(arcs_now(f, 0.0f, arcs) == 1);
    CHECK(arcs[0].angle == doctest::Approx(-kPi / 2));
    CHECK(arcs[0].strength == doctest::Approx(1.0f));
    REQUIRE(arcs_now(f, kPi / 2, arcs) == 1); // the player turns toward it
    CHECK(arcs[0].angle == doctest::Approx(0.0f).epsilon(1e-5));
}

TEST_CASE("damage arcs fade over 1 s; several sources show several arcs; a fall shows none") {
    const Vec3 eye(0.0f, 3.0f, 0.0f);
    Feedback f;
    std::array<DamageArc, Feedback::kMaxArcs> arcs;
    f.on_event(damaged_from(Vec3(-6, 2, 0), eye), eye);    // left
    f.on_event(damaged_from(Vec3(6, 2, 1), eye), eye);     // right
    f.on_event(damaged_from(Vec3(0, 2, 9), eye), eye);     // behind
    f.on_event(damaged_from(Vec3(-7, 2, 0.5f), eye), eye); // left again: renews the left arc
    REQUIRE(arcs_now(f, 0.0f, arcs) == 3);
    int left = 0, right = 0, behind = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        left += arcs[i].angle < -1.0f && arcs[i].angle > -2.0f ? 1 : 0;
        right += arcs[i].angle > 1.0f && arcs[i].angle < 2.0f ? 1 : 0;
        behind += std::abs(arcs[i].angle) > 3.0f ? 1 : 0;
    }
    CHECK(left == 1);
    CHECK(right == 1);
    CHECK(behind == 1);
    for (int i = 0; i < 60; ++i) f.update(kStep);
    REQUIRE(arcs_now(f, 0.0f, arcs) == 3);
    CHECK(arcs[0].strength < 0.9f);
    CHECK(arcs[0].strength > 0.3f);
    for (int i = 0; i < 61; ++i) f.update(kStep);
    CHECK(arcs_now(f, 0.0f, arcs) == 0);
    CHECK(f.live_arcs() == 0);
    CHECK(damage_arc_strength(0.0f) == 1.0f);
    CHECK(damage_arc_strength(kDamageArcSeconds) == 0.0f);

    f.on_event(damaged_from(eye, eye), eye); // no source (a fall)
    CHECK(f.live_arcs() == 0);
}

TEST_CASE("camera shake: weaker with distance, a little for a robot's death close by, gone after 0.5 s") {
    CHECK(shake_strength(0.0f, 7.0f) == doctest::Approx(1.0f));
    CHECK(shake_strength(5.0f, 7.0f) > shake_strength(15.0f, 7.0f));
    CHECK(shake_strength(15.0f, 7.0f) > shake_strength(25.0f, 7.0f));
    CHECK(shake_strength(25.0f, 7.0f) > 0.0f);
    CHECK(shake_strength(40.0f, 7.0f) == 0.0f);
    CHECK(shake_strength(3.0f, 0.0f) > 0.0f); // robot deaths (radius 0) still shake close by ...
    CHECK(shake_strength(3.0f, 0.0f) < 0.5f * shake_strength(3.0f, 7.0f)); // ... less ...
    CHECK(shake_strength(20.0f, 0.0f) == 0.0f);                            // ... and not far away
    CHECK(shake_strength(NAN, 7.0f) == 0.0f);

    CHECK(peak_shake(5.0f, 7.0f) > 1.5f * peak_shake(15.0f, 7.0f));
    CHECK(peak_shake(5.0f, 7.0f) < 2.0f * kShakeMaxRadians);
    CHECK(peak_shake(5.0f, 7.0f, 0.3f) < 0.5f * peak_shake(5.0f, 7.0f)); // decaying
    CHECK(peak_shake(0.0f, 7.0f, kShakeSeconds, 1.0f) == 0.0f);          // over
    // Deterministic and smooth: the same seed gives the same angles; 1 ms apart they barely move.
    const ShakeAngles a = shake_offset(3, 0.05f, 1.0f), b = shake_offset(3, 0.05f, 1.0f);
    CHECK(a.yaw == b.yaw);
    CHECK(shake_offset(4, 0.05f, 1.0f).yaw != a.yaw);
    for (float t = 0.0f; t < kShakeSeconds; t += 0.001f) {
        const ShakeAngles p = shake_offset(3, t, 1.0f), q = shake_offset(3, t + 0.001f, 1.0f);
        CHECK(std::abs(q.yaw - p.yaw) < 0.1f * kShakeMaxRadians * 2.0f);
        CHECK(std::abs(q.pitch - p.pitch) < 0.1f * kShakeMaxRadians * 2.0f);
    }

    Feedback f;
    const Vec3 eye(0.0f, 3.0f, 0.0f);
    f.on_event(event_at(game::EventType::Explosion, Vec3(0, 1, -6), 7.0f, 50), eye);
    f.on_event(event_at(game::EventType::Explosion, Vec3(0, 1, -200), 7.0f, 51), eye); // too far: nothing
    CHECK(f.live_shakes() == 1);
    float moved = 0.0f;
    for (int i = 0; i < 12; ++i) {
        f.update(kStep);
        moved = std::max(moved, std::abs(f.shake().pitch) + std::abs(f.shake().yaw));
    }
    CHECK(moved > 0.005f);
    for (int i = 0; i < 60; ++i) f.update(kStep);
    CHECK(f.live_shakes() == 0);
    CHECK(f.shake().yaw == 0.0f);
    CHECK(f.shake().roll == 0.0f);
}

TEST_CASE("a hit robot is tinted red at the hit, less after half a second, and not at all after 1 s") {
    const Vec3 full = hit_tint(game::kRobotHitFlashSeconds);
    CHECK(full.r > 0.8f);
    CHECK(full.g == 0.0f);
    CHECK(full.b == 0.0f);
    CHECK(hit_tint(0.5f).r < 0.5f * full.r);
    CHECK(hit_tint(0.5f).r > 0.0f);
    CHECK(hit_tint(0.0f) == Vec3(0.0f));
    CHECK(hit_tint(NAN) == Vec3(0.0f));
    // Through the game: the robot's own hit flash drives it.
    auto lv = game_test::flat_level();
    game_test::add_robot(lv, Vec3(0, 0, -60));
    auto g = game_test::make_game(lv);
    g->step({});
    g->damage_robot(0, 20.0f, true);
    CHECK(hit_tint(g->robots()[0].hit_flash).r > 0.8f);
    game_test::run_for(*g, 0.5);
    CHECK(hit_tint(g->robots()[0].hit_flash).r > 0.1f);
    game_test::run_for(*g, 0.5 + kStep);
    CHECK(hit_tint(g->robots()[0].hit_flash) == Vec3(0.0f));
}

TEST_CASE("a shot's muzzle light is there for a few steps, then none; warm, and redder for a robot") {
    Feedback f;
    const Vec3 eye(0.0f, 3.0f, 0.0f), tip(0.3f, 2.75f, -1.0f);
    std::array<MuzzleLight, Feedback::kMaxLights> live;
    f.update(kStep);
    f.on_event(event_at(game::EventType::ShotFired, tip), eye);
    int steps_lit = 0;
    for (int i = 0; i < 20; ++i) {
        const std::size_t n = f.muzzle_lights(live);
        CHECK(n <= 1);
        if (n == 1) {
            ++steps_lit;
            const MuzzleLight& l = live[0];
            CHECK(l.position == tip);
            CHECK(l.color.r > l.color.g);
            CHECK(l.color.g > l.color.b); // warm
            CHECK(l.intensity > 0.0f);
            CHECK(l.range > 3.0f);
        }
        f.update(kStep);
    }
    CHECK(steps_lit >= 5); // 60 ms at 120 steps/s
    CHECK(steps_lit <= 8);
    CHECK(f.live_lights() == 0);
    CHECK(muzzle_light_intensity(0.0f) > muzzle_light_intensity(0.03f));
    CHECK(muzzle_light_intensity(kMuzzleLightSeconds) == 0.0f);
    // A robot's shot lights its hand, redder; many shots at once keep at most kMaxLights.
    for (int i = 0; i < 30; ++i) f.on_event(event_at(game::EventType::RobotShot, Vec3(5, 2, 0)), eye);
    CHECK(f.muzzle_lights(live) == Feedback::kMaxLights);
    CHECK(live[0].color.g < 0.6f);
    // Later in the frame (the interpolation past the last step) a light is dimmer, and gone past 60 ms.
    CHECK(f.muzzle_lights(live, 0.03f) == Feedback::kMaxLights);
    CHECK(live[0].intensity < muzzle_light_intensity(0.0f));
    CHECK(f.muzzle_lights(live, kMuzzleLightSeconds) == 0);
}
