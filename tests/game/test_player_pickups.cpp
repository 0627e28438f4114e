// Player stats: shield first, caps, pickups, shots and ammo, the death and win flows.
#include "game_test_levels.h"
#include "level/shutdown_objective.h"

#include <cmath>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

TEST_CASE("the shield absorbs damage first, the overflow reduces health, health stops at 0") {
    auto g = make_game(flat_level());
    g->step({});
    auto lv = flat_level();
    auto& shield = lv.add(level::EntityType::Pickup, Vec3(0, 0, -3), "shield");
    shield.as<level::PickupProps>().kind.value = "shield";
    shield.as<level::PickupProps>().amount = 30;
    g = make_game(lv);
    run_for(*g, 0.5, Input{1.0f});
    REQUIRE(g->player().shield == doctest::Approx(30.0f));
    g->damage_player(20.0f);
    CHECK(g->player().shield == doctest::Approx(10.0f));
    CHECK(g->player().health == doctest::Approx(100.0f));
    g->damage_player(25.0f); // 10 absorbed, 15 to health
    CHECK(g->player().shield == doctest::Approx(0.0f));
    CHECK(g->player().health == doctest::Approx(85.0f));
    CHECK(g->player().damage_flash > 0.0f);
    g->damage_player(1000.0f);
    CHECK(g->player().health == 0.0f);
    CHECK(g->phase() == Phase::Dead);
}

TEST_CASE("pickups add their amount capped at the maximum, are removed, and wait while the stat is full") {
    auto lv = flat_level();
    auto add = [&](const char* kind, float amount, float z) {
        auto& e = lv.add(level::EntityType::Pickup, Vec3(0, 0, z), kind);
        e.as<level::PickupProps>().kind.value = kind;
        e.as<level::PickupProps>().amount = amount;
    };
    add("health", 10, -4);  // health is full: must stay
    add("ammo", 300, -8);   // 150 + 300 capped at 400
    add("shield", 80, -12); // capped at 50
    auto g = make_game(lv);
    int taken = 0;
    for (int i = 0; i < 120; ++i) {
        g->step(Input{1.0f});
        taken += count_events(*g, EventType::PickupTaken);
    }
    CHECK(g->player().feet.z < -13.0f);
    CHECK(taken == 2);
    CHECK(g->player().ammo == 400);
    CHECK(g->player().shield == doctest::Approx(50.0f));
    CHECK_FALSE(g->pickups()[0].taken);
    CHECK(g->pickups()[1].taken);
    CHECK(g->pickups()[2].taken);
    // Hurt, walk back over the health pickup: +10, capped at 100.
    g->damage_player(50.0f + 5.0f); // shield 50 absorbs, health 95
    REQUIRE(g->player().health == doctest::Approx(95.0f));
    run_for(*g, 1.0, Input{-1.0f});
    CHECK(g->pickups()[0].taken);
    CHECK(g->player().health == doctest::Approx(100.0f));
}

TEST_CASE("a shot costs one ammo, hits the closest shootable along the view, and needs ammo") {
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -30));
    add_robot(lv, Vec3(0, 0, -40)); // behind the first: never hit
    auto g = make_game(lv);
    g->step({});
    Input fire;
    fire.fire = true;
    // Aim at the robot's centre (eye at y 3, centre at y 1.5, 30 away).
    g->teleport_player(Vec3(0.0f), 0.0f, std::atan2(-1.5f, 30.0f));
    g->step(fire);
    CHECK(g->player().ammo == 149);
    CHECK(g->player().shots == 1);
    CHECK(count_events(*g, EventType::ShotFired) == 1);
    CHECK(g->robots()[0].health == doctest::Approx(80.0f));
    CHECK(g->robots()[1].health == doctest::Approx(100.0f));
    CHECK(g->player().hit_marker > 0.0f);
    CHECK(g->robots()[0].angry > 9.9f);
    for (int i = 0; i < 4; ++i) g->step(fire);
    CHECK(g->robots()[0].health == 0.0f);
    CHECK(g->robots()[0].mode == RobotMode::Dying);
    // The death clip plays, then the robot explodes and is removed.
    bool died = false, exploded = false;
    for (int i = 0; i < 600 && !died; ++i) {
        g->step({});
        died = count_events(*g, EventType::RobotDied) > 0;
        exploded = count_events(*g, EventType::Explosion) > 0;
    }
    CHECK(died);
    CHECK(exploded);
    CHECK(g->robots()[0].mode == RobotMode::Dead);
    CHECK(g->robots_killed() == 1);
    CHECK_FALSE(g->world().enabled(g->robots()[0].body));
}

TEST_CASE("without ammo the trigger does nothing") {
    GameOptions options;
    options.settings.start_ammo = 1;
    auto g = Game::create(flat_level(), options);
    REQUIRE(g.ok());
    Input fire;
    fire.fire = true;
    (*g)->step(fire);
    (*g)->step(fire);
    CHECK((*g)->player().ammo == 0);
    CHECK((*g)->player().shots == 1);
    CHECK(count_events(**g, EventType::ShotFired) == 0);
}

TEST_CASE("death flow: fall camera (0.3 s Quadratic.In drop, 0.3 s Bounce roll), then the death menu") {
    auto g = make_game(flat_level());
    g->step({});
    g->damage_player(500.0f);
    REQUIRE(g->phase() == Phase::Dead);
    CHECK(count_events(*g, EventType::PlayerDied) == 1);
    CHECK(g->death_camera().eye_drop == doctest::Approx(0.0f));
    run_for(*g, 0.15);
    const float half_drop = g->death_camera().eye_drop;
    CHECK(half_drop == doctest::Approx(1.5f * 0.25f).epsilon(0.05)); // k² at k = 0.5
    run_for(*g, 0.15);
    CHECK(g->death_camera().eye_drop == doctest::Approx(1.5f));
    CHECK(g->death_camera().roll == doctest::Approx(0.0f).epsilon(0.01));
    run_for(*g, 0.3);
    // The reference's camera.rotation.z = +π/2: a fall onto the left side, geometry::Camera roll −π/2.
    CHECK(g->death_camera().roll == doctest::Approx(-kPi / 2));
    CHECK(g->death_camera().pitch == doctest::Approx(kPi / 4));
    CHECK_FALSE(g->death_camera().menu_ready);
    run_for(*g, 1.0);
    CHECK(g->death_camera().menu_ready);
    // A dead player no longer moves, shoots or takes pickups.
    Input fire;
    fire.fire = true;
    g->step(fire);
    CHECK(g->player().shots == 0);
}

TEST_CASE("win flow: E at the control panel ends the game in victory") {
    auto lv = flat_level();
    lv.add(level::EntityType::ControlPanel, Vec3(0, 0, -5), "panel");
    level::add_shutdown_objective(lv);
    auto g = make_game(lv);
    g->step({});
    CHECK(g->interact_target() == lv.entities.back().id);
    CHECK(g->caption().visible());
    CHECK(g->caption().text() == "Press E to shutdown the simulation");
    Input e;
    e.interact = true;
    g->step(e);
    CHECK(g->phase() == Phase::Won);
    CHECK(count_events(*g, EventType::Won) == 1);
}

TEST_CASE("non-finite and absurd input is ignored, not propagated") {
    auto g = make_game(flat_level());
    Input bad;
    bad.move_forward = std::nanf("");
    bad.move_right = 1e30f;
    bad.look_yaw = INFINITY;
    bad.look_pitch = -1e9f;
    run_for(*g, 0.5, bad);
    CHECK(is_finite(g->player().feet));
    CHECK(std::isfinite(g->player().yaw));
    CHECK(g->player().pitch >= -kPi / 2);
    CHECK(g->player().feet.y == doctest::Approx(0.0f).epsilon(0.05));
}

TEST_CASE("pause freezes the simulation until toggled again") {
    auto g = make_game(flat_level());
    Input pause;
    pause.pause = true;
    g->step(pause);
    CHECK(g->paused());
    const auto steps = g->steps();
    run_for(*g, 1.0, Input{1.0f});
    CHECK(g->steps() == steps);
    CHECK(g->player().feet.z == doctest::Approx(0.0f));
    g->step(pause);
    CHECK_FALSE(g->paused());
    run_for(*g, 1.0, Input{1.0f});
    CHECK(g->player().feet.z < -10.0f);
}

TEST_CASE("bad levels and settings give errors naming the entity, not crashes") {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -5));
    r.position.x = std::nanf("");
    const int id = r.id;
    auto g = Game::create(lv);
    REQUIRE_FALSE(g.ok());
    CHECK(g.error().str().find("robot " + std::to_string(id)) != std::string::npos);

    auto huge = flat_level();
    add_wall(huge, Vec3(0.0f), Vec3(1e7f, 16, 0.5f)); // absurd size: refused by the physics' shape check
    auto h = Game::create(huge);
    REQUIRE_FALSE(h.ok());
    CHECK(h.error().str().find("wall") != std::string::npos);

    GameOptions bad_step;
    bad_step.settings.step = 0.0;
    auto s = Game::create(flat_level(), bad_step);
    REQUIRE_FALSE(s.ok());
    CHECK(s.error().str().find("step") != std::string::npos);
}
