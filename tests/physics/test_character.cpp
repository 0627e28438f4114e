// Character controller hard cases, each at 30/60/120/240 Hz: floor seams, 90° and 30° corners, the main
// level's stairs up and down at full speed, box steps, a ledge, landing at 60 m/s on a 10 cm floor, a 5 cm
// wall at 50 m/s, a whole simulated hour standing still.
#include "physics_scene.h"

#include <cmath>
#include <map>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

namespace {
void walk(World& w, BodyId p, Vec3 velocity) {
    auto& m = w.character(p).movement;
    m.velocity.x = velocity.x;
    m.velocity.z = velocity.z;
}
int steps_for(int hz, float seconds) {
    return static_cast<int>(std::lround(seconds * hz));
}
} // namespace

TEST_CASE("standing and walking on a floor seam: no vertical motion at all") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_box(w, {-50, -0.5f, 0}, {50, 0.5f, 50});
        add_box(w, {50, -0.5f, 0}, {50, 0.5f, 50});
        BodyId p = add_player(w, {0, 0, 0});
        const float y0 = w.transform(p).position.y;
        for (int i = 0; i < steps_for(hz, 1.0f); ++i) {
            w.step(1.0f / hz);
            CHECK(w.transform(p).position == Vec3(0, y0, 0));
            CHECK(w.character(p).grounded);
        }
        walk(w, p, {15, 0, 0});
        for (int i = 0; i < steps_for(hz, 1.0f); ++i) {
            w.step(1.0f / hz);
            CHECK(std::abs(w.transform(p).position.y - y0) < 1e-5f);
            CHECK(w.character(p).grounded);
        }
        CHECK(w.transform(p).position.x == doctest::Approx(15.0f).epsilon(1e-3));
    }
}

TEST_CASE("walking into a 90° corner and a 30° corner: stops without jitter or penetration") {
    for (int hz : kRates) {
        for (float corner_deg : {90.0f, 30.0f}) {
            CAPTURE(hz);
            CAPTURE(corner_deg);
            World w(at_rate(hz));
            add_floor(w);
            // Two walls meeting at the origin, symmetric about -z, `corner_deg` apart.
            const float half_angle = radians(corner_deg) * 0.5f;
            for (float side : {-1.0f, 1.0f}) {
                const float yaw = side * half_angle;
                const Vec3 along = glm::angleAxis(yaw, Vec3(0, 1, 0)) * Vec3(0, 0, -1); // vertex -> open end
                const Vec3 outward = glm::cross(along, Vec3(0, 1, 0)) * -side;
                // Inner face through the vertex at the origin; 20 long, 0.5 thick, 16 tall.
                add_box(w, along * 10.0f + outward * 0.25f + Vec3(0, 8, 0), {0.25f, 8, 10}, yaw);
            }
            // The corner opens toward -z; walking +z from z = -15 runs into it.
            BodyId p = add_player(w, {0, 0, -15});
            walk(w, p, {0, 0, 15}); // straight into the corner
            std::vector<Vec3> last;
            for (int i = 0; i < steps_for(hz, 3.0f); ++i) {
                w.step(1.0f / hz);
                last.push_back(w.transform(p).position);
            }
            // Settled: the last half second does not move (no jitter) and nothing overlaps.
            const Vec3 final = last.back();
            for (std::size_t i = last.size() - hz / 2; i < last.size(); ++i)
                CHECK(glm::length(last[i] - final) < 1e-4f);
            std::vector<BodyId> overlaps;
            const Segment s{final - Vec3(0, 0.5f, 0), final + Vec3(0, 0.5f, 0)};
            w.overlap_capsule(s, 0.999f, overlaps);
            for (BodyId o : overlaps) CHECK(o == p); // only itself
            CHECK(final.z > -15.0f);
            CHECK(std::abs(final.x) < 1e-3f); // symmetric corner: it stays on the bisector
        }
    }
}

TEST_CASE("up and down the main level's stairs (26.6° ramp) at full speed: always grounded, monotonic") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_floor(w);
        add_main_stairs(w);
        BodyId p = add_player(w, {-4, 0, -55});
        w.step(1.0f / hz);
        walk(w, p, {0, 0, -15});
        float prev = feet_y(w, p);
        for (int i = 0; i < steps_for(hz, 2.5f); ++i) {
            w.step(1.0f / hz);
            CHECK(w.character(p).grounded);
            CHECK(feet_y(w, p) >= prev - 1e-4f);
            prev = feet_y(w, p);
        }
        CHECK(feet_y(w, p) == doctest::Approx(6.0f + 0.01f).epsilon(1e-3));
        CHECK(w.transform(p).position.z < -80.0f);
        walk(w, p, {0, 0, 15});
        for (int i = 0; i < steps_for(hz, 2.5f); ++i) {
            w.step(1.0f / hz);
            CHECK(w.character(p).grounded);
            CHECK(feet_y(w, p) <= prev + 1e-4f);
            prev = feet_y(w, p);
        }
        CHECK(feet_y(w, p) == doctest::Approx(0.01f).epsilon(1e-3));
        CHECK(w.transform(p).position.z > -60.0f);
    }
}

TEST_CASE("stairs built from 0.6-unit box steps are climbed by the step height") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_floor(w);
        for (int s = 0; s < 10; ++s) // step s: top at 0.6(s+1), from z = -1.2 s onward (-z)
            add_box(w, {0, 0.3f * (s + 1), -1.2f * s - 0.6f - 6.0f}, {6, 0.3f * (s + 1), 0.6f});
        add_box(w, {0, 3, -30}, {6, 3, 12}); // landing at the top, y = 6
        BodyId p = add_player(w, {0, 0, 0});
        w.step(1.0f / hz);
        walk(w, p, {0, 0, -15});
        for (int i = 0; i < steps_for(hz, 2.0f); ++i) w.step(1.0f / hz);
        CHECK(feet_y(w, p) == doctest::Approx(6.01f).epsilon(1e-3));
        CHECK(w.transform(p).position.z < -20.0f);
    }
}

TEST_CASE("off a ledge: falls, is airborne, lands grounded on the floor below") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_floor(w);
        add_box(w, {0, 1.5f, 0}, {5, 1.5f, 5}); // a 3-unit ledge
        BodyId p = add_player(w, {0, 3, 0});
        walk(w, p, {15, 0, 0});
        bool airborne = false;
        for (int i = 0; i < steps_for(hz, 1.5f); ++i) {
            w.step(1.0f / hz);
            airborne |= !w.character(p).grounded;
        }
        CHECK(airborne);
        CHECK(w.character(p).grounded);
        CHECK(feet_y(w, p) == doctest::Approx(0.01f).epsilon(1e-3));
    }
}

TEST_CASE("landing at 60 m/s on a 10 cm floor, and a 5 cm wall at 50 m/s: nothing tunnels") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_box(w, {0, -0.05f, 0}, {20, 0.05f, 20}); // 10 cm slab, nothing under it
        add_box(w, {10, 5, 0}, {0.025f, 5, 20});     // 5 cm wall
        BodyId faller = add_player(w, {0, 40, -10});
        w.character(faller).movement.velocity = {0, -60, 0};
        BodyId runner = add_player(w, {0, 0, 5});
        for (int i = 0; i < steps_for(hz, 2.0f); ++i) {
            walk(w, runner, {50, 0, 0});
            w.step(1.0f / hz);
            CHECK(feet_y(w, faller) > -1e-3f);
            CHECK(w.transform(runner).position.x < 10.0f - 0.025f - 1.0f + 1e-3f);
        }
        CHECK(w.character(faller).grounded);
        CHECK(feet_y(w, faller) == doctest::Approx(0.01f).epsilon(1e-3));
    }
}

TEST_CASE("one simulated hour standing still drifts exactly 0 mm") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_floor(w);
        add_box(w, {3.5f, 8, 0}, {0.25f, 8, 10}); // a wall nearby, touching nothing
        BodyId p = add_player(w, {0, 0, 0});
        w.step(1.0f / hz); // settle onto the skin
        const Vec3 start = w.transform(p).position;
        const int steps = 3600 * hz;
        for (int i = 0; i < steps; ++i) w.step(1.0f / hz);
        CHECK(w.transform(p).position == start);
        CHECK(w.character(p).grounded);
    }
}

TEST_CASE("jump: apex 4.5 and 1.2 s air time at every step rate; independent of the render frame rate") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_floor(w);
        BodyId p = add_player(w, {0, 0, 0});
        w.step(1.0f / hz);
        const float y0 = feet_y(w, p);
        REQUIRE(w.jump(p, 15.0f));
        CHECK_FALSE(w.jump(p, 15.0f)); // no double jump
        float apex = y0;
        int air_steps = 0;
        while (!w.character(p).grounded && air_steps < 10 * hz) {
            w.step(1.0f / hz);
            apex = std::max(apex, feet_y(w, p));
            ++air_steps;
        }
        CHECK(apex - y0 == doctest::Approx(4.5f).epsilon(1e-4));
        CHECK(air_steps == doctest::Approx(1.2 * hz).epsilon(0.02));
    }
    // Render frames of 1/15 s and 1/240 s over the same fixed 120 Hz steps: the same trajectory, step for
    // step (compared wherever both have a frame boundary), hence the same apex and landing point.
    auto run = [](double frame) {
        World w;
        add_floor(w);
        BodyId p = add_player(w, {0, 0, 0});
        w.advance(0.05);
        REQUIRE(w.jump(p, 15.0f));
        w.character(p).movement.velocity.x = 15.0f;
        std::map<long long, Vec3> by_step;
        while (w.clock().total_steps() < 246) {
            w.advance(frame);
            by_step[w.clock().total_steps()] = w.transform(p).position;
        }
        return by_step;
    };
    const auto slow = run(1.0 / 15.0), fast = run(1.0 / 240.0);
    int compared = 0;
    float apex = 0.0f;
    for (const auto& [step, pos] : fast) apex = std::max(apex, pos.y - 1.51f);
    CHECK(apex == doctest::Approx(4.5f).epsilon(1e-4));
    for (const auto& [step, pos] : slow)
        if (auto it = fast.find(step); it != fast.end()) {
            CHECK(glm::length(pos - it->second) < 1e-3f);
            ++compared;
        }
    CHECK(compared >= 30);
    CHECK(fast.rbegin()->second.x == doctest::Approx(slow.rbegin()->second.x));
}

TEST_CASE("frame time extremes: dt = 0, dt = 1e-6, dt = 1 s, NaN velocity") {
    World w;
    add_floor(w);
    BodyId p = add_player(w, {0, 10, 0});
    const Vec3 start = w.transform(p).position;
    w.advance(0.0);
    w.step(0.0f);
    w.step(NAN);
    w.advance(-1.0);
    CHECK(w.transform(p).position == start);
    for (int i = 0; i < 1000; ++i) w.advance(1e-6); // accumulates; no step yet (1 ms < 8.3 ms)
    CHECK(w.transform(p).position == start);
    w.advance(1.0); // a one-second hitch: 120 sub-steps, never skipped, never exploding
    CHECK(w.clock().total_steps() == 120);
    CHECK(w.character(p).grounded);
    CHECK(feet_y(w, p) == doctest::Approx(0.01f).epsilon(1e-3));
    w.character(p).movement.velocity = {NAN, INFINITY, 0};
    w.advance(0.1);
    CHECK(is_finite(w.transform(p).position));
    CHECK(is_finite(w.character(p).movement.velocity));
}

TEST_CASE("the contacts a step reports are the exact contacts where the character ended, on floors of every "
          "kind") {
    // The report reuses the ground probe's own contact when the probe hit at once; it must be the very
    // contact a fresh query at the final position gives (a floor level, turned about y, tilted).
    struct Floor {
        const char* name;
        Quat rotation;
    };
    for (const Floor& floor : {Floor{"level", Quat(1, 0, 0, 0)}, Floor{"turned", yaw(0.6f)},
                               Floor{"tilted", glm::angleAxis(0.2f, glm::normalize(Vec3(1, 0, 0.3f)))}})
        for (int hz : {60, 240}) {
            CAPTURE(floor.name);
            CAPTURE(hz);
            World w(at_rate(hz));
            BodyDesc d;
            d.shape = Shape::box({60, 0.5f, 60});
            d.transform.position = {0, -0.5f, 0};
            d.transform.rotation = floor.rotation;
            const auto added = w.add(d, "floor");
            REQUIRE(added.ok());
            const BodyId ground = *added;
            const BodyId p = add_player(w, {0, 8, 0});
            int checked = 0;
            for (int i = 0; i < steps_for(hz, 2.0f); ++i) {
                if (i == steps_for(hz, 1.0f)) walk(w, p, {9, 0, 4});
                w.step(1.0f / hz);
                const Vec3 centre = w.transform(p).position;
                const Segment core{centre - Vec3(0, kPlayerHalfSegment, 0),
                                   centre + Vec3(0, kPlayerHalfSegment, 0)};
                for (const Collision& c : w.collisions()) {
                    if (c.self != p || c.other != ground) continue;
                    const auto fresh =
                        collide_capsule_shape(core, kPlayerRadius, w.shape(ground), w.transform(ground),
                                              4.0f * CharacterSettings{}.skin);
                    REQUIRE(fresh);
                    CHECK(c.normal == fresh->normal);
                    CHECK(c.point == fresh->point);
                    CHECK(c.penetration == std::max(0.0f, fresh->penetration));
                    ++checked;
                }
            }
            CHECK(checked > steps_for(hz, 1.0f)); // landed and standing, then walking on it
        }
    // Walking down 0.3-unit steps: the probe snaps down onto each (a hit after t = 0, not reused).
    for (int hz : {60, 240}) {
        CAPTURE(hz);
        World w(at_rate(hz));
        std::vector<BodyId> steps;
        for (int k = 0; k < 8; ++k)
            steps.push_back(add_box(w, {k * 2.0f, -0.5f - 0.3f * k, 0}, {1, 0.5f, 4}));
        const BodyId p = add_player(w, {0, 0.01f, 0});
        walk(w, p, {6, 0, 0});
        int checked = 0;
        for (int i = 0; i < steps_for(hz, 2.0f); ++i) {
            w.step(1.0f / hz);
            const Vec3 centre = w.transform(p).position;
            const Segment core{centre - Vec3(0, kPlayerHalfSegment, 0),
                               centre + Vec3(0, kPlayerHalfSegment, 0)};
            for (const Collision& c : w.collisions()) {
                if (c.self != p) continue;
                const auto fresh =
                    collide_capsule_shape(core, kPlayerRadius, w.shape(c.other), w.transform(c.other),
                                          4.0f * CharacterSettings{}.skin);
                if (!fresh) continue; // touched on the way, left behind
                CHECK(c.normal == fresh->normal);
                CHECK(c.point == fresh->point);
                CHECK(c.penetration == std::max(0.0f, fresh->penetration));
                ++checked;
            }
        }
        CHECK(feet_y(w, p) < -1.5f); // went down the steps
        CHECK(checked > steps_for(hz, 1.5f));
    }
}
