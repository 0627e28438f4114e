// Transitions: no pose jump when any clip interrupts any other at any moment, continuous velocity when
// blending, frame-rate independence, cross-fades, Next hand-overs and long-run stability.
#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rotation.h"
#include "anim_test_support.h"
#include "core/random.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <doctest/doctest.h>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::anim;
using ks::anim::test::robot_library;

namespace {

const char* const kSixClips[] = {"idle", "alert", "shoot_pose", "shooting", "shoot_pose_reverse", "death"};

int clip(const char* name) {
    int i = robot_library().clips.find(name);
    REQUIRE_MESSAGE(i >= 0, name);
    return i;
}

struct Jump {
    float rotation = 0; // largest per-node rotation change, radians
    float position = 0; // largest per-node translation change
};
Jump jump(const Pose& a, const Pose& b) {
    Jump j;
    for (int n = 0; n < a.size(); ++n) {
        const auto k = static_cast<std::size_t>(n);
        j.rotation = std::max(j.rotation, angle_between(a.rotation[k], b.rotation[k]));
        j.position = std::max(j.position, glm::length(a.position[k] - b.position[k]));
    }
    return j;
}

struct Rates {
    std::vector<Vec3> euler, position;
    explicit Rates(int n) : euler(static_cast<std::size_t>(n)), position(static_cast<std::size_t>(n)) {}
};
float largest_difference(const Rates& a, const Rates& b, float* largest_rate = nullptr) {
    float diff = 0, rate = 0;
    for (std::size_t i = 0; i < a.euler.size(); ++i) {
        diff = std::max(
            {diff, glm::length(a.euler[i] - b.euler[i]), glm::length(a.position[i] - b.position[i])});
        rate = std::max({rate, glm::length(a.euler[i]), glm::length(a.position[i])});
    }
    if (largest_rate) *largest_rate = rate;
    return diff;
}

} // namespace

TEST_CASE("interrupting each clip by each other clip at 100 random times never jumps the pose") {
    const AnimationLibrary& lib = robot_library();
    Rng rng(2024);
    float worst_rotation = 0, worst_position = 0;
    int interruptions = 0;
    for (bool library_blends : {true, false})
        for (const char* from : kSixClips)
            for (const char* to : kSixClips) {
                const float from_length = lib.clips.clips[static_cast<std::size_t>(clip(from))].duration;
                for (int i = 0; i < 100; ++i) {
                    // Random moments, plus the awkward ones: the start, phase boundaries, the very end.
                    double t = rng.uniform_double() * (from_length * 1.3 + 0.2);
                    if (i == 0) t = 0;
                    if (i == 1) t = 0.3;
                    if (i == 2) t = from_length;
                    if (i == 3) t = 0.9;
                    Player player(lib.clips, lib.rig);
                    player.play(clip("idle"), 0.0f); // a history, so the interrupted clip starts off-rest
                    player.advance(0.37);
                    player.play(clip(from));
                    player.advance(t);
                    const Pose before = player.pose();
                    if (library_blends)
                        player.play(clip(to));
                    else
                        player.play(clip(to), 0.0f);
                    const Jump j = jump(before, player.pose());
                    worst_rotation = std::max(worst_rotation, j.rotation);
                    worst_position = std::max(worst_position, j.position);
                    ++interruptions;
                    if (j.rotation >= 1e-5f || j.position >= 1e-5f) {
                        FAIL_CHECK(from << " -> " << to << " at t = " << t << ": jump " << j.rotation
                                        << " rad, " << j.position << " units");
                    }
                }
            }
    CHECK(interruptions == 2 * 6 * 6 * 100);
    MESSAGE("worst jump over ", interruptions, " interruptions: ", worst_rotation, " rad, ", worst_position,
            " units");
    CHECK(worst_rotation < 1e-5f);
    CHECK(worst_position < 1e-5f);
}

TEST_CASE("random chains of interruptions, also mid-blend and mid-cross-fade, never jump") {
    const AnimationLibrary& lib = robot_library();
    Rng rng(99);
    Player player(lib.clips, lib.rig);
    for (int step = 0; step < 3000; ++step) {
        player.advance(rng.uniform(0.0f, 0.25f));
        const Pose before = player.pose();
        const int next = clip(kSixClips[rng.below(6)]);
        switch (rng.below(3)) {
        case 0:
            player.play(next);
            break;
        case 1:
            player.play(next, rng.uniform(0.0f, 0.5f));
            break;
        default:
            player.crossfade(next, rng.uniform(0.01f, 0.5f));
            break;
        }
        const Jump j = jump(before, player.pose());
        REQUIRE(j.rotation < 1e-5f);
        REQUIRE(j.position < 1e-5f);
        for (const Quat& q : player.pose().rotation) REQUIRE(std::abs(glm::length(q) - 1.0f) < 1e-5f);
    }
}

TEST_CASE("with a blend time the velocity is continuous at the switch; without one it is not") {
    const AnimationLibrary& lib = robot_library();
    Rng rng(7);
    const int n = lib.rig.size();
    float worst_blended = 0, worst_cut = 0;
    for (const char* from : kSixClips)
        for (const char* to : kSixClips)
            for (int i = 0; i < 20; ++i) {
                const double t = rng.uniform_double() * 0.9;
                for (int mode = 0; mode < 3; ++mode) { // blended play, cross-fade, cut
                    Player player(lib.clips, lib.rig);
                    player.play(clip(from), 0.0f);
                    player.advance(t);
                    Rates before(n), after(n);
                    player.velocity(before.euler, before.position);
                    if (mode == 0) player.play(clip(to), 0.2f);
                    if (mode == 1) player.crossfade(clip(to), 0.2f);
                    if (mode == 2) player.play(clip(to), 0.0f);
                    player.velocity(after.euler, after.position);
                    float rate = 0;
                    const float diff = largest_difference(before, after, &rate);
                    if (mode < 2) {
                        worst_blended = std::max(worst_blended, diff / (1 + rate));
                        if (diff > 1e-4f * (1 + rate))
                            FAIL_CHECK(from << " -> " << to << " at " << t << " mode " << mode
                                            << ": rate jump " << diff << " (rates up to " << rate << ")");
                    } else {
                        worst_cut = std::max(worst_cut, diff);
                    }
                }
            }
    MESSAGE("relative velocity jump: blended ", worst_blended, ", cut (blend 0) ", worst_cut, " rad/s");
    CHECK(worst_blended < 1e-4f);
    CHECK(worst_cut > 1.0f); // the check above can fail: cutting does change the velocity
}

TEST_CASE("the analytic velocity matches finite differences of the pose, inside blends too") {
    const AnimationLibrary& lib = robot_library();
    const int n = lib.rig.size();
    Rng rng(31);
    for (int i = 0; i < 200; ++i) {
        Player player(lib.clips, lib.rig);
        player.play(clip(kSixClips[rng.below(6)]), 0.0f);
        player.advance(rng.uniform(0.0f, 1.0f));
        if (i % 2)
            player.play(clip(kSixClips[rng.below(6)]), 0.3f);
        else
            player.crossfade(clip(kSixClips[rng.below(6)]), 0.3f);
        player.advance(rng.uniform(0.001f, 0.4f));
        Rates analytic(n), numeric(n);
        player.velocity(analytic.euler, analytic.position);
        const double h = 1e-5;
        Player ahead = player; // the player is a value: a copy can look ahead without disturbing it
        ahead.advance(h);
        for (std::size_t k = 0; k < numeric.euler.size(); ++k) {
            numeric.euler[k] = (ahead.pose().euler[k] - player.pose().euler[k]) / static_cast<float>(h);
            numeric.position[k] =
                (ahead.pose().position[k] - player.pose().position[k]) / static_cast<float>(h);
        }
        float rate = 0;
        const float diff = largest_difference(analytic, numeric, &rate);
        CHECK_MESSAGE(diff < 0.05f + 0.02f * rate, "sample ", i, ": analytic vs numeric ", diff, " (rate ",
                      rate, ")");
    }
}

TEST_CASE("the same clips sampled at 30, 60, 144 and 240 fps land on identical poses at identical times") {
    const AnimationLibrary& lib = robot_library();
    struct Event {
        double time;
        const char* clip;
        int how; // 0 play (library blend), 1 play without blend, 2 cross-fade
    };
    const Event events[] = {{0.0, "idle", 0},       {0.5, "alert", 0},    {1.0, "shooting", 2},
                            {1.5, "shoot_pose", 1}, {2.0, "shooting", 0}, {2.5, "shoot_pose_reverse", 0},
                            {3.0, "death", 0},      {4.0, "idle", 2}};
    auto run = [&](int fps) {
        std::vector<Pose> samples; // every 1/6 s, a time all four rates reach exactly
        Player player(lib.clips, lib.rig);
        const int frames = fps * 6;
        std::size_t next_event = 0;
        for (int frame = 0; frame <= frames; ++frame) {
            // Events fall on frame boundaries at every rate (multiples of 0.5 s).
            while (next_event < std::size(events) && events[next_event].time * fps <= frame + 1e-9) {
                const Event& e = events[next_event++];
                if (e.how == 0) player.play(clip(e.clip));
                if (e.how == 1) player.play(clip(e.clip), 0.0f);
                if (e.how == 2) player.crossfade(clip(e.clip), 0.25f);
            }
            if (frame % (fps / 6) == 0) samples.push_back(player.pose());
            player.advance(1.0 / fps);
        }
        return samples;
    };
    const auto at30 = run(30);
    for (int fps : {60, 144, 240}) {
        const auto other = run(fps);
        REQUIRE(other.size() == at30.size());
        for (std::size_t s = 0; s < at30.size(); ++s) {
            INFO("fps ", fps, " sample ", s);
            const auto bytes = at30[s].euler.size() * sizeof(Vec3);
            CHECK(std::memcmp(at30[s].euler.data(), other[s].euler.data(), bytes) == 0);
            CHECK(std::memcmp(at30[s].position.data(), other[s].position.data(), bytes) == 0);
            CHECK(std::memcmp(at30[s].rotation.data(), other[s].rotation.data(),
                              at30[s].rotation.size() * sizeof(Quat)) == 0);
        }
    }
}

TEST_CASE("a cross-fade keeps the old clip running underneath and ends on the new clip alone") {
    const AnimationLibrary& lib = robot_library();
    Player player(lib.clips, lib.rig);
    player.play(clip("idle"), 0.0f);
    player.advance(0.3);
    player.crossfade(clip("alert"), 0.3f);
    CHECK(player.blending());
    const Pose start = player.pose();
    player.advance(0.15);
    // Halfway: the smoothstep weight is 0.5, between idle (still running) and alert (from `start`).
    Pose idle_now = start, alert_now = start;
    const Clip& idle = lib.clips.clips[static_cast<std::size_t>(clip("idle"))];
    const Clip& alert = lib.clips.clips[static_cast<std::size_t>(clip("alert"))];
    Pose rest;
    rest.set_rest(lib.rig);
    sample_clip(idle, rest.euler, rest.position, 0.45, idle_now.euler, idle_now.position);
    sample_clip(alert, start.euler, start.position, 0.15, alert_now.euler, alert_now.position);
    for (std::size_t k = 0; k < start.euler.size(); ++k) {
        const Vec3 expected = idle_now.euler[k] + (alert_now.euler[k] - idle_now.euler[k]) * 0.5f;
        CHECK(glm::length(player.pose().euler[k] - expected) < 1e-5f);
    }
    player.advance(0.25);
    CHECK_FALSE(player.blending());
    sample_clip(alert, start.euler, start.position, 0.4, alert_now.euler, alert_now.position);
    for (std::size_t k = 0; k < start.euler.size(); ++k)
        CHECK(glm::length(player.pose().euler[k] - alert_now.euler[k]) < 1e-5f);
    CHECK(player.current_clip() == clip("alert"));
}

TEST_CASE("loop mode 'next' hands over at the clip's exact end, whatever the frame size") {
    AnimationFile file = robot_library().file;
    ClipDef* pose = nullptr;
    for (ClipDef& c : file.clips)
        if (c.name == "shoot_pose") pose = &c;
    REQUIRE(pose);
    pose->loop = LoopMode::Next;
    pose->next = "shooting";
    REQUIRE(validate(file).empty());
    auto clips = compile(file, robot_library().rig);
    REQUIRE(clips.ok());
    for (double dt : {1.0 / 60, 0.1, 1.0}) {
        Player player(*clips, robot_library().rig);
        player.play(clips->find("shoot_pose"), 0.0f);
        int frames = 0;
        while (player.time() < 1.0 - 1e-9) {
            player.advance(dt);
            ++frames;
        }
        INFO("dt ", dt);
        CHECK(player.current_clip() == clips->find("shooting"));
        CHECK(player.clip_time() == doctest::Approx(0.7).epsilon(1e-9));
        CHECK(player.ticks() == kFlicksPerSecond);
    }
    // Zero-time cycles through 'next' are refused at load.
    AnimationFile cycle = robot_library().file;
    for (ClipDef& c : cycle.clips)
        if (c.name == "reset") {
            c.loop = LoopMode::Next;
            c.next = "reset";
        }
    auto issues = validate(cycle);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("returns to itself") != std::string::npos);
}

TEST_CASE("reset snaps to the rest pose; finished() and bad time steps") {
    const AnimationLibrary& lib = robot_library();
    Player player(lib.clips, lib.rig);
    CHECK(player.finished());
    player.play(clip("death"));
    player.advance(1.0);
    CHECK_FALSE(player.finished());
    player.advance(1.0);
    CHECK(player.finished());
    player.play(clip("reset"));
    Pose rest;
    rest.set_rest(lib.rig);
    CHECK(jump(player.pose(), rest).rotation < 1e-6f);
    const auto ticks = player.ticks();
    player.advance(-1.0);
    player.advance(std::nan(""));
    player.advance(0.0);
    CHECK(player.ticks() == ticks);
    player.play(-1);
    player.play(999);
    player.crossfade(999, 0.1f);
    CHECK(player.current_clip() == clip("reset"));
    player.play(clip("idle"));
    player.advance(10.0);
    CHECK_FALSE(player.finished()); // loops never finish
}

TEST_CASE("long runs stay finite and periodic (flick clock, loop iteration start in closed form)") {
    const AnimationLibrary& lib = robot_library();
    Player a(lib.clips, lib.rig), b(lib.clips, lib.rig);
    a.play(clip("idle"), 0.0f);
    b.play(clip("idle"), 0.0f);
    a.advance(0.5);
    b.advance(0.5 + 1.6 * 100000); // ~44 hours later, same phase of the loop
    for (const Vec3& e : b.pose().euler) CHECK(is_finite(e));
    CHECK(jump(a.pose(), b.pose()).rotation < 1e-4f);
    CHECK(jump(a.pose(), b.pose()).position < 1e-4f);
    b.play(clip("death"));
    b.advance(1e7);
    for (const Quat& q : b.pose().rotation) CHECK(is_finite(q));
}

TEST_CASE("extreme blend times: one flick and ten seconds stay jump-free and finite") {
    const AnimationLibrary& lib = robot_library();
    for (float blend : {1e-9f, 1e-6f, 10.0f}) {
        Player player(lib.clips, lib.rig);
        player.play(clip("alert"), 0.0f);
        player.advance(0.2);
        const Pose before = player.pose();
        player.play(clip("death"), blend);
        CHECK(jump(before, player.pose()).rotation < 1e-5f);
        for (int i = 0; i < 200; ++i) {
            player.advance(1.0 / 60);
            for (const Quat& q : player.pose().rotation) REQUIRE(is_finite(q));
        }
        Rates rates(lib.rig.size());
        player.velocity(rates.euler, rates.position);
        for (const Vec3& v : rates.euler) CHECK(is_finite(v));
    }
}

namespace {
// The names of the events fired by one advance(), in order.
std::vector<std::string> fired_names(const Player& player) {
    std::vector<std::string> names;
    for (const FiredEvent& f : player.fired_events()) names.push_back(f.event->name);
    return names;
}
} // namespace

TEST_CASE(
    "clip events fire once when the clip passes them: at the start, per loop iteration, across 'next'") {
    AnimationFile file = robot_library().file;
    for (ClipDef& c : file.clips) {
        if (c.name == "idle") c.events = {{0.0, "step_left", "footstep_floor"}, {0.8, "step_right", ""}};
        if (c.name == "shoot_pose") {
            c.loop = LoopMode::Next;
            c.next = "shooting";
            c.events = {{0.3, "aimed", ""}};
        }
    }
    REQUIRE(validate(file).empty());
    auto clips = compile(file, robot_library().rig);
    REQUIRE(clips.ok());
    const ClipSet& set = *clips;

    SUBCASE("the shipped shooting clip carries its muzzle flash and shot sound at 0 s, fired once per play") {
        const ClipSet& shipped = robot_library().clips;
        Player player(shipped, robot_library().rig);
        player.play(shipped.find("shooting"));
        player.advance(1.0 / 120);
        REQUIRE(player.fired_events().size() == 1);
        CHECK(player.fired_events()[0].event->name == "muzzle_flash");
        CHECK(player.fired_events()[0].event->sound == "robot_shot");
        int later = 0;
        for (int i = 0; i < 240; ++i) {
            player.advance(1.0 / 120);
            later += static_cast<int>(player.fired_events().size());
        }
        CHECK(later == 0); // a Once clip holds its last pose: no second shot sound
    }
    SUBCASE("a loop reports each iteration, whatever the frame size") {
        for (double dt : {1.0 / 120, 1.0 / 30, 0.25}) {
            Player player(set, robot_library().rig);
            player.play(set.find("idle"), 0.0f);
            int left = 0, right = 0;
            const int steps = static_cast<int>(std::lround(3.5 / dt));
            for (int i = 0; i < steps; ++i) {
                player.advance(dt);
                for (const std::string& n : fired_names(player)) (n == "step_left" ? left : right) += 1;
            }
            INFO("dt ", dt);
            CHECK(left == 3);  // 0, 1.6, 3.2 s
            CHECK(right == 2); // 0.8, 2.4 s (4.0 s is not reached in 3.5 s)
        }
    }
    SUBCASE("a huge step of a loop reports a bounded number of iterations") {
        Player player(set, robot_library().rig);
        player.play(set.find("idle"), 0.0f);
        player.advance(1000.0);
        CHECK(player.fired_events().size() <= 8);
        CHECK(player.fired_events().size() >= 2);
    }
    SUBCASE("the end event of a 'next' clip fires before the next clip's own events") {
        Player player(set, robot_library().rig);
        player.play(set.find("shoot_pose"), 0.0f);
        player.advance(1.0); // 0.3 s of shoot_pose, then shooting (its muzzle_flash at 0 s)
        CHECK(fired_names(player) == std::vector<std::string>{"aimed", "muzzle_flash"});
        player.advance(1.0 / 120);
        CHECK(player.fired_events().empty());
    }
    SUBCASE("playing the clip again re-arms its events; a bad step fires nothing") {
        Player player(set, robot_library().rig);
        player.play(set.find("idle"), 0.0f);
        player.advance(0.1);
        CHECK(fired_names(player) == std::vector<std::string>{"step_left"});
        player.play(set.find("idle"));
        player.advance(0.1);
        CHECK(fired_names(player) == std::vector<std::string>{"step_left"});
        player.advance(std::nan(""));
        CHECK(player.fired_events().empty());
    }
}
