// The robot's shot is timed by its shooting clip: the ray, the RobotShot event and the damage happen when the
// clip passes its muzzle_flash event, read from a copy of assets/animations/robot.json; the cooldown starts
// when the clip does. A clip without the event still fires, at its start, with one warning at load.
#include "anim/clip_io.h"
#include "core/log.h"
#include "core/paths.h"
#include "game/robot_rig.h"
#include "game_test_levels.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <memory>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// The shipped clip file with the shooting clip's events replaced, saved into `dir` and loaded back the
// way the game loads its clips.
std::shared_ptr<const anim::AnimationLibrary>
clips_with_shot_events(const ks::test::ScratchDir& dir, const std::vector<anim::ClipEvent>& events) {
    auto file = anim::load_animation_file(paths::asset("animations/robot.json"));
    REQUIRE(file);
    auto shooting = std::find_if(file->clips.begin(), file->clips.end(),
                                 [](const anim::ClipDef& c) { return c.name == "shooting"; });
    REQUIRE(shooting != file->clips.end());
    shooting->events = events;
    const auto copy = dir / "robot.json";
    REQUIRE(anim::save_animation_file(copy, *file));
    auto lib = load_robot_animations(copy);
    REQUIRE_MESSAGE(lib, (lib ? std::string() : lib.error().str()));
    return *lib;
}

// A step covers (t, t + 1/120]; the robot starts its shooting clip as step N begins, and a RobotShot comes in
// the step that reaches its event's time: an event at 0 s in step N itself, one at 0.15 s in the step that
// ends 0.15 s (18 steps) after the clip started, step N + 17.
struct ShotLog {
    std::vector<int> delays; // steps of game time from the clip's start to the end of each RobotShot's step
    float health = 0.0f;
};

// A robot 8 units in front of the player that always hits, one shot a second, for `seconds`.
// `after_play` runs on the step the shooting clip starts (the robot's cooldown restarts then).
ShotLog shoot_at_player(std::shared_ptr<const anim::AnimationLibrary> lib, double seconds,
                        const std::function<void(Game&)>& after_play = {}) {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -8));
    r.as<level::RobotProps>().hit_probability = 1.0f;
    r.as<level::RobotProps>().cooldown = 1.0f;
    GameOptions options;
    options.animations = std::move(lib);
    auto created = Game::create(lv, options);
    REQUIRE(created);
    Game& g = **created;
    ShotLog log;
    std::int64_t clip_start = -1;
    float cooldown = 0.0f;
    const auto steps = static_cast<int>(seconds * 120.0);
    for (int i = 0; i < steps; ++i) {
        g.step({});
        const float now = g.robots()[0].cooldown;
        if (now > cooldown + 0.5f) {
            clip_start = g.steps() - 1; // the clip starts as its step begins
            CHECK(g.robot_animation_clip(0) == g.animations().clips.find("shooting"));
            if (after_play) after_play(g);
        }
        cooldown = now;
        for (const Event& e : g.events())
            if (e.type == EventType::RobotShot) {
                REQUIRE(clip_start >= 0);
                log.delays.push_back(static_cast<int>(g.steps() - clip_start));
            }
    }
    log.health = g.player().health;
    return log;
}

} // namespace

TEST_CASE("robot shot timing: the shot fires at the shooting clip's muzzle_flash event, not at its start") {
    ks::test::ScratchDir dir;
    SUBCASE("the shipped clip: the flash at 0 s fires in the step the clip starts (as the shot did before)") {
        const ShotLog shots =
            shoot_at_player(clips_with_shot_events(dir, {{0.0, "muzzle_flash", "robot_shot"}}), 6);
        REQUIRE(shots.delays.size() >= 4);
        for (int d : shots.delays) CHECK(d == 1);
        CHECK(shots.health == doctest::Approx(100.0f - 10.0f * static_cast<float>(shots.delays.size())));
    }
    SUBCASE(
        "the flash moved to 0.15 s: each shot in the step ending 0.15 s (18 steps) after the clip start") {
        const ShotLog shots =
            shoot_at_player(clips_with_shot_events(dir, {{0.15, "muzzle_flash", "robot_shot"}}), 6);
        REQUIRE(shots.delays.size() >= 4);
        for (int d : shots.delays) CHECK(d == 18); // 0.15 s at 120 steps a second
        CHECK(shots.health == doctest::Approx(100.0f - 10.0f * static_cast<float>(shots.delays.size())));
    }
    SUBCASE("two flashes: two shots per clip, the cooldown still one per second") {
        const ShotLog shots = shoot_at_player(
            clips_with_shot_events(dir, {{0.0, "muzzle_flash", "robot_shot"}, {0.25, "muzzle_flash", ""}}),
            4);
        REQUIRE(shots.delays.size() >= 6);
        for (std::size_t i = 0; i < shots.delays.size(); ++i) CHECK(shots.delays[i] == (i % 2 == 0 ? 1 : 30));
    }
    SUBCASE("other events do not shoot") {
        const ShotLog shots =
            shoot_at_player(clips_with_shot_events(
                                dir, {{0.1, "muzzle_flash", "robot_shot"}, {0.05, "footstep", "robot_shot"}}),
                            4);
        REQUIRE(shots.delays.size() >= 3);
        for (int d : shots.delays) CHECK(d == 12); // at the flash's 0.1 s, not the footstep's 0.05 s
    }
}

TEST_CASE("robot shot timing: a robot killed before its clip's flash never fires that shot") {
    ks::test::ScratchDir dir;
    int plays = 0;
    const ShotLog shots =
        shoot_at_player(clips_with_shot_events(dir, {{0.15, "muzzle_flash", "robot_shot"}}), 3, [&](Game& g) {
            ++plays;
            g.damage_robot(0, 1000.0f, true);
        });
    CHECK(plays == 1);
    CHECK(shots.delays.empty());
    CHECK(shots.health == 100.0f);
}

TEST_CASE(
    "robot shot timing: a shooting clip without a muzzle_flash fires at its start, warned once at load") {
    ks::test::ScratchDir dir;
    auto lib = clips_with_shot_events(dir, {{0.1, "footstep", ""}});
    ShotLog shots;
    {
        log::Capture captured;
        auto lv = flat_level();
        add_robot(lv, Vec3(0, 0, -60));
        GameOptions options;
        options.animations = lib;
        auto g = Game::create(lv, options);
        REQUIRE(g);
        run_for(**g, 1.0);
        CHECK(captured.count(log::Level::Warn) == 1);
        CHECK(captured.text().find("robot.json") != std::string::npos);
        CHECK(captured.text().find("\"shooting\" clip has no \"muzzle_flash\" event") != std::string::npos);
        CHECK(captured.text().find("\"name\": \"muzzle_flash\"") != std::string::npos); // the fix
    }
    shots = shoot_at_player(lib, 6);
    REQUIRE(shots.delays.size() >= 4);        // the robots are not disarmed
    for (int d : shots.delays) CHECK(d == 1); // in the step the clip starts
    CHECK(shots.health == doctest::Approx(100.0f - 10.0f * static_cast<float>(shots.delays.size())));

    // The shipped file has the event: no warning.
    log::Capture quiet;
    auto lv = flat_level();
    auto g = Game::create(lv);
    REQUIRE(g);
    CHECK(quiet.count(log::Level::Warn) == 0);
}
