// What the player hears: game events and the sound cues made from them (game/sound_cues.h). The game only
// emits events; these tests read them and the cues directly, without an audio device.
#include "game/sound_cues.h"
#include "game_test_levels.h"
#include "level/level_io.h"

#include <algorithm>
#include <string>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// Steps `seconds` with one input and collects the cues of every step.
std::vector<SoundCue> cues_over(Game& g, double seconds, const Input& in = {}) {
    std::vector<SoundCue> all, step;
    const auto n = static_cast<int>(seconds / g.settings().step + 0.5);
    for (int i = 0; i < n; ++i) {
        g.step(in);
        sound_cues(g, g.events(), step);
        all.insert(all.end(), step.begin(), step.end());
    }
    return all;
}

int count(const std::vector<SoundCue>& cues, std::string_view sound) {
    return static_cast<int>(
        std::count_if(cues.begin(), cues.end(), [&](const SoundCue& c) { return c.sound == sound; }));
}

const SoundCue* find(const std::vector<SoundCue>& cues, std::string_view sound) {
    for (const SoundCue& c : cues)
        if (c.sound == sound) return &c;
    return nullptr;
}

} // namespace

TEST_CASE("the rifle: a shot is a rifle_shot at the player, a wall hit an impact there, empty is a click") {
    auto lv = flat_level();
    add_wall(lv, Vec3(0, 0, -20), Vec3(40, 16, 1));
    GameOptions options;
    options.settings.start_ammo = 1;
    auto created = Game::create(lv, options);
    REQUIRE(created.ok());
    Game& g = **created;
    Input fire;
    fire.fire = true;
    auto cues = cues_over(g, 1.0 / 120, fire);
    const SoundCue* shot = find(cues, "rifle_shot");
    REQUIRE(shot);
    CHECK_FALSE(shot->positional); // the player's own rifle sits on the listener
    CHECK(shot->priority == SoundPriority::Critical);
    const SoundCue* impact = find(cues, "impact");
    REQUIRE(impact);
    CHECK(impact->positional);
    CHECK(impact->position.z == doctest::Approx(-19.5f).epsilon(0.02)); // the wall's face
    CHECK(count(cues, "dry_fire") == 0);

    cues = cues_over(g, 1.0 / 120, fire); // the magazine is empty now
    CHECK(count(cues, "dry_fire") == 1);
    CHECK(count(cues, "rifle_shot") == 0);
}

TEST_CASE("footsteps follow the speed: half speed, half as many; none standing; stairs sound different") {
    auto steps_at = [](float forward) {
        auto g = make_game(flat_level());
        run_for(*g, 0.5); // settle on the ground
        Input walk;
        walk.move_forward = forward;
        return count(cues_over(*g, 4.0, walk), "footstep_floor");
    };
    const int full = steps_at(1.0f), half = steps_at(0.5f), still = steps_at(0.0f);
    // 15 units/s over 4 s with a 5-unit stride.
    CHECK(full == 12);
    CHECK(half == 6);
    CHECK(still == 0);

    auto lv = flat_level();
    auto& stair = lv.add(level::EntityType::Stair, Vec3(0, 0, -12), "stair");
    stair.as<level::StairProps>().size = Vec3(12, 6, 20);
    auto g = make_game(lv);
    run_for(*g, 0.5);
    Input walk;
    walk.move_forward = 1.0f;
    const auto cues = cues_over(*g, 1.6, walk);
    CHECK(count(cues, "footstep_stairs") >= 2);
    CHECK(g->player().feet.y > 2.0f); // really climbed
    for (const SoundCue& c : cues)
        if (c.sound.starts_with("footstep")) {
            CHECK(c.pitch >= 0.94f);
            CHECK(c.pitch <= 1.06f);
            CHECK(c.priority == SoundPriority::Footstep);
        }
}

TEST_CASE("a jump and its landing: one jump cue, one land cue louder for a longer fall") {
    auto g = make_game(flat_level());
    run_for(*g, 0.5);
    Input jump;
    jump.jump = true;
    auto cues = cues_over(*g, 1.0 / 120, jump);
    CHECK(count(cues, "jump") == 1);
    cues = cues_over(*g, 3.0);
    REQUIRE(count(cues, "land") == 1);
    const float hop = find(cues, "land")->volume;
    CHECK(count(cues, "footstep_floor") == 0);

    // A drop from 20 units lands harder.
    g->teleport_player(Vec3(0, 20, 0), 0.0f, 0.0f);
    cues = cues_over(*g, 4.0);
    REQUIRE(count(cues, "land") == 1);
    CHECK(find(cues, "land")->volume > hop);
    // Walking on flat ground never "lands".
    Input walk;
    walk.move_forward = 1.0f;
    CHECK(count(cues_over(*g, 2.0, walk), "land") == 0);
}

TEST_CASE("a robot's shot sounds from its shooting clip's muzzle_flash event, once per shot, at the robot") {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -8));
    r.as<level::RobotProps>().hit_probability = 0.0f; // no damage: only the shots are counted
    r.as<level::RobotProps>().cooldown = 1.0f;
    auto g = make_game(lv);
    int shots = 0, cues_heard = 0;
    std::vector<SoundCue> cues;
    for (int i = 0; i < 6 * 120; ++i) {
        g->step({});
        shots += count_events(*g, EventType::RobotShot);
        sound_cues(*g, g->events(), cues);
        for (const SoundCue& c : cues)
            if (c.sound == "robot_shot") {
                ++cues_heard;
                CHECK(c.positional);
                CHECK(c.entity == r.id);
                CHECK(glm::length(c.position - g->robots()[0].feet) < 3.0f);
            }
    }
    CHECK(shots >= 3);
    CHECK(cues_heard == shots);
}

TEST_CASE("shield and health: a hit the shield takes sounds as a shield hit; the overflow also hurts") {
    auto lv = flat_level();
    auto& shield = lv.add(level::EntityType::Pickup, Vec3(0, 0, -3), "shield");
    shield.as<level::PickupProps>().kind.value = "shield";
    shield.as<level::PickupProps>().amount = 30;
    auto g = make_game(lv);
    Input walk;
    walk.move_forward = 1.0f;
    auto cues = cues_over(*g, 0.5, walk);
    CHECK(count(cues, "pickup_shield") == 1);
    std::vector<SoundCue> step;
    g->damage_player(20.0f); // all absorbed
    sound_cues(*g, g->events(), step);
    g->step({}); // damage_player pushes into this step's list; take the events before they clear
    CHECK(count(step, "shield_hit") == 1);
    CHECK(count(step, "player_hurt") == 0);
    g->damage_player(25.0f); // 10 absorbed, 15 to health
    sound_cues(*g, g->events(), step);
    CHECK(count(step, "shield_hit") == 1);
    CHECK(count(step, "player_hurt") == 1);
    g->damage_player(1000.0f);
    sound_cues(*g, g->events(), step);
    CHECK(count(step, "player_death") == 1);
}

TEST_CASE(
    "level logic is heard: a locked door refuses at the door, an objective and a message are the player's") {
    level::LoadReport report;
    auto lv = level::load_level_file(ks::test::data_dir() / "levels" / "logic_hall.json", &report);
    REQUIRE_MESSAGE(lv.ok(), report.str());
    auto g = make_game(*lv);
    std::vector<SoundCue> step;
    g->step({}); // on_start shows the welcome message
    sound_cues(*g, g->events(), step);
    REQUIRE(count(step, "message_shown") == 1);
    CHECK_FALSE(find(step, "message_shown")->positional);

    g->teleport_player(Vec3(0, 0, -25), 0.0f); // at the locked exit
    g->step({});
    Input use;
    use.interact = true;
    g->step(use);
    sound_cues(*g, g->events(), step);
    REQUIRE(count(step, "door_locked") == 1);
    const SoundCue& locked = *find(step, "door_locked");
    CHECK(locked.positional);
    CHECK(locked.entity == 12);
    CHECK(locked.position.z == doctest::Approx(-30.0f));

    REQUIRE(g->complete_objective("clear_hall"));
    sound_cues(*g, g->events(), step);
    REQUIRE(count(step, "objective_complete") == 1);
    CHECK_FALSE(find(step, "objective_complete")->positional);
    CHECK(find(step, "objective_complete")->priority == SoundPriority::Critical);
}

TEST_CASE("every event sound is a name of the sound list, and cues are deterministic") {
    for (std::string_view name : event_sound_names()) {
        CHECK_FALSE(name.empty());
        CHECK(name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string_view::npos);
    }
    auto run = [] {
        auto g = make_game(flat_level());
        Input in;
        in.move_forward = 1.0f;
        in.fire = true;
        std::vector<std::string> heard;
        for (const SoundCue& c : cues_over(*g, 2.0, in))
            heard.push_back(std::string(c.sound) + "@" + std::to_string(c.pitch));
        return heard;
    };
    const auto a = run();
    CHECK_FALSE(a.empty());
    CHECK(a == run());
}
