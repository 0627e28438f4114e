// The level logic's events and actions in the headless game: each source's events (trigger, robot, door,
// floor light, control panel, pickup, the level, an objective) and each target's actions (door, light,
// trigger, robot, spawner, message, sound, objective, the level), with locked doors and dormant robots.
#include "game/sound_cues.h"
#include "game_test_levels.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// A robot that never notices the player (for tests where it only has to stand there).
level::Entity& add_blind_robot(level::Level& lv, const char* name, Vec3 feet) {
    auto& r = add_robot(lv, feet);
    r.name = name;
    auto& props = r.as<level::RobotProps>();
    props.eye_radius_min = props.eye_radius_max = props.hearing_radius = 0.0f;
    props.dormant = true;
    return r;
}

} // namespace

TEST_CASE("level on_start shows a message on the first step; it counts down and goes") {
    auto lv = flat_level();
    add_message(lv, "Hello", "Find the panel", 1.0f);
    lv.links = {link("on_start", "Hello", "show")};
    auto g = make_game(lv);
    CHECK(on_screen(*g).empty());
    g->step({});
    CHECK(shown(*g, "Find the panel") == 1);
    CHECK(on_screen(*g) == "Find the panel");
    CHECK(g->logic().message().duration == 1.0f);
    run_for(*g, 0.5);
    CHECK(g->logic().message().time_left == doctest::Approx(0.5f).epsilon(0.02));
    run_for(*g, 0.6);
    CHECK(on_screen(*g).empty());
    CHECK(count_events(*g, EventType::MessageShown) == 0); // on_start fires once
}

TEST_CASE("a trigger fires on_enter when the player walks in and on_exit when the player leaves, once each") {
    auto lv = flat_level();
    add_message(lv, "In", "in");
    add_message(lv, "Out", "out");
    add_trigger(lv, "Gate", Vec3(0, 0, -10), Vec3(6, 4, 4)).links = {link("on_enter", "In", "show"),
                                                                     link("on_exit", "Out", "show")};
    auto g = make_game(lv);
    g->step({});
    CHECK_FALSE(g->logic().triggers()[0].occupied);
    // Walking north: the feet reach z -8 (the box's near face) after about 0.5 s at 15 units/s.
    int entered_at = -1;
    for (int i = 0; i < 120 && entered_at < 0; ++i) {
        g->step(Input{1.0f});
        if (shown(*g, "in") == 1) entered_at = i;
    }
    REQUIRE(entered_at > 0);
    CHECK(g->player().feet.z <= -8.0f);
    CHECK(g->player().feet.z > -8.2f);
    CHECK(g->logic().triggers()[0].occupied);
    run_for(*g, 0.2); // still inside: nothing more
    CHECK(on_screen(*g) == "in");
    g->teleport_player(Vec3(0, 0, 0), 0.0f);
    g->step({});
    CHECK(shown(*g, "out") == 1);
    // Above the box (feet over its top) is outside; the body's axis through the box is inside.
    g->teleport_player(Vec3(0, 4.5f, -10), 0.0f);
    g->step({});
    CHECK_FALSE(g->logic().triggers()[0].occupied);
}

TEST_CASE("a trigger notices robots, both or the player only, never the dead; disabled, it notices nothing") {
    auto lv = flat_level();
    add_message(lv, "Robot in", "robot in");
    add_message(lv, "Robot out", "robot out");
    add_message(lv, "Player in", "player in");
    add_blind_robot(lv, "Sleeper", Vec3(20, 0, 0));
    add_trigger(lv, "Robot gate", Vec3(20, 0, 0), Vec3(4, 4, 4), "robots").links = {
        link("on_enter", "Robot in", "show"), link("on_exit", "Robot out", "show")};
    add_trigger(lv, "Player gate", Vec3(20, 0, 0), Vec3(4, 4, 4), "player").links = {
        link("on_enter", "Player in", "show")};
    auto& both = add_trigger(lv, "Both gate", Vec3(-20, 0, 0), Vec3(4, 4, 4), "both");
    both.as<level::TriggerProps>().enabled = false;
    both.links = {link("on_enter", "Player in", "show")};
    auto g = make_game(lv);
    g->step({});
    CHECK(shown(*g, "robot in") == 1); // the robot stands in it from the start
    CHECK(shown(*g, "player in") == 0);
    g->damage_robot(0, 1000.0f, false);
    g->step({});
    CHECK(shown(*g, "robot out") == 1); // a dying robot is no one

    g->teleport_player(Vec3(-20, 0, 0), 0.0f);
    run_for(*g, 0.2);
    CHECK_FALSE(g->logic().triggers()[2].occupied); // disabled
    const int both_id = lv.entities.back().id;
    REQUIRE(g->run_action(level::LinkAction::Enable, both_id));
    g->step({});
    CHECK(shown(*g, "player in") == 1); // enabled with the player inside: noticed at the next step
    REQUIRE(g->run_action(level::LinkAction::Disable, both_id));
    g->teleport_player(Vec3(0, 0, 0), 0.0f);
    run_for(*g, 0.1);
    CHECK_FALSE(g->logic().triggers()[2].occupied);
    CHECK(count_events(*g, EventType::MessageShown) == 0);
}

TEST_CASE("doors: open, close, toggle; on_open and on_close from the player's E and from links") {
    auto lv = flat_level();
    add_message(lv, "Opened", "opened");
    add_message(lv, "Closed", "closed");
    auto& door = lv.add(level::EntityType::Door, Vec3(0, 0, -3), "Door");
    door.links = {link("on_open", "Opened", "show"), link("on_close", "Closed", "show")};
    const int door_id = door.id;
    auto g = make_game(lv);
    g->step({});
    REQUIRE(g->doors()[0].player_inside);
    REQUIRE(g->run_action(level::LinkAction::Open, door_id));
    CHECK(g->doors()[0].opening);
    CHECK(shown(*g, "opened") == 1);
    REQUIRE(g->run_action(level::LinkAction::Open, door_id)); // already opening: no event, no link
    CHECK(shown(*g, "opened") == 1);
    g->step(press_e()); // the player closes it
    CHECK_FALSE(g->doors()[0].opening);
    CHECK(shown(*g, "closed") == 1);
    CHECK(count_events(*g, EventType::Used) == 1);
    REQUIRE(g->run_action(level::LinkAction::Toggle, door_id));
    CHECK(g->doors()[0].opening);
    REQUIRE(g->run_action(level::LinkAction::Close, door_id));
    CHECK_FALSE(g->doors()[0].opening);
    CHECK_FALSE(g->run_action(level::LinkAction::On, door_id)); // a door takes no "on"
}

TEST_CASE("a locked door: E does nothing and the caption says Locked; unlocked, E works again") {
    auto lv = flat_level();
    auto& door = lv.add(level::EntityType::Door, Vec3(0, 0, -3), "Door");
    door.as<level::DoorProps>().locked = true;
    const int door_id = door.id;
    auto g = make_game(lv);
    g->step({});
    REQUIRE(g->doors()[0].locked);
    REQUIRE(g->interact_target() == door_id);
    CHECK(g->caption().text() == "Locked");
    g->step(press_e());
    CHECK_FALSE(g->doors()[0].opening);
    CHECK(count_events(*g, EventType::LockedDoorUsed) == 1);
    CHECK(count_events(*g, EventType::DoorToggled) == 0);
    run_for(*g, 0.5);
    CHECK(g->doors()[0].progress == 0.0f);
    // A link may still open a locked door; the player still cannot close it.
    REQUIRE(g->run_action(level::LinkAction::Open, door_id));
    run_for(*g, 0.6);
    CHECK(g->doors()[0].progress == 1.0f);
    g->step(press_e());
    CHECK(g->doors()[0].opening);
    REQUIRE(g->run_action(level::LinkAction::Unlock, door_id));
    g->step({});
    CHECK(g->caption().text() == "Press E to close the door");
    g->step(press_e());
    CHECK_FALSE(g->doors()[0].opening);
    REQUIRE(g->run_action(level::LinkAction::Lock, door_id));
    g->step({});
    CHECK(g->caption().text() == "Locked");
}

TEST_CASE("lights: on, off and toggle act on floor and top lights; a floor light's E is its on_use") {
    auto lv = flat_level();
    auto& lamp = lv.add(level::EntityType::FloorLight, Vec3(0, 0, -3), "Lamp");
    lamp.links = {link("on_use", "Ceiling light", "toggle")};
    const int top_id = lv.add(level::EntityType::TopLight, Vec3(0, 16, 0), "Ceiling light").id;
    auto g = make_game(lv);
    g->step({});
    g->step(press_e());
    CHECK_FALSE(g->lights()[0].on); // the player's toggle
    CHECK_FALSE(g->lights()[1].on); // and its link's
    CHECK(count_events(*g, EventType::LightToggled) == 2);
    g->step({});
    REQUIRE(g->run_action(level::LinkAction::On, top_id)); // between steps: its events join the last step's
    CHECK(g->lights()[1].on);
    CHECK(count_events(*g, EventType::LightToggled) == 1);
    REQUIRE(g->run_action(level::LinkAction::On, top_id)); // already on: no event
    CHECK(count_events(*g, EventType::LightToggled) == 1);
    REQUIRE(g->run_action(level::LinkAction::Off, top_id));
    CHECK_FALSE(g->lights()[1].on);
}

TEST_CASE("the control panel does what its links say: on_use completes an objective, and the level is won") {
    auto lv = flat_level();
    auto& panel = lv.add(level::EntityType::ControlPanel, Vec3(0, 0, -5), "Panel");
    panel.links = {link("on_use", "off", "complete")};
    lv.objectives = {{"off", "Switch it off", {}, {}}};
    auto g = make_game(lv);
    g->step({});
    g->step(press_e());
    CHECK(count_events(*g, EventType::Used) == 1);
    CHECK(count_events(*g, EventType::ObjectiveCompleted) == 1);
    CHECK(g->phase() == Phase::Won);
    CHECK(count_events(*g, EventType::Won) == 1);

    // Without links the panel does nothing (a version-2 level says what it does).
    auto quiet = flat_level();
    quiet.add(level::EntityType::ControlPanel, Vec3(0, 0, -5), "Panel");
    auto h = make_game(quiet);
    h->step({});
    h->step(press_e());
    CHECK(h->phase() == Phase::Playing);
}

TEST_CASE(
    "robots: dormant until activated, alert and on_alert, kill and on_death; a dead robot takes no orders") {
    auto lv = flat_level();
    add_message(lv, "Seen", "seen");
    add_message(lv, "Down", "down");
    auto& guard = add_robot(lv, Vec3(0, 0, -15), 180.0f);
    guard.name = "Guard";
    guard.as<level::RobotProps>().dormant = true;
    guard.as<level::RobotProps>().hit_probability = 0.0f;
    guard.links = {link("on_alert", "Seen", "show"), link("on_death", "Down", "show")};
    const int guard_id = guard.id;
    auto g = make_game(lv);
    const Vec3 start = g->robots()[0].feet;
    run_for(*g, 2.0); // the player stands 15 away in plain sight, inside its eye radius
    CHECK(g->robots()[0].dormant);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
    CHECK(glm::length(g->robots()[0].feet - start) < 0.05f);
    REQUIRE(g->run_action(level::LinkAction::Activate, guard_id));
    CHECK_FALSE(g->robots()[0].dormant);
    int alerted = 0;
    for (int i = 0; i < 60; ++i) {
        g->step({});
        alerted += shown(*g, "seen");
    }
    CHECK(alerted == 1);
    CHECK(g->robots()[0].mode != RobotMode::Idle);
    REQUIRE(g->run_action(level::LinkAction::Kill, guard_id));
    CHECK_FALSE(g->robots()[0].alive());
    CHECK(shown(*g, "down") == 1);
    // Gone: orders do nothing, and nothing fires twice.
    for (auto action : {level::LinkAction::Alert, level::LinkAction::Activate, level::LinkAction::Kill})
        CHECK(g->run_action(action, guard_id));
    run_for(*g, 3.0);
    CHECK(g->robots()[0].mode == RobotMode::Dead);
    CHECK(g->robots()[0].health == 0.0f);
    CHECK(g->robots_killed() == 1);
}

TEST_CASE("alert wakes a dormant robot and sends it after the player; any damage wakes one too") {
    auto lv = flat_level();
    add_blind_robot(lv, "Far", Vec3(0, 0, -60)).as<level::RobotProps>().hit_probability = 0.0f;
    add_blind_robot(lv, "Near", Vec3(10, 0, -10));
    const int far_id = lv.entities[1].id;
    auto g = make_game(lv);
    run_for(*g, 0.5);
    REQUIRE(g->run_action(level::LinkAction::Alert, far_id));
    run_for(*g, 2.0);
    CHECK(g->robots()[0].feet.z > -50.0f); // walking toward the player
    CHECK(g->robots()[1].dormant);
    g->damage_robot(1, 10.0f, false);
    g->step({});
    CHECK_FALSE(g->robots()[1].dormant);
}

TEST_CASE("a pickup's on_pickup fires when taken, once; a taken pickup does nothing more") {
    auto lv = flat_level();
    add_message(lv, "Got", "got it");
    auto& pickup = lv.add(level::EntityType::Pickup, Vec3(0, 0, -6), "Medkit");
    pickup.links = {link("on_pickup", "Got", "show")};
    auto g = make_game(lv);
    g->damage_player(50.0f);
    g->teleport_player(Vec3(0, 0, -6), 0.0f);
    int got = 0;
    for (int i = 0; i < 30; ++i) {
        g->step({});
        got += shown(*g, "got it");
    }
    CHECK(got == 1);
    CHECK(g->pickups()[0].taken);
    g->teleport_player(Vec3(0, 0, 0), 0.0f);
    run_for(*g, 0.2);
    g->teleport_player(Vec3(0, 0, -6), 0.0f);
    for (int i = 0; i < 30; ++i) {
        g->step({});
        got += shown(*g, "got it");
    }
    CHECK(got == 1);
}

TEST_CASE("play: a sound emitter plays once, heard through the event's cue") {
    auto lv = flat_level();
    auto& siren = lv.add(level::EntityType::Sound, Vec3(4, 3, -8), "Siren").as<level::SoundProps>();
    siren = {{"alarm_loop"}, 0.5f, 20.0f, true};
    lv.links = {link("on_start", "Siren", "play")};
    auto g = make_game(lv);
    g->step({});
    REQUIRE(count_events(*g, EventType::SoundPlayed) == 1);
    std::vector<SoundCue> cues;
    sound_cues(*g, g->events(), cues);
    const auto cue =
        std::find_if(cues.begin(), cues.end(), [](const SoundCue& c) { return c.sound == "alarm_loop"; });
    REQUIRE(cue != cues.end());
    CHECK(cue->volume == 0.5f);
    CHECK(cue->position == Vec3(4, 3, -8));
    CHECK(cue->positional);
    g->step({});
    CHECK(count_events(*g, EventType::SoundPlayed) == 0);
}

TEST_CASE("the level's win and lose actions end the game") {
    auto lv = flat_level();
    auto g = make_game(lv);
    g->step({});
    REQUIRE(g->run_action(level::LinkAction::Win, -1));
    CHECK(g->phase() == Phase::Won);
    auto h = make_game(lv);
    h->step({});
    REQUIRE(h->run_action(level::LinkAction::Lose, -1));
    CHECK(h->phase() == Phase::Dead);
    CHECK(count_events(*h, EventType::PlayerDied) == 1);
    // Over, nothing more happens.
    CHECK(h->run_action(level::LinkAction::Win, -1));
    CHECK(h->phase() == Phase::Dead);
}
