// The character controller on brushes, unchanged: up a brush ramp (26.565°), against a brush wall and up
// brush stairs, each at 30/60/120/240 Hz and compared step by step with the same scene built from boxes and
// the stair wedge (same heights within 1e-3 units).
#include "physics_scene.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

namespace {

using SceneBuilder = std::function<void(World&)>;

struct Trajectory {
    std::vector<Vec3> positions;
    std::vector<bool> grounded;
};

// Walks the player from `feet` at `velocity` for `seconds` in the scene, recording every step.
Trajectory walk_through(int hz, const SceneBuilder& build, Vec3 feet, Vec3 velocity, float seconds) {
    World w(at_rate(hz));
    add_floor(w);
    build(w);
    BodyId p = add_player(w, feet);
    w.step(1.0f / hz);
    Trajectory t;
    for (int i = 0; i < static_cast<int>(std::lround(seconds * hz)); ++i) {
        auto& m = w.character(p).movement;
        m.velocity.x = velocity.x;
        m.velocity.z = velocity.z;
        w.step(1.0f / hz);
        t.positions.push_back(w.transform(p).position);
        t.grounded.push_back(w.character(p).grounded);
    }
    return t;
}

float largest_difference(const Trajectory& a, const Trajectory& b) {
    REQUIRE(a.positions.size() == b.positions.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.positions.size(); ++i)
        worst = std::max(worst, glm::length(a.positions[i] - b.positions[i]));
    return worst;
}

// The main level's stair ramp (a wedge of half size (6, 3, 6) at (-4, 3, -72), rising toward -z) as a
// triangular prism brush, and the platform behind it as a box brush.
void add_brush_stairs(World& w) {
    const std::vector<DVec3> profile = {{-10, 0, -66}, {-10, 0, -78}, {-10, 6, -78}};
    auto ramp = brush::make_extrusion(profile, {12, 0, 0});
    REQUIRE(ramp.ok());
    add_brush(w, *ramp);
    add_brush(w, box_brush({-4, 3, -90}, {12, 3, 12}));
}

} // namespace

TEST_CASE("brush ramp: the 26.565° slope is walked up and down as on the stair wedge") {
    auto ramp = brush::make_extrusion(std::vector<DVec3>{{-10, 0, -66}, {-10, 0, -78}, {-10, 6, -78}},
                                      DVec3(12, 0, 0));
    REQUIRE(ramp.ok());
    bool found_slope = false;
    for (const auto& f : ramp->faces())
        if (f.plane.normal.y > 0.1 && f.plane.normal.y < 0.99) {
            found_slope = true;
            CHECK(degrees(std::acos(f.plane.normal.y)) == doctest::Approx(26.565).epsilon(1e-4));
        }
    CHECK(found_slope);
    for (int hz : kRates) {
        CAPTURE(hz);
        for (float dir : {-1.0f, 1.0f}) { // up the ramp, then (starting on the platform) down it
            const Vec3 feet = dir < 0 ? Vec3(-4, 0, -55) : Vec3(-4, 6, -84);
            const Trajectory on_brush = walk_through(hz, add_brush_stairs, feet, {0, 0, 15 * dir}, 2.5f);
            const Trajectory on_wedge = walk_through(hz, add_main_stairs, feet, {0, 0, 15 * dir}, 2.5f);
            const float diff = largest_difference(on_brush, on_wedge);
            MESSAGE("ramp at " << hz << " Hz, " << std::string(dir < 0 ? "up" : "down") << ": brush vs wedge "
                               << diff);
            CHECK(diff < 1e-3f);
            float prev = on_brush.positions.front().y;
            for (std::size_t i = 0; i < on_brush.positions.size(); ++i) {
                CHECK(on_brush.grounded[i]);
                CHECK(on_brush.positions[i].y * -dir >= prev * -dir - 1e-4f); // monotonic
                prev = on_brush.positions[i].y;
            }
            const float end_feet = on_brush.positions.back().y - 1.5f;
            CHECK(end_feet == doctest::Approx(dir < 0 ? 6.01f : 0.01f).epsilon(1e-3));
        }
    }
}

TEST_CASE("brush wall: the character stops at it, a radius and the skin short, as at a box wall") {
    for (int hz : kRates) {
        CAPTURE(hz);
        for (float yaw_deg : {0.0f, 30.0f}) {
            CAPTURE(yaw_deg);
            // A 0.5-thick, 16-tall wall across the path at z = -10, turned by yaw about its centre; the
            // brush is the hull of the turned box's corners.
            const Vec3 centre(0, 8, -10.25f), half(10, 8, 0.25f);
            const Quat turn = yaw(radians(yaw_deg));
            std::vector<DVec3> corners;
            for (int i = 0; i < 8; ++i)
                corners.push_back(DVec3(centre) +
                                  DVec3(turn * Vec3((i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y,
                                                    (i & 4) ? half.z : -half.z)));
            auto wall = brush::make_from_points(corners);
            REQUIRE(wall.ok());
            const Trajectory on_brush = walk_through(
                hz, [&](World& w) { add_brush(w, *wall); }, {0, 0, 0}, {0, 0, -15}, 2.0f);
            const Trajectory on_box = walk_through(
                hz, [&](World& w) { add_box(w, centre, half, radians(yaw_deg)); }, {0, 0, 0}, {0, 0, -15},
                2.0f);
            const float diff = largest_difference(on_brush, on_box);
            MESSAGE("wall at " << hz << " Hz, yaw " << yaw_deg << ": brush vs box " << diff);
            CHECK(diff < 1e-3f);
            const Vec3 end = on_brush.positions.back();
            // Resting against the wall's face: its distance to the face plane is the radius plus the skin.
            const Vec3 normal = turn * Vec3(0, 0, 1);
            const float gap = glm::dot(end - (centre + normal * half.z), normal);
            if (yaw_deg == 0.0f) CHECK(gap == doctest::Approx(1.01f).epsilon(1e-3));
            CHECK(gap >= 1.0f);
            CHECK(gap < 1.02f);
            CHECK(on_brush.grounded.back());
        }
    }
}

TEST_CASE("brush stairs: 0.6-unit brush steps are climbed by the step height, as box steps are") {
    const auto steps = [](bool brushes) {
        return [brushes](World& w) {
            for (int s = 0; s < 10; ++s) {
                const Vec3 centre(0, 0.3f * (s + 1), -1.2f * s - 0.6f - 6.0f), half(6, 0.3f * (s + 1), 0.6f);
                brushes ? static_cast<void>(add_brush(w, box_brush(centre, half)))
                        : static_cast<void>(add_box(w, centre, half));
            }
            brushes ? static_cast<void>(add_brush(w, box_brush({0, 3, -30}, {6, 3, 12})))
                    : static_cast<void>(add_box(w, {0, 3, -30}, {6, 3, 12}));
        };
    };
    for (int hz : kRates) {
        CAPTURE(hz);
        const Trajectory on_brush = walk_through(hz, steps(true), {0, 0, 0}, {0, 0, -15}, 2.0f);
        const Trajectory on_box = walk_through(hz, steps(false), {0, 0, 0}, {0, 0, -15}, 2.0f);
        const float diff = largest_difference(on_brush, on_box);
        MESSAGE("stairs at " << hz << " Hz: brush vs box " << diff);
        CHECK(diff < 1e-3f);
        CHECK(on_brush.positions.back().y - 1.5f == doctest::Approx(6.01f).epsilon(1e-3));
        CHECK(on_brush.positions.back().z < -20.0f);
    }
}
