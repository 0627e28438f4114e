#pragma once
// Small scene builders for the physics tests: boxes, brushes, the main level's stairs, the player capsule.
#include "brush/brush_build.h"
#include "physics/brush_shape.h"
#include "physics/world.h"

#include <doctest/doctest.h>

namespace ks::physics_test {
using namespace ks::physics;

inline constexpr float kPlayerRadius = 1.0f, kPlayerHalfSegment = 0.5f; // radius 1, height 3
inline constexpr int kRates[] = {30, 60, 120, 240};

inline BodyId add_box(World& w, Vec3 centre, Vec3 half, float yaw = 0.0f) {
    BodyDesc d;
    d.shape = Shape::box(half);
    d.transform = {centre, glm::angleAxis(yaw, Vec3(0, 1, 0))};
    auto id = w.add(d, "test box");
    REQUIRE(id.ok());
    return *id;
}

// A static brush body (physics/brush_shape.h).
inline BodyId add_brush(World& w, const brush::Brush& b) {
    const BrushBody body = brush_body(b);
    BodyDesc d;
    d.shape = body.shape;
    d.transform = body.transform;
    auto id = w.add(d, "test brush");
    REQUIRE(id.ok());
    return *id;
}

// The box brush of centre and half extents (what add_box places, as planes).
inline brush::Brush box_brush(Vec3 centre, Vec3 half) {
    auto b = brush::make_box(DVec3(centre) - DVec3(half), DVec3(centre) + DVec3(half));
    REQUIRE(b.ok());
    return std::move(*b);
}

inline BodyId add_floor(World& w, float top = 0.0f, float half_size = 200.0f) {
    return add_box(w, {0, top - 0.5f, 0}, {half_size, 0.5f, half_size});
}

// Feet position in, capsule centre = feet + 1.5 (plus the skin it rests on).
inline BodyId add_player(World& w, Vec3 feet, CharacterSettings cs = {}) {
    BodyDesc d;
    d.shape = Shape::capsule(kPlayerRadius, kPlayerHalfSegment);
    d.transform.position = feet + Vec3(0, 1.5f + cs.skin, 0);
    d.motion = Motion::Character;
    d.character = cs;
    d.movement.max_speed = 1000.0f;
    auto id = w.add(d, "player");
    REQUIRE(id.ok());
    return *id;
}

inline float feet_y(const World& w, BodyId id) {
    return w.transform(id).position.y - 1.5f;
}

// The main level's staircase S1: a 12x6x12 ramp at (-4, 0, -72) rising toward -z onto a platform of top 6.
inline void add_main_stairs(World& w) {
    BodyDesc d;
    d.shape = Shape::wedge({6, 3, 6});
    d.transform = {{-4, 3, -72}, Quat(1, 0, 0, 0)};
    REQUIRE(w.add(d, "stairs S1").ok());
    add_box(w, {-4, 3, -90}, {12, 3, 12}); // platform F3, top at y = 6, from z = -78 on
}

inline WorldSettings at_rate(int hz) {
    WorldSettings s;
    s.step = 1.0 / hz;
    return s;
}

// A rotation by `radians` about +y.
inline Quat yaw(float radians) {
    return glm::angleAxis(radians, Vec3(0, 1, 0));
}

} // namespace ks::physics_test
