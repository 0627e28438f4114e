// The editor's entity boxes and walkable surfaces follow the level conventions (the box maths itself is
// tested in tests/geometry/test_obb.cpp).
#include "brush/brush_build.h"
#include "level/entity_shapes.h"
#include "model/bounds.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::editor;

TEST_CASE("entity boxes follow the level conventions (bottom-centre positions, floors below the surface)") {
    level::Entity wall;
    wall.props = level::WallProps{};
    wall.position = {0, 0, -30};
    wall.rotation = {90, 0, 0};
    auto b = entity_obb(wall).aabb();
    CHECK(b.min.y == doctest::Approx(0));
    CHECK(b.max.y == doctest::Approx(16));
    CHECK(b.min.z == doctest::Approx(-35)); // 10 wide along local x, turned onto z
    CHECK(b.max.x == doctest::Approx(0.25));

    level::Entity floor;
    floor.props = level::FloorProps{};
    floor.position = {0, 6, 0};
    auto f = entity_obb(floor).aabb();
    CHECK(f.max.y == doctest::Approx(6));
    CHECK(f.min.y == doctest::Approx(5.5));
    CHECK(surface_height_at(floor, 9.9f, -9.9f) == doctest::Approx(6));
    CHECK_FALSE(surface_height_at(floor, 10.1f, 0).has_value());

    // Stairs rise toward local -z in `steps` treads: reference S1 rises from z -66 to z -78.
    level::Entity stair;
    stair.props = level::StairProps{};
    stair.position = {-4, 0, -72};
    stair.rotation = {0, 0, 0}; // as levels/main.json stores it
    CHECK(*surface_height_at(stair, -4, -66.5f) == doctest::Approx(0.6));
    CHECK(*surface_height_at(stair, -4, -77.5f) == doctest::Approx(6.0));
}

TEST_CASE("selection bounds: the box around every entity's box, empty (not valid) for none") {
    level::Entity floor;
    floor.props = level::FloorProps{};
    floor.position = {0, 6, 0};
    level::Entity wall;
    wall.props = level::WallProps{};
    wall.position = {0, 0, -30};
    wall.rotation = {90, 0, 0};
    const geometry::Aabb f = entity_obb(floor).aabb(), w = entity_obb(wall).aabb();

    const geometry::Aabb both = selection_bounds(std::vector<level::Entity>{floor, wall});
    CHECK(both.min.x == doctest::Approx(std::min(f.min.x, w.min.x)));
    CHECK(both.min.y == doctest::Approx(0));  // the wall's foot
    CHECK(both.max.y == doctest::Approx(16)); // the wall's top
    CHECK(both.min.z == doctest::Approx(-35));
    CHECK(both.max.z == doctest::Approx(f.max.z));
    const geometry::Aabb by_pointer = selection_bounds(std::vector<const level::Entity*>{&floor, &wall});
    CHECK(by_pointer.min == both.min);
    CHECK(by_pointer.max == both.max);
    const geometry::Aabb one = selection_bounds(std::vector<const level::Entity*>{&floor});
    CHECK(one.min == f.min);
    CHECK(one.max == f.max);

    CHECK_FALSE(selection_bounds(std::vector<level::Entity>{}).valid());
    CHECK_FALSE(selection_bounds(std::vector<const level::Entity*>{}).valid());
    CHECK(is_finite(selection_bounds(std::vector<level::Entity>{}).center()));
}

TEST_CASE("a brush's box turns with it, and its selection bounds are its world vertices' box") {
    level::Level level;
    level::Entity& e = level.add(level::EntityType::Brush, {10, 2, -4});
    e.rotation = {30, 20, 0};
    const DVec3 corners[] = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}}; // a tetrahedron
    e.as<level::BrushProps>().brush = brush::make_from_points(corners, {"concrete"}).value();
    const auto world = level::world_brush(e);
    REQUIRE(world.ok());
    const geometry::Obb box = entity_obb(e);
    for (const DVec3& v : world->vertices()) CHECK(box.contains(Vec3(v), 1e-4f));
    const geometry::Aabb bounds = selection_bounds(std::vector<level::Entity>{e});
    CHECK(glm::length(bounds.min - Vec3(world->bounds_min())) < 1e-5f);
    CHECK(glm::length(bounds.max - Vec3(world->bounds_max())) < 1e-5f);
    const Vec3 tight = bounds.max - bounds.min, loose = box.aabb().max - box.aabb().min;
    CHECK(tight.x + tight.y + tight.z < loose.x + loose.y + loose.z - 1.0f); // tighter than the turned box's
}
