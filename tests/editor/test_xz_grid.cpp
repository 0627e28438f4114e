// The ground-plane grid the validation rules use to find nearby walls and floors: a query returns, in
// ascending order and once each, every item whose box meets the query in x and z (a superset is fine, a
// miss is a rule that silently stops firing). And the rules built on it still find each planted defect on
// a level far larger than one grid cell, wherever it is.
#include "editor_test_util.h"
#include "level/shutdown_objective.h"
#include "model/validation.h"
#include "model/xz_grid.h"

#include <algorithm>
#include <limits>
#include <random>

using namespace ks;
using namespace ks::editor;

namespace {
bool meets_xz(const geometry::Aabb& a, const geometry::Aabb& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.z <= b.max.z && b.min.z <= a.max.z;
}
} // namespace

TEST_CASE("xz grid: queries return every box they meet, sorted and once, for random boxes of every size") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> centre(-500.0f, 500.0f), size(0.0f, 6.0f), coin(0.0f, 1.0f);
    for (int round = 0; round < 20; ++round) {
        std::vector<geometry::Aabb> boxes;
        const int n = 1 + round * 37;
        for (int i = 0; i < n; ++i) {
            const Vec3 c(centre(rng), centre(rng) * 0.01f, centre(rng));
            Vec3 half(size(rng), size(rng), size(rng));
            if (coin(rng) < 0.05f) half.x = 400.0f;   // long walls and whole-level floors span many cells
            if (coin(rng) < 0.05f) half = Vec3(0.0f); // points
            boxes.push_back({c - half, c + half});
        }
        const XzGrid grid(boxes);
        CHECK(grid.columns() >= 1);
        CHECK(grid.columns() <= 1024);
        std::vector<int> got;
        for (int q = 0; q < 200; ++q) {
            const Vec3 c(centre(rng) * 1.2f, 0.0f, centre(rng) * 1.2f);
            const Vec3 half = q % 3 == 0 ? Vec3(0.0f) : Vec3(size(rng) * 4.0f);
            const geometry::Aabb query{c - half, c + half};
            grid.query(query, got);
            CHECK(std::is_sorted(got.begin(), got.end()));
            CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
            for (int i = 0; i < n; ++i)
                if (meets_xz(boxes[static_cast<size_t>(i)], query)) {
                    INFO("round " << round << ", query " << q << ", box " << i);
                    CHECK(std::binary_search(got.begin(), got.end(), i));
                }
        }
    }
}

TEST_CASE("xz grid: non-finite boxes are returned by every query; an empty grid returns nothing") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<geometry::Aabb> boxes = {
        {Vec3(0.0f), Vec3(1.0f)}, {Vec3(nan, 0.0f, 0.0f), Vec3(1.0f)}, {Vec3(100.0f), Vec3(101.0f)}};
    const XzGrid grid(boxes);
    std::vector<int> got;
    grid.query_point(100.5f, 100.5f, got);
    CHECK(got == std::vector<int>{1, 2});
    grid.query_point(-50.0f, 3.0f, got); // outside every finite box
    CHECK(got == std::vector<int>{1});
    grid.query({Vec3(nan), Vec3(nan)}, got); // a non-finite query meets everything, as a plain loop would
    CHECK(got == std::vector<int>{0, 1, 2});
    const XzGrid empty(std::vector<geometry::Aabb>{});
    empty.query_point(0.0f, 0.0f, got);
    CHECK(got.empty());
}

TEST_CASE("validation on a 10 x 10 room level finds each planted defect wherever it is, and nothing else") {
    // Rooms 24 units square, walls between them with 5-unit doorways (a door in every other one).
    level::Level lv;
    const int side = 10;
    const float room = 24.0f, span = side * room;
    auto& ground = lv.add(level::EntityType::Floor, Vec3(span / 2, 0, span / 2), "ground");
    ground.as<level::FloorProps>().size = Vec2(span, span);
    auto wall = [&](Vec3 a, Vec3 b, float base, float height) {
        auto& w = lv.add(level::EntityType::Wall, Vec3((a.x + b.x) / 2, base, (a.z + b.z) / 2), "wall");
        w.as<level::WallProps>().size = Vec3(glm::length(b - a), height, 0.5f);
        w.rotation.x = std::abs(b.x - a.x) > std::abs(b.z - a.z) ? 0.0f : 90.0f;
    };
    int doors = 0;
    auto doorway_wall = [&](Vec3 a, Vec3 b) {
        const Vec3 dir = glm::normalize(b - a);
        const Vec3 d0 = a + dir * (room / 2 - 2.5f), d1 = a + dir * (room / 2 + 2.5f);
        wall(a, d0, 0, 16), wall(d1, b, 0, 16), wall(d0, d1, 5, 11);
        if (doors++ % 2 == 0) {
            auto& d = lv.add(level::EntityType::Door, (d0 + d1) * 0.5f, "door");
            d.rotation.x = std::abs(dir.x) > 0.5f ? 0.0f : 90.0f;
        }
    };
    for (int i = 1; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            doorway_wall({i * room, 0, j * room}, {i * room, 0, (j + 1) * room});
            doorway_wall({j * room, 0, i * room}, {(j + 1) * room, 0, i * room});
        }
    lv.add(level::EntityType::ControlPanel, Vec3(span - 12, 0, span - 12), "panel");
    level::add_shutdown_objective(lv); // won at the panel
    lv.player_start.position = Vec3(12, 0, 12);
    ValidationOptions options;
    options.check_reachability = false; // this test is about the rules that ask the grid
    REQUIRE(validate_design(lv, options).empty());

    // Defects in far-apart rooms: a cylinder inside a wall, a floating pickup, a robot outside every floor,
    // a door standing in the open, the player start inside a wall.
    const int cylinder =
        lv.add(level::EntityType::GasCylinder, Vec3(9 * room, 0, 7 * room + 3), "in wall").id;
    const int pickup =
        lv.add(level::EntityType::Pickup, Vec3(8 * room + 5, 2.0f, 1 * room + 5), "floating").id;
    const int robot = lv.add(level::EntityType::Robot, Vec3(span + 30, 0, span / 2), "outside").id;
    const int open_door = lv.add(level::EntityType::Door, Vec3(5 * room + 12, 0, 3 * room + 12), "open").id;
    lv.player_start.position = Vec3(3 * room, 0, 6 * room + 3);
    const auto issues = validate_design(lv, options);
    auto has = [&](Rule rule, int id) {
        return std::any_of(issues.begin(), issues.end(),
                           [&](const Issue& i) { return i.rule == rule && i.entity_id == id; });
    };
    std::string found;
    for (const auto& i : issues) found += std::string(rule_name(i.rule)) + ": " + i.message + "\n";
    INFO(found);
    CHECK(has(Rule::WallOverlap, cylinder));
    CHECK(has(Rule::Support, pickup));
    CHECK(has(Rule::Support, robot));
    CHECK(has(Rule::DoorGap, open_door));
    CHECK(has(Rule::PlayerStart, 0));
    CHECK(issues.size() == 5);
}
