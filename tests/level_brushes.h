#pragma once
// Brush entities for the suites that build levels by hand (game, navigation, editor): one way to place a
// brush, and the ramp the shipped stair's size makes.
#include "brush/brush.h"
#include "level/level.h"

#include <doctest/doctest.h>

#include <utility>
#include <vector>

namespace ks::test {

// A brush entity at `position`, turned `yaw_degrees` about y, whose faces are `b` in the entity's frame.
inline level::Entity& place_brush(level::Level& lv, Vec3 position, float yaw_degrees, const brush::Brush& b) {
    level::Entity& e = lv.add(level::EntityType::Brush, position, "brush");
    e.rotation.x = yaw_degrees;
    e.as<level::BrushProps>().brush = b;
    return e;
}

// 12 wide and 12 long, rising from y = 0 at local z = 6 to y = 6 at local z = -6 (26.6 degrees: the shipped
// stair's size); concrete sides, a tiled slope.
inline brush::Brush stair_ramp() {
    std::vector<brush::Face> faces;
    for (const auto& [n, d] : std::vector<std::pair<DVec3, double>>{
             {{-1, 0, 0}, 6}, {{1, 0, 0}, 6}, {{0, -1, 0}, 0}, {{0, 0, -1}, 6}})
        faces.push_back({{n, d}, {"concrete"}});
    const DVec3 slope = glm::normalize(DVec3(0, 2, 1));
    faces.push_back({{slope, 3.0 * slope.y}, {"tiles"}}); // 2y + z = 6
    auto ramp = brush::Brush::from_faces(faces);
    REQUIRE(ramp.ok());
    return std::move(*ramp);
}

} // namespace ks::test
