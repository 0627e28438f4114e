// Doors, stairs, floor lights, the caption owner rule and gas cylinders (falloff, chain reactions).
#include "game_test_levels.h"

#include <cmath>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// A wall across z = -10 with a 5-wide doorway and a door in it.
level::Level door_level(bool open) {
    auto lv = flat_level();
    add_wall(lv, Vec3(-7.5f, 0, -10), Vec3(10, 16, 0.5f));
    add_wall(lv, Vec3(7.5f, 0, -10), Vec3(10, 16, 0.5f));
    add_wall(lv, Vec3(0, 5, -10), Vec3(5, 11, 0.5f));
    auto& d = lv.add(level::EntityType::Door, Vec3(0, 0, -10), "door");
    d.as<level::DoorProps>().open = open;
    return lv;
}

} // namespace

TEST_CASE(
    "a closed door blocks; E inside its sensor opens it in 0.5 s; an open door lets the player through") {
    auto g = make_game(door_level(false));
    run_for(*g, 1.5, Input{1.0f});
    CHECK(g->player().feet.z > -9.5f); // stopped by the leaves
    CHECK(g->player().feet.z < -7.0f);
    REQUIRE(g->doors()[0].player_inside);
    CHECK(g->caption().text() == "Press E to open the door");
    g->step(press_e());
    CHECK(g->doors()[0].opening);
    CHECK(count_events(*g, EventType::DoorToggled) == 1);
    CHECK(g->caption().text() == "Press E to close the door");
    run_for(*g, 0.25);
    CHECK(g->doors()[0].progress == doctest::Approx(0.5f).epsilon(0.03)); // linear
    run_for(*g, 0.3);
    CHECK(g->doors()[0].progress == 1.0f);
    CHECK(g->doors()[0].leaf_offset() == doctest::Approx(2.0f));
    run_for(*g, 1.5, Input{1.0f});
    CHECK(g->player().feet.z < -15.0f);
}

TEST_CASE("a closing door pushes the player out of the doorway instead of trapping them") {
    auto g = make_game(door_level(true));
    g->teleport_player(Vec3(0, 0, -10), 0.0f);
    g->step({});
    REQUIRE(g->doors()[0].player_inside);
    g->step(press_e());
    REQUIRE_FALSE(g->doors()[0].opening);
    run_for(*g, 1.0);
    CHECK(g->doors()[0].progress == 0.0f);
    // Not inside a leaf, and free to walk away.
    std::vector<physics::BodyId> overlaps;
    const Vec3 c = g->world().transform(g->player().body).position;
    g->world().overlap_capsule({c - Vec3(0, 0.5f, 0), c + Vec3(0, 0.5f, 0)}, 0.99f, overlaps);
    for (auto id : overlaps) CHECK(user_kind(g->world().user_data(id)) != BodyKind::DoorLeaf);
    CHECK(std::abs(g->player().feet.z + 10.0f) > 0.9f);
    const Vec3 before = g->player().feet;
    run_for(*g, 0.5, Input{-1.0f});
    CHECK(glm::length(g->player().feet - before) > 3.0f);
}

TEST_CASE("stairs are climbable by the player and by a chasing robot") {
    auto lv = flat_level();
    lv.add(level::EntityType::Stair, Vec3(0, 0, -10), "stair"); // 12 x 6 x 12, rises toward -z
    auto& top = lv.add(level::EntityType::Floor, Vec3(0, 6, -22), "platform");
    top.as<level::FloorProps>().size = Vec2(12, 12);
    top.as<level::FloorProps>().thickness = 6.0f;
    check_climb_to_platform(lv);
}

TEST_CASE("floor lights toggle with E; top lights are fixed") {
    auto lv = flat_level();
    const int lamp_id = lv.add(level::EntityType::FloorLight, Vec3(0, 0, -3), "lamp").id;
    lv.add(level::EntityType::TopLight, Vec3(0, 16, 0), "top");
    auto g = make_game(lv);
    g->step({});
    REQUIRE(g->interact_target() == lamp_id);
    CHECK(g->caption().text() == "Press E to toggle the light");
    CHECK(g->lights()[0].intensity() == doctest::Approx(0.8f));
    g->step(press_e());
    CHECK_FALSE(g->lights()[0].on);
    CHECK(g->lights()[0].intensity() == 0.0f);
    CHECK(g->lights()[0].emissive() == 0.0f);
    CHECK(count_events(*g, EventType::LightToggled) == 1);
    g->step(press_e());
    CHECK(g->lights()[0].on);
    CHECK(g->lights()[1].on);
    // Turned away from it, E does nothing.
    g->teleport_player(g->player().feet, kPi);
    g->step(press_e());
    CHECK(g->lights()[0].on);
    CHECK(g->interact_target() == -1);
}

TEST_CASE("caption owner rule: only the owner hides it, unless the owner changes") {
    Caption c;
    CHECK(c.show("Press E to open the door", 1));
    CHECK_FALSE(c.hide(2)); // not the owner
    CHECK(c.visible());
    CHECK(c.show("Press E to toggle the light", 2)); // the owner changes with the text
    CHECK(c.owner() == 2);
    CHECK_FALSE(c.hide(1)); // the old owner can no longer hide it
    CHECK(c.visible());
    CHECK(c.text() == "Press E to toggle the light");
    CHECK(c.hide(2));
    CHECK_FALSE(c.visible());
    CHECK_FALSE(c.hide(2));

    SUBCASE("in the game: leaving a door's sensor hides its caption; another object's caption survives") {
        auto lv = door_level(false);
        lv.add(level::EntityType::FloorLight, Vec3(4, 0, -20), "lamp");
        auto g = make_game(lv);
        g->teleport_player(Vec3(0, 0, -6), 0.0f);
        g->step({});
        CHECK(g->caption().visible());
        CHECK(g->caption().owner() == g->doors()[0].entity_id);
        g->teleport_player(Vec3(0, 0, 10), 0.0f); // out of the sensor
        run_for(*g, 0.05);
        CHECK_FALSE(g->caption().visible());
    }
}

TEST_CASE("gas cylinders: radial damage falls off with distance, walls shelter, chain reactions") {
    SUBCASE("damage by distance") {
        float damage[3];
        const float distances[3] = {2.5f, 4.5f, 10.0f};
        for (int k = 0; k < 3; ++k) {
            auto lv = flat_level();
            lv.add(level::EntityType::GasCylinder, Vec3(0, 0, -distances[k]), "gas");
            auto g = make_game(lv);
            g->step({});
            g->explode_cylinder(0);
            damage[k] = 100.0f - g->player().health;
            CHECK(count_events(*g, EventType::Explosion) == 1);
            CHECK(g->cylinders()[0].exploded);
            CHECK_FALSE(g->world().enabled(g->cylinders()[0].body));
        }
        // Linear falloff to the player's surface: 30·(1 - (d - 1)/7).
        CHECK(damage[0] == doctest::Approx(30.0f * (1.0f - 1.5f / 7.0f)).epsilon(0.02));
        CHECK(damage[1] == doctest::Approx(30.0f * (1.0f - 3.5f / 7.0f)).epsilon(0.02));
        CHECK(damage[2] == 0.0f);
        CHECK(damage[0] > damage[1]);
    }
    SUBCASE("a wall between shelters") {
        auto lv = flat_level();
        lv.add(level::EntityType::GasCylinder, Vec3(0, 0, -4), "gas");
        add_wall(lv, Vec3(0, 0, -2), Vec3(10, 16, 0.5f));
        auto g = make_game(lv);
        g->step({});
        g->explode_cylinder(0);
        CHECK(g->player().health == 100.0f);
    }
    SUBCASE("chain: A sets off B, B sets off C (out of A's reach), each after a fuse; robots take damage") {
        auto lv = flat_level();
        for (float z : {-20.0f, -25.0f, -30.0f}) lv.add(level::EntityType::GasCylinder, Vec3(0, 0, z), "gas");
        add_robot(lv, Vec3(3, 0, -30)).as<level::RobotProps>().hit_probability = 0.0f;
        auto g = make_game(lv);
        g->step({});
        Input fire;
        fire.fire = true;
        g->teleport_player(Vec3(0.0f), 0.0f, std::atan2(-2.0f, 20.0f)); // aim at A's centre
        g->step(fire);
        CHECK(g->cylinders()[0].exploded);
        CHECK_FALSE(g->cylinders()[1].exploded);
        CHECK_FALSE(g->cylinders()[2].exploded);
        run_for(*g, 0.13);
        CHECK(g->cylinders()[1].exploded);
        CHECK_FALSE(g->cylinders()[2].exploded);
        run_for(*g, 0.13);
        CHECK(g->cylinders()[2].exploded);
        CHECK(g->robots()[0].health < 100.0f);
        CHECK(g->player().health == 100.0f); // 20 away: out of reach
    }
    SUBCASE("touching a cylinder sets it off") {
        auto lv = flat_level();
        lv.add(level::EntityType::GasCylinder, Vec3(0, 0, -5), "gas");
        auto g = make_game(lv);
        run_for(*g, 1.0, Input{1.0f});
        CHECK(g->cylinders()[0].exploded);
        CHECK(g->player().health < 100.0f);
    }
}
