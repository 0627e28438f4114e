#pragma once
// Small levels built in code for the game's scenario tests, and a helper that builds a Game from one.
#include "game/game.h"
#include "game/headless.h"
#include "level/level.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <memory>

namespace ks::game_test {
using namespace ks::game;

// A 200 x 200 ground floor at y 0, player at the origin facing -z, no robots.
inline level::Level flat_level() {
    level::Level lv;
    lv.name = "test flat";
    auto& floor = lv.add(level::EntityType::Floor, Vec3(0.0f), "ground");
    floor.as<level::FloorProps>().size = Vec2(200.0f, 200.0f);
    lv.player_start.position = Vec3(0.0f);
    return lv;
}

inline level::Entity& add_robot(level::Level& lv, Vec3 feet, float yaw_degrees = 0.0f) {
    auto& r = lv.add(level::EntityType::Robot, feet, "robot");
    r.rotation.x = yaw_degrees;
    return r;
}

inline level::Entity& add_wall(level::Level& lv, Vec3 base, Vec3 size, float yaw_degrees = 0.0f) {
    auto& w = lv.add(level::EntityType::Wall, base, "wall");
    w.as<level::WallProps>().size = size;
    w.rotation.x = yaw_degrees;
    return w;
}

inline std::unique_ptr<Game> make_game(const level::Level& lv, std::uint64_t seed = 1) {
    GameOptions options;
    options.seed = seed;
    auto g = Game::create(lv, options);
    if (!g) FAIL(g.error().str());
    return std::move(*g);
}

// Steps `seconds` of simulated time with the same input each step.
inline void run_for(Game& g, double seconds, const Input& in = {}) {
    const auto n = static_cast<int>(seconds / g.settings().step + 0.5);
    for (int i = 0; i < n; ++i) g.step(in);
}

// Plays `level` with the autoplay bot for `seconds` while recording into `dir`, then replays the recording.
struct RecordedRun {
    HeadlessStats recorded, replayed;
};
inline RecordedRun record_and_replay(const std::filesystem::path& level, double seconds, std::uint64_t seed,
                                     const std::filesystem::path& dir,
                                     const std::filesystem::path& stats_json = {}) {
    HeadlessOptions rec;
    rec.level = level;
    rec.seconds = seconds;
    rec.seed = seed;
    rec.autoplay = true;
    rec.record = dir / "run.replay";
    rec.stats_json = stats_json;
    auto recorded = run_headless(rec);
    if (!recorded) FAIL(recorded.error().str());
    HeadlessOptions play;
    play.level = rec.level;
    play.replay = rec.record;
    auto replayed = run_headless(play);
    if (!replayed) FAIL(replayed.error().str());
    return {*recorded, *replayed};
}

inline int count_events(const Game& g, EventType type) {
    int n = 0;
    for (const Event& e : g.events())
        if (e.type == type) ++n;
    return n;
}

// Level logic helpers: a message entity, a link, what the HUD's message line shows now.
inline level::Entity& add_message(level::Level& lv, const char* name, const char* text,
                                  float duration = 2.0f) {
    auto& m = lv.add(level::EntityType::Message, Vec3(0, 2, 0), name);
    m.as<level::MessageProps>() = {text, duration};
    return m;
}

inline level::Link link(const char* event, const char* target, const char* action, float delay = 0.0f,
                        bool once = false) {
    return {event, target, action, delay, once};
}

inline std::string on_screen(const Game& g) {
    return g.logic().message().visible() ? std::string(g.logic().message().text) : std::string();
}

// MessageShown events of the last step with this text.
inline int shown(const Game& g, std::string_view text) {
    int n = 0;
    for (const Event& e : g.events())
        if (e.type == EventType::MessageShown && e.cue == text) ++n;
    return n;
}

// A trigger box `size` at `at`, set off by `who` ("player", "robots", "both").
inline level::Entity& add_trigger(level::Level& lv, const char* name, Vec3 at, Vec3 size,
                                  const char* who = "player") {
    auto& t = lv.add(level::EntityType::Trigger, at, name);
    t.as<level::TriggerProps>().size = size;
    t.as<level::TriggerProps>().who.value = who;
    return t;
}

// One frame's input with E (interact) pressed.
// `lv` has a way up (a stair, a ramp) from the start toward -z onto a platform 6 high beyond z = -16: the
// player walks forward onto it, then a robot standing at (0, 0, 3), angered, chases up after.
inline void check_climb_to_platform(level::Level lv) {
    auto& r = add_robot(lv, Vec3(0, 0, 3));
    r.as<level::RobotProps>().shooting_distance = 1.0f;
    r.as<level::RobotProps>().hit_probability = 0.0f;
    auto g = make_game(lv);
    run_for(*g, 1.4, Input{1.0f});
    CHECK(g->player().feet.y == doctest::Approx(6.0f).epsilon(0.02));
    CHECK(g->player().feet.z < -16.0f);
    g->damage_robot(0, 1.0f, true); // angry: chases wherever the player is
    run_for(*g, 4.0);
    CHECK(g->robots()[0].feet.y == doctest::Approx(6.0f).epsilon(0.02));
    CHECK(g->robots()[0].feet.z < -16.0f);
}

inline Input press_e() {
    Input in;
    in.interact = true;
    return in;
}

} // namespace ks::game_test
