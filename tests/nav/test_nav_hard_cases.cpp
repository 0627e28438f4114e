// The edges of the mesh: gaps around the robot's diameter, thin walls, levels with nothing to walk on or
// bad numbers, the shipped main level, and a stress of random queries.
#include "nav/nav_levels.h"
#include "test_support.h"

#include "core/random.h"
#include "level/level_io.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace ks;
using namespace ks::test;

namespace {

constexpr float kDiameter = 2.0f * level::kRobotRadius;

// A 40 x 20 floor cut along z = 0 by a wall with one opening of `gap` starting at x = 1 + offset.
bool gap_passes(float gap, float offset, float wall_thickness = 0.5f) {
    level::Level lv;
    lv.name = "gap";
    add_floor(lv, Vec3(0), Vec2(40, 20));
    add_wall_with_gap(lv, Vec3(-20, 0, 0), Vec3(20, 0, 0), 1.0f + offset, gap, wall_thickness);
    auto mesh = nav::NavMesh::build(lv, robot_settings());
    REQUIRE(mesh.ok());
    return (*mesh)->reachable(Vec3(0, 0, 5), Vec3(0, 0, -5));
}

} // namespace

// Documented in docs/navigation.md: erosion by the radius (4 cells of 0.2) keeps a gap open when it holds at
// least 9 cell centres. Narrower than 2r never passes; 2r + one cell always passes; exactly 2r passes only
// when both jambs sit exactly on cell centres (offset 0.1 here), so the robot never plans through a gap it
// would have to touch both sides of.
TEST_CASE("gaps around the robot's diameter: under 2r closed, exactly 2r closed, 2r + one cell open") {
    const float cell = robot_settings().cell_size;
    for (float offset : {0.0f, 0.03f, 0.05f, 0.07f, 0.15f, 0.18f}) {
        CAPTURE(offset);
        CHECK_FALSE(gap_passes(kDiameter - cell, offset));
        CHECK_FALSE(gap_passes(kDiameter, offset));
        CHECK(gap_passes(kDiameter + cell, offset));
        CHECK(gap_passes(kDiameter + 2.0f * cell, offset));
    }
}

TEST_CASE("a wall 0.1 thick blocks, and so does one thinner than a cell") {
    for (float thickness : {0.1f, 0.05f}) {
        CAPTURE(thickness);
        level::Level lv;
        lv.name = "thin wall";
        add_floor(lv, Vec3(0), Vec2(20, 20));
        add_wall(lv, Vec3(-10, 0, 0.03f), Vec3(10, 0, 0.03f), thickness);
        auto mesh = nav::NavMesh::build(lv, robot_settings());
        REQUIRE(mesh.ok());
        std::vector<Vec3> path;
        CHECK((*mesh)->find_path(Vec3(0, 0, 5), Vec3(0, 0, -5), path) == nav::PathStatus::Partial);
        CHECK_FALSE((*mesh)->walkable_line(Vec3(0, 0, 5), Vec3(0, 0, -5)));
    }
}

TEST_CASE("a level with nothing to walk on is a clear error naming the level") {
    level::Level empty;
    empty.name = "Empty";
    auto none = nav::NavMesh::build(empty, robot_settings());
    REQUIRE_FALSE(none.ok());
    CHECK(none.error().message.find("'Empty'") != std::string::npos);
    CHECK(none.error().hint.find("floor") != std::string::npos);

    level::Level walls_only;
    walls_only.name = "Walls only";
    add_wall(walls_only, Vec3(0, 0, 0), Vec3(10, 0, 0));
    add_wall(walls_only, Vec3(0, 0, 5), Vec3(10, 0, 5));
    auto unwalkable = nav::NavMesh::build(walls_only, robot_settings());
    REQUIRE_FALSE(unwalkable.ok());
    CHECK(unwalkable.error().message.find("no walkable floor") != std::string::npos);
    CHECK(unwalkable.error().message.find("'Walls only'") != std::string::npos);
}

TEST_CASE("bad numbers: a NaN position names the entity; unusable settings are refused") {
    level::Level lv;
    lv.name = "nan";
    add_floor(lv, Vec3(0), Vec2(20, 20));
    auto& wall = add_wall(lv, Vec3(-5, 0, 0), Vec3(5, 0, 0));
    wall.name = "Broken wall";
    wall.position.x = std::numeric_limits<float>::quiet_NaN();
    auto mesh = nav::NavMesh::build(lv, robot_settings());
    REQUIRE_FALSE(mesh.ok());
    CHECK(mesh.error().message.find("Broken wall") != std::string::npos);
    CHECK(mesh.error().message.find(std::to_string(wall.id)) != std::string::npos);

    level::Level ok_level;
    add_floor(ok_level, Vec3(0), Vec2(20, 20));
    nav::NavSettings no_slope; // step height and slope not filled in
    auto refused = nav::NavMesh::build(ok_level, no_slope);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("slope") != std::string::npos);
}

namespace {

std::unique_ptr<nav::NavMesh> main_level_mesh(level::Level& out_level) {
    auto lv = level::load_level_file(source_dir() / "levels" / "main.json");
    REQUIRE_MESSAGE(lv.ok(), (lv.ok() ? "" : lv.error().str()));
    out_level = std::move(lv.value());
    auto mesh = nav::NavMesh::build(out_level, robot_settings());
    REQUIRE_MESSAGE(mesh.ok(), (mesh.ok() ? "" : mesh.error().str()));
    return std::move(mesh.value());
}

} // namespace

TEST_CASE(
    "the shipped main level builds and its player start reaches the control panel once the doors open") {
    level::Level lv;
    auto mesh = main_level_mesh(lv);
    CHECK(mesh->stats().tile_columns * mesh->stats().tile_rows > 1);
    const level::Entity* panel = nullptr;
    std::vector<int> doors;
    for (const level::Entity& e : lv.entities) {
        if (e.type() == level::EntityType::ControlPanel) panel = &e;
        if (e.type() == level::EntityType::Door) doors.push_back(e.id);
    }
    REQUIRE(panel != nullptr);
    REQUIRE(doors.size() == 2);
    // Beside the panel's -x face, a robot radius and a bit away.
    const float half_x = panel->as<level::ControlPanelProps>().size.x * 0.5f;
    const Vec3 beside_panel = panel->position - Vec3(half_x + level::kRobotRadius + 0.5f, 0, 0);
    const Vec3 start = lv.player_start.position;
    CHECK_FALSE(mesh->reachable(start, beside_panel)); // both doors start closed
    for (int id : doors) REQUIRE(mesh->set_door_open(id, true));
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(start, beside_panel, path) == nav::PathStatus::Found);
    CHECK(glm::length(path.back() - beside_panel) < 0.3f);
    const auto length = mesh->path_length(start, beside_panel);
    REQUIRE(length.has_value());
    CHECK(*length >= glm::length(beside_panel - start));
    CHECK_FALSE(mesh->triangles().empty());
}

TEST_CASE("1000 random queries on the main level never crash and keep their promises") {
    level::Level lv;
    auto mesh = main_level_mesh(lv);
    Rng rng(13);
    std::vector<Vec3> path;
    int found = 0;
    const auto random_point = [&] {
        return Vec3(rng.uniform(-30, 110), rng.uniform(-1, 8), rng.uniform(-110, 110));
    };
    for (int i = 0; i < 1000; ++i) {
        const Vec3 a = random_point(), b = random_point();
        if (i % 100 == 0)
            (void)mesh->set_door_open(lv.entities.front().id, i % 200 == 0); // not a door: ignored
        const nav::PathStatus status = mesh->find_path(a, b, path);
        if (status == nav::PathStatus::Found) {
            ++found;
            REQUIRE(path.size() >= 1);
            const auto b_on_mesh = mesh->nearest_point(b, robot_settings().query_extents);
            REQUIRE(b_on_mesh.has_value());
            CHECK(glm::length(path.back() - *b_on_mesh) < 0.01f);
        } else if (status == nav::PathStatus::Partial) {
            CHECK_FALSE(path.empty());
        } else {
            CHECK(path.empty());
        }
        (void)mesh->walkable_line(a, b);
        (void)mesh->path_length(a, b);
    }
    const Vec3 nan(std::numeric_limits<float>::quiet_NaN());
    CHECK(mesh->find_path(nan, Vec3(0), path) == nav::PathStatus::StartOffMesh);
    CHECK_FALSE(mesh->nearest_point(nan, Vec3(1)).has_value());
    CHECK(found > 0);
}
