// Loop mode ping_pong: forward, then backward to the start, forever. The pose at t equals the pose at 2d - t
// (and repeats every 2d from the same start), the turn does not jump, the rate flips sign on the way back,
// events fire on both passes (once at a turn), and the clip never finishes.
#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rotation.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::anim;

namespace {

constexpr double kLength = 0.8; // the clip's duration d

// A three-node rig and a ping-pong clip of two phases (0.3 s then 0.5 s), absolute and relative keys, with
// events at the start, inside, and at the end.
AnimationFile sway_file() {
    AnimationFile f;
    f.rig = {{"robot", "", DVec3(0), DVec3(0)},
             {"chest", "robot", DVec3(0, 1, 0), DVec3(0)},
             {"head", "chest", DVec3(0, 0.5, 0), DVec3(0)}};
    f.rest_nodes = {"chest", "head"};
    ClipDef sway;
    sway.name = "sway";
    sway.loop = LoopMode::PingPong;
    PhaseDef lean{0.3, Ease::named(EaseFamily::Quadratic, EaseMode::InOut), {}};
    TargetDef chest;
    chest.node = "chest";
    chest.rot = DVec3(0, 0, 40);
    chest.pos = DVec3(0, 0.2, 0);
    lean.targets.push_back(chest);
    PhaseDef look{0.5, Ease::named(EaseFamily::Cubic, EaseMode::Out), {}};
    TargetDef head;
    head.node = "head";
    head.add_rot = DVec3(0, 90, 0);
    look.targets.push_back(head);
    TargetDef chest_hold;
    chest_hold.node = "chest";
    chest_hold.add_rot = DVec3(0);
    look.targets.push_back(chest_hold);
    sway.phases = {lean, look};
    sway.events = {{0.0, "start", ""}, {0.2, "mid", "robot_step"}, {kLength, "end", ""}};
    f.clips = {sway};
    return f;
}

struct Compiled {
    Rig rig;
    ClipSet clips;
};
Compiled compiled(const AnimationFile& f) {
    REQUIRE(validate(f).empty());
    auto rig = build_rig(f);
    REQUIRE(rig.ok());
    auto clips = compile(f, *rig);
    REQUIRE(clips.ok());
    return {std::move(rig).value(), std::move(clips).value()};
}

struct Sample {
    std::vector<Vec3> euler, position, euler_rate, position_rate;
};
Sample sample(const Compiled& c, double t) {
    Pose rest;
    rest.set_rest(c.rig);
    Sample s{rest.euler, rest.position, rest.euler, rest.position};
    sample_clip(c.clips.clips[0], rest.euler, rest.position, t, s.euler, s.position, s.euler_rate,
                s.position_rate);
    return s;
}
float difference(const Sample& a, const Sample& b) {
    float d = 0;
    for (std::size_t i = 0; i < a.euler.size(); ++i)
        d = std::max({d, glm::length(a.euler[i] - b.euler[i]), glm::length(a.position[i] - b.position[i])});
    return d;
}

} // namespace

TEST_CASE("ping_pong: the pose at t equals the pose at 2d - t, and every 2d it starts over from the start") {
    const Compiled c = compiled(sway_file());
    REQUIRE(c.clips.clips[0].loop == LoopMode::PingPong);
    // The forward pass moves (a clip that stood still would pass every check below).
    CHECK(difference(sample(c, 0.0), sample(c, kLength)) > 0.5f);
    for (double t : {0.0, 0.05, 0.3, 0.31, 0.55, 0.79, kLength}) {
        INFO("t = " << t);
        CHECK(difference(sample(c, t), sample(c, 2 * kLength - t)) < 1e-5f);
        for (int cycle : {1, 2, 50}) // relative keys do not accumulate: each cycle retraces the first
            CHECK(difference(sample(c, t), sample(c, t + 2 * kLength * cycle)) < 1e-4f);
    }
    // Past the end it is not held (as a once clip would be): halfway back is the halfway-out pose.
    CHECK(difference(sample(c, kLength + 0.4), sample(c, kLength - 0.4)) < 1e-5f);
    CHECK(difference(sample(c, kLength + 0.4), sample(c, kLength)) > 0.1f);
}

TEST_CASE("ping_pong: no pose jump at either turn, and the rate flips sign on the way back") {
    const Compiled c = compiled(sway_file());
    constexpr double h = 1e-4;
    for (double turn : {kLength, 2 * kLength}) {
        INFO("turn at " << turn);
        CHECK(difference(sample(c, turn - h), sample(c, turn + h)) < 1e-3f);
    }
    // The analytic rate on the way back is the forward rate mirrored, and matches finite differences.
    for (double t : {0.1, 0.45, 0.7}) {
        const Sample out = sample(c, t), back = sample(c, 2 * kLength - t);
        const Sample before = sample(c, 2 * kLength - t - h), after = sample(c, 2 * kLength - t + h);
        for (std::size_t n = 0; n < out.euler.size(); ++n) {
            CHECK(glm::length(back.euler_rate[n] + out.euler_rate[n]) < 1e-4f);
            const Vec3 numeric = (after.euler[n] - before.euler[n]) / static_cast<float>(2 * h);
            CHECK(glm::length(numeric - back.euler_rate[n]) < 2e-2f);
        }
    }
}

TEST_CASE("ping_pong in a Player: events fire on both passes (once at a turn), in time order; it never "
          "finishes") {
    const Compiled c = compiled(sway_file());
    Player player(c.clips, c.rig);
    player.play(0, 0.0f);
    // One advance across a whole cycle lists it in order: out, and back.
    player.advance(2 * kLength);
    std::vector<std::string> names;
    for (const FiredEvent& e : player.fired_events()) names.push_back(e.event->name);
    CHECK(names == std::vector<std::string>{"start", "mid", "end", "mid", "start"});
    CHECK_FALSE(player.finished());

    // Frame by frame for two more cycles: each event at the time of its pass.
    std::vector<std::pair<double, std::string>> fired;
    for (int frame = 0; frame < 2 * 96; ++frame) { // 1.6 s cycles at 60 fps
        player.advance(1.0 / 60);
        for (const FiredEvent& e : player.fired_events()) fired.emplace_back(player.time(), e.event->name);
    }
    const std::vector<std::pair<double, std::string>> expected = {{1.8, "mid"},   {2.4, "end"},  {3.0, "mid"},
                                                                  {3.2, "start"}, {3.4, "mid"},  {4.0, "end"},
                                                                  {4.6, "mid"},   {4.8, "start"}};
    REQUIRE(fired.size() == expected.size());
    for (std::size_t i = 0; i < fired.size(); ++i) {
        CHECK(fired[i].first == doctest::Approx(expected[i].first).epsilon(1e-9));
        CHECK(fired[i].second == expected[i].second);
    }
    CHECK_FALSE(player.finished());
    CHECK(player.current_clip() == 0);
}

TEST_CASE("ping_pong in the file: read and written as \"ping_pong\"; zero length refused like a loop") {
    AnimationFile f = sway_file();
    const std::string text = save_animation_string(f);
    CHECK(text.find("\"loop\": \"ping_pong\"") != std::string::npos);
    auto reloaded = load_animation_string(text, "sway.json");
    REQUIRE(reloaded.ok());
    CHECK(reloaded->clips[0].loop == LoopMode::PingPong);
    CHECK(save_animation_string(*reloaded) == text);

    for (PhaseDef& p : f.clips[0].phases) p.duration = 0;
    f.clips[0].events.clear();
    const auto issues = validate(f);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].path.str() == "clips[0].phases");
    CHECK(issues[0].message == "ping-pong clip 'sway' has zero length");
}
