// Determinism: equal seeds give equal state hashes; a recorded run replays to the same final hash; shipped
// levels build; bad files and options give clear errors.
#include "game/autoplay.h"
#include "game/headless.h"
#include "game/replay.h"
#include "game_test_levels.h"
#include "level/level_io.h"

#include <string>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

level::Level shipped(const char* name) {
    auto lv = level::load_level_file(ks::test::source_dir() / "levels" / name);
    if (!lv) FAIL(lv.error().str());
    return std::move(*lv);
}

std::uint64_t hash_after(const level::Level& lv, std::uint64_t seed, double seconds) {
    auto g = make_game(lv, seed);
    auto bot = Autoplay::create(lv, *g, seed);
    if (!bot) FAIL(bot.error().str());
    const int steps = static_cast<int>(seconds * 120);
    for (int i = 0; i < steps && g->phase() == Phase::Playing; ++i) g->step(bot->decide(*g));
    return g->state_hash();
}

} // namespace

TEST_CASE("the same seed gives the same state hash; another seed another one") {
    const auto lv = shipped("main.json");
    const auto a = hash_after(lv, 7, 6.0);
    CHECK(a == hash_after(lv, 7, 6.0));
    CHECK(a != hash_after(lv, 8, 6.0)); // robots wander differently
}

TEST_CASE("a recorded autoplay run replays to the exact final state hash") {
    ks::test::ScratchDir dir;
    const auto [recorded, replayed] = record_and_replay(ks::test::source_dir() / "levels/main.json", 12.0, 5,
                                                        dir.path(), dir / "stats.json");
    CHECK(replayed.state_hash == recorded.state_hash);
    CHECK(replayed.steps == recorded.steps);
    CHECK(replayed.shots == recorded.shots);
    CHECK(replayed.outcome == recorded.outcome);
    const std::string json = ks::test::read_file(dir / "stats.json");
    for (const char* key : {"\"outcome\"", "\"sim_time_s\"", "\"robots_killed\"", "\"damage_taken\"",
                            "\"shots\"", "\"steps_per_second\"", "\"state_hash\""})
        CHECK(json.find(key) != std::string::npos);

    SUBCASE("an edited replay no longer matches") {
        auto r = load_recording_file(dir / "run.replay");
        REQUIRE(r.ok());
        REQUIRE(r->inputs.size() > 200);
        r->inputs[100].look_yaw += 0.01f;
        REQUIRE(save_recording_file(dir / "edited.replay", *r).ok());
        HeadlessOptions play;
        play.level = ks::test::source_dir() / "levels/main.json";
        play.replay = dir / "edited.replay";
        auto edited = run_headless(play);
        REQUIRE(edited.ok());
        CHECK(edited->state_hash != recorded.state_hash);
    }
}

TEST_CASE("recordings round-trip bit-exactly and bad ones are reported with file and line") {
    Recording r;
    r.seed = 99;
    r.level = "levels/main.json";
    Input a;
    a.move_forward = 0.1f;
    a.look_yaw = -1.0e-7f;
    a.look_pitch = 3.14159274f;
    a.fire = a.jump = true;
    Input b;
    b.interact = b.pause = true;
    r.inputs = {a, b, Input{}};
    auto back = load_recording_string(save_recording_string(r), "mem");
    REQUIRE(back.ok());
    CHECK(back->seed == 99);
    CHECK(back->inputs == r.inputs);

    auto bad = [](const std::string& text) {
        auto res = load_recording_string(text, "bad.replay");
        REQUIRE_FALSE(res.ok());
        CHECK(res.error().where.file == "bad.replay");
        return res.error();
    };
    CHECK(bad("hello\n").where.line == 1);
    CHECK(bad("killswitch-replay 1\nseed x\n").where.line == 2);
    const Error nan = bad("killswitch-replay 1\nseed 1\nlevel a\nsteps 1\nnan 0 0 0 -\n");
    CHECK(nan.where.line == 5);
    CHECK(bad("killswitch-replay 1\nseed 1\nlevel a\nsteps 1\n0 0 0 0 z\n").message.find("flag") !=
          std::string::npos);
    CHECK(bad("killswitch-replay 1\nseed 1\nlevel a\nsteps 3\n0 0 0 0 -\n").message.find("3") !=
          std::string::npos);
    // The difficulty a run was recorded on: a header line only when not Normal (older files stay as they
    // were), read back; a bad word is refused on its line.
    CHECK(save_recording_string(r).find("difficulty") == std::string::npos);
    CHECK(back->difficulty == Difficulty::Normal);
    r.difficulty = Difficulty::Hard;
    auto hard = load_recording_string(save_recording_string(r), "mem");
    REQUIRE(hard.ok());
    CHECK(hard->difficulty == Difficulty::Hard);
    CHECK(hard->inputs == r.inputs);
    const Error word = bad("killswitch-replay 1\nseed 1\nlevel a\ndifficulty brutal\nsteps 0\n");
    CHECK(word.where.line == 4);
    CHECK(word.message.find("brutal") != std::string::npos);
}

TEST_CASE("headless options: parsing, conflicts and missing files are errors, not crashes") {
    auto parse = [](std::vector<const char*> args) {
        args.insert(args.begin(), "killswitch");
        auto cl = CommandLine::parse(static_cast<int>(args.size()), args.data(), headless_flags());
        REQUIRE(cl.ok());
        return parse_headless_options(*cl);
    };
    auto ok = parse({"--headless", "--level", "levels/main.json", "--seconds", "30", "--seed", "12",
                     "--autoplay", "--stats-json", "-"});
    REQUIRE(ok.ok());
    CHECK(ok->seconds == 30.0);
    CHECK(ok->seed == 12);
    CHECK(ok->autoplay);
    CHECK(ok->stats_json == "-");
    CHECK_FALSE(parse({"--seconds", "-3"}).ok());
    CHECK_FALSE(parse({"--seconds", "nan"}).ok());
    CHECK_FALSE(parse({"--seed", "abc"}).ok());
    CHECK_FALSE(parse({"--record", "a", "--replay", "b"}).ok());
    CHECK_FALSE(parse({"--autoplay", "--replay", "b"}).ok());

    HeadlessOptions missing;
    missing.level = ks::test::source_dir() / "levels/does_not_exist.json";
    auto r = run_headless(missing);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str().find("does_not_exist") != std::string::npos);
    HeadlessOptions no_replay;
    no_replay.level = ks::test::source_dir() / "levels/main.json";
    no_replay.replay = ks::test::source_dir() / "no_such.replay";
    CHECK_FALSE(run_headless(no_replay).ok());
}

TEST_CASE("shipped levels build into games with the reference's entities") {
    auto main_game = make_game(shipped("main.json"));
    CHECK(main_game->robots().size() == 8);
    CHECK(main_game->doors().size() == 2);
    CHECK(main_game->pickups().size() == 3);
    CHECK(main_game->cylinders().size() == 6);
    CHECK(main_game->panels().size() == 1);
    CHECK(main_game->lights().size() == 11);
    CHECK(main_game->player().feet == Vec3(0, 0, 25));
    run_for(*main_game, 2.0);
    CHECK(main_game->player().feet.y == doctest::Approx(0.0f).epsilon(0.02)); // stands on the ground
    for (const Robot& r : main_game->robots()) CHECK(r.feet.y >= -0.1f);
    // The dojo's robot is an animation dummy: not simulated by the game.
    auto dojo = make_game(shipped("dojo.json"));
    CHECK(dojo->robots().empty());
    CHECK(dojo->pickups().size() == 3);
    run_for(*dojo, 1.0);
    CHECK(dojo->phase() == Phase::Playing);
}

TEST_CASE("without input the player survives standing at the main level's start") {
    auto g = make_game(shipped("main.json"), 3);
    run_for(*g, 30.0);
    CHECK(g->phase() == Phase::Playing); // room 1 has no robots; door 1 stays closed
}

TEST_CASE("headless outcomes: death when robots win, timeout when nothing happens; stats JSON on stdout") {
    ks::test::ScratchDir dir;
    auto lv = flat_level();
    for (float x : {-3.0f, 0.0f, 3.0f})
        add_robot(lv, Vec3(x, 0, -8)).as<level::RobotProps>().hit_probability = 1.0f;
    REQUIRE(level::save_level_file(dir / "ambush.json", lv).ok());
    HeadlessOptions o;
    o.level = dir / "ambush.json";
    o.seconds = 30.0;
    auto death = run_headless(o);
    if (!death) FAIL(death.error().str());
    CHECK(death->outcome == "death");
    CHECK(death->damage_taken >= 100.0f);
    CHECK(death->sim_time_s < 30.0);

    REQUIRE(level::save_level_file(dir / "empty.json", flat_level()).ok());
    o.level = dir / "empty.json";
    o.seconds = 2.0;
    auto timeout = run_headless(o);
    REQUIRE(timeout.ok());
    CHECK(timeout->outcome == "timeout");
    CHECK(timeout->steps == 240);
    CHECK(timeout->sim_time_s == doctest::Approx(2.0));

    // The binary-level contract: one JSON object with the seven keys.
    const std::string json = timeout->to_json();
    CHECK(json.front() == '{');
    CHECK(json.find("\"outcome\":\"timeout\"") != std::string::npos);
    CHECK(json.find('\n') == std::string::npos);
}
