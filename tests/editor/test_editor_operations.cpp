// Selection, locks, grid snapping, transforms, multi-selection editing, duplicate and copy/paste.
#include "editor_test_util.h"

#include <nlohmann/json.hpp>

#include <cmath>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

TEST_CASE(
    "selection: single, add, toggle, remove, all of a type, box; locked and hidden entities are skipped") {
    Editor ed;
    int a = *ed.place(EntityType::Robot, {0, 0, 0});
    int b = *ed.place(EntityType::Robot, {10, 0, 0});
    int c = *ed.place(EntityType::Pickup, {20, 0, 0});
    int d = *ed.place(EntityType::Robot, {30, 0, 0});

    REQUIRE(ed.select({a}).ok());
    REQUIRE(ed.select({b, c}, SelectMode::Add).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, b, c});
    REQUIRE(ed.select({b, d}, SelectMode::Toggle).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, c, d});
    REQUIRE(ed.select({a}, SelectMode::Remove).ok());
    CHECK(ed.doc().selection == std::vector<int>{c, d});

    CHECK(ed.select_all_of_type(EntityType::Robot) == 3);
    CHECK(ed.doc().selection == std::vector<int>{a, b, d});

    REQUIRE(ed.set_locked(b, true).ok());
    REQUIRE(ed.set_hidden(d, true).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, d}); // locking drops it from the selection
    CHECK(ed.select_all_of_type(EntityType::Robot) == 1);
    CHECK(ed.doc().selection == std::vector<int>{a});
    auto locked = ed.select({b});
    REQUIRE_FALSE(locked.ok());
    CHECK(locked.error().hint.find("unlock") != std::string::npos);
    CHECK_FALSE(ed.select({999}).ok());
    CHECK(ed.doc().selection == std::vector<int>{a}); // failed selects change nothing

    // Box select: the robot at x=0 spans x -0.8..0.8; the pickup at 20 spans 19.6..20.4.
    CHECK(ed.select_in_box({{-1, 0, -1}, {20, 3, 1}}) == 2);
    CHECK(ed.doc().selection == std::vector<int>{a, c});
    CHECK(ed.select_in_box({{0.9f, 0, -1}, {19.5f, 3, 1}}) == 0); // b is inside but locked
    CHECK(ed.doc().selection.empty());
    CHECK(ed.select_where([](const level::Entity& e) { return e.position.x > 15; }) == 1); // d hidden
    CHECK(ed.select_all() == 2);

    // Locked entities are not edited even when an operation names them.
    REQUIRE(ed.set_locked(b, true).ok());
    CHECK_FALSE(ed.rename(b, "x").ok());
    CHECK_FALSE(ed.delete_entities({b}).ok());
}

TEST_CASE("transforms: snapping, nudge, pivot rotation exact at quarter turns, 15° turns stay stable") {
    Editor ed;
    ed.grid().step = 0.5f;
    int a = *ed.place(EntityType::Robot, {1.26f, 0, 0.74f}, 8.0f);
    CHECK(ed.level().find(a)->position == Vec3(1.5f, 0, 0.5f));
    CHECK(ed.level().find(a)->rotation.x == 15.0f);

    REQUIRE(ed.nudge(0, 1).ok());
    REQUIRE(ed.nudge(2, -1).ok());
    CHECK(ed.level().find(a)->position == Vec3(2.0f, 0, 0.0f));
    CHECK_FALSE(ed.nudge(3, 1).ok());

    // Snapped move: the primary lands on the grid; others keep their offset to it.
    int b = *ed.place(EntityType::Robot, {4.0f, 0, 0.0f});
    REQUIRE(ed.select({a, b}).ok());
    REQUIRE(ed.move_selection({0.3f, 0, 0.1f}, true).ok());
    CHECK(ed.level().find(a)->position == Vec3(2.5f, 0, 0.0f));
    CHECK(ed.level().find(b)->position == Vec3(4.5f, 0, 0.0f));

    // Two entities turn about the centre of their positions: exact at 90°.
    REQUIRE(ed.rotate_selection(90).ok());
    CHECK(ed.level().find(a)->position == Vec3(3.5f, 0, 1.0f));
    CHECK(ed.level().find(b)->position == Vec3(3.5f, 0, -1.0f));
    CHECK(ed.level().find(a)->rotation.x == 105.0f);
    for (int i = 0; i < 3; ++i) REQUIRE(ed.rotate_selection(90).ok());
    CHECK(ed.level().find(a)->position == Vec3(2.5f, 0, 0.0f));
    CHECK(ed.level().find(a)->rotation.x == 15.0f);

    // Yaw stays in (-180, 180] and 24 turns of 15° come back (positions to float round-off).
    ed.grid().snap = true;
    for (int i = 0; i < 24; ++i) REQUIRE(ed.rotate_selection(15).ok());
    CHECK(ed.level().find(a)->rotation.x == 15.0f);
    CHECK(ed.level().find(a)->position.x == doctest::Approx(2.5).epsilon(1e-5));
    CHECK(std::abs(ed.level().find(a)->position.z) < 1e-5f);
    CHECK(ed.level().find(b)->position.x == doctest::Approx(4.5).epsilon(1e-5));
    // With snapping on, a 20° request turns 15° (the rotation step).
    REQUIRE(ed.select({a}).ok());
    REQUIRE(ed.rotate_selection(20).ok());
    CHECK(ed.level().find(a)->rotation.x == 30.0f);
    REQUIRE(ed.rotate_selection(170).ok());
    CHECK(ed.level().find(a)->rotation.x == -165.0f);
}

TEST_CASE("scale: changes only size fields, per type; types without sizes are reported") {
    Editor ed;
    int wall = *ed.place(EntityType::Wall, {0, 0, 0});
    int floor = *ed.place(EntityType::Floor, {0, 0, 0});
    int door = *ed.place(EntityType::Door, {0, 0, 0});
    int gas = *ed.place(EntityType::GasCylinder, {0, 0, 0});
    int robot = *ed.place(EntityType::Robot, {0, 0, 0});
    REQUIRE(ed.select({wall, floor, door, gas, robot}).ok());
    REQUIRE(ed.scale_selection({2, 0.5f, 3}).ok());
    CHECK(ed.level().find(wall)->as<level::WallProps>().size == Vec3(20, 8, 1.5f));
    CHECK(ed.level().find(floor)->as<level::FloorProps>().size == Vec2(40, 60));
    CHECK(ed.level().find(door)->as<level::DoorProps>().width == 10.0f);
    CHECK(ed.level().find(door)->as<level::DoorProps>().height == 2.5f);
    CHECK(ed.level().find(gas)->as<level::GasCylinderProps>().radius == 1.0f);
    CHECK(ed.level().find(robot)->as<level::RobotProps>() == level::RobotProps{});
    REQUIRE(ed.select({robot}).ok());
    CHECK_FALSE(ed.scale_selection({2, 2, 2}).ok());
    REQUIRE(ed.select({door}).ok());
    CHECK_FALSE(ed.scale_selection({1000, 1, 1}).ok()); // width beyond its range: nothing changes
    CHECK(ed.level().find(door)->as<level::DoorProps>().width == 10.0f);
}

TEST_CASE("properties: multi-selection edits common fields; revert to default") {
    Editor ed;
    int fl = *ed.place(EntityType::FloorLight, {0, 0, 0});
    int tl = *ed.place(EntityType::TopLight, {0, 16, 0});
    int robot = *ed.place(EntityType::Robot, {0, 0, 0});
    REQUIRE(ed.select({fl, tl}).ok());
    auto common = common_fields(ed.selected_entities());
    std::vector<std::string> names;
    for (const auto& f : common) names.push_back(f.name);
    CHECK(names ==
          std::vector<std::string>{"name", "position", "rotation", "color", "intensity", "range", "on"});
    REQUIRE(ed.set_field_text("color", "#ff8000").ok());
    REQUIRE(ed.set_field_text("on", "false").ok());
    for (int id : {fl, tl}) {
        auto color = get_entity_field(*ed.level().find(id), "color");
        CHECK(format_field_value(*color) == "#ff8000");
        CHECK(std::get<bool>(*get_entity_field(*ed.level().find(id), "on")) == false);
    }
    // A field only some selected entities have: the others are an error, nothing changes.
    REQUIRE(ed.select({fl, robot}).ok());
    CHECK_FALSE(ed.set_field_text("cone_angle", "20").ok());
    CHECK(ed.level().find(fl)->as<level::FloorLightProps>().cone_angle == 35.0f);

    REQUIRE(ed.select({fl, tl}).ok());
    REQUIRE(ed.revert_field("color").ok());
    REQUIRE(ed.revert_field("on").ok());
    CHECK(ed.level().find(fl)->as<level::FloorLightProps>() == level::FloorLightProps{});
    CHECK(ed.level().find(tl)->as<level::TopLightProps>() == level::TopLightProps{});

    // Choices only take their options.
    int pickup = *ed.place(EntityType::Pickup, {0, 0, 0});
    (void)pickup;
    auto bad = ed.set_field_text("kind", "armor");
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().hint.find("health, ammo, shield") != std::string::npos);
    REQUIRE(ed.set_field_text("kind", "shield").ok());
}

TEST_CASE("duplicate gives new ids after next_id, offset by a grid step, and selects the copies") {
    Editor ed;
    ed.grid().step = 2.0f;
    int a = *ed.place(EntityType::Robot, {0, 0, 0}, 0, "R1");
    int b = *ed.place(EntityType::Pickup, {4, 0, 0});
    REQUIRE(ed.select({b, a}).ok());
    REQUIRE(ed.duplicate().ok());
    REQUIRE(ed.level().entities.size() == 4);
    const auto& copy_a = ed.level().entities[2];
    const auto& copy_b = ed.level().entities[3];
    CHECK(copy_a.id == 3); // level order, not selection order
    CHECK(copy_b.id == 4);
    CHECK(copy_a.name == "R1");
    CHECK(copy_a.position == Vec3(2, 0, 2));
    CHECK(copy_b.position == Vec3(6, 0, 2));
    CHECK(ed.level().next_id == 5);
    CHECK(ed.doc().selection == std::vector<int>{3, 4});
    CHECK(ed.history().undo_name() == "Duplicate 2 entities");
}

TEST_CASE("copy/paste: JSON text with fresh ids, between levels, and bad clipboards reported") {
    Editor source;
    int r = *source.place(EntityType::Robot, {3, 0, 4}, 90, "Guard");
    REQUIRE(source.set_field("health", FieldValue(300.0)).ok());
    int g = *source.place(EntityType::GasCylinder, {6, 0, 4});
    REQUIRE(source.select({r, g}).ok());
    const std::string text = source.copy();
    CHECK(text.find("killswitch-clipboard") != std::string::npos);

    Editor target; // another level
    for (int i = 0; i < 5; ++i) (void)target.place(EntityType::Pickup, {float(i), 0, 0});
    REQUIRE(target.paste_text(text).ok());
    REQUIRE(target.level().entities.size() == 7);
    const auto& pasted = target.level().entities[5];
    CHECK(pasted.id == 6);
    CHECK(pasted.name == "Guard");
    CHECK(pasted.position == Vec3(3, 0, 4));
    CHECK(pasted.rotation.x == 90.0f);
    CHECK(pasted.as<level::RobotProps>().health == 300.0f);
    CHECK(target.level().entities[6].id == 7);
    CHECK(target.doc().selection == std::vector<int>{6, 7});
    REQUIRE(target.undo());
    CHECK(target.level().entities.size() == 5);
    CHECK(target.level().next_id == 6);

    // Pasting in the same level twice gives distinct ids each time.
    REQUIRE(source.paste().ok());
    REQUIRE(source.paste().ok());
    CHECK(source.level().entities.size() == 6);
    CHECK(source.level().next_id == 7);

    // A single entity's JSON also pastes.
    REQUIRE(target.paste_text(nlohmann::json(level::entity_to_json(source.level().entities[0])).dump()).ok());

    const size_t steps = target.history().undo_count();
    auto not_json = target.paste_text("hello");
    REQUIRE_FALSE(not_json.ok());
    CHECK(not_json.error().hint.find("Ctrl+C") != std::string::npos);
    CHECK_FALSE(target.paste_text("[]").ok());
    auto bad_entity =
        target.paste_text(R"({"killswitch-clipboard":1,"entities":[{"type":"robot","position":[0,0,"x"]}]})");
    REQUIRE_FALSE(bad_entity.ok());
    CHECK(bad_entity.error().str().find("clipboard") != std::string::npos);
    CHECK(target.history().undo_count() == steps);
}

TEST_CASE(
    "transforms: turning a pair 2400 times by 15° far from the origin does not drift beyond a few ulps") {
    Editor ed;
    ed.grid().snap = false;
    const Vec3 start_a(1000, 0, 1000), start_b(1010, 0, 993);
    int a = *ed.place(EntityType::Robot, start_a);
    int b = *ed.place(EntityType::Robot, start_b);
    REQUIRE(ed.select({a, b}).ok());
    const float ulp = std::nextafter(1010.0f, 2000.0f) - 1010.0f; // 6.1e-5
    int turned = 0;
    for (int i = 0; i < 2400; ++i) turned += ed.rotate_selection(15).ok();
    CHECK(turned == 2400);
    CHECK(glm::length(ed.level().find(a)->position - start_a) < 8 * ulp);
    CHECK(glm::length(ed.level().find(b)->position - start_b) < 8 * ulp);
    CHECK(ed.level().find(a)->rotation.x == 0.0f);
}
