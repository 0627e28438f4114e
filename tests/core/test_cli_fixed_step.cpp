#include "core/cli.h"
#include "core/fixed_step.h"

#include <cmath>
#include <doctest/doctest.h>

using namespace ks;

TEST_CASE("CommandLine parses values, flags, '=' forms and reports bad numbers") {
    const char* argv[] = {"prog",       "--level", "a.json",  "--frames=30",
                          "--no-vsync", "extra",   "--width", "abc"};
    auto cl = CommandLine::parse(8, argv, {"no-vsync"});
    REQUIRE(cl.ok());
    CHECK(cl->get_or("level", "") == "a.json");
    CHECK(cl->get_int("frames", 1, 1, 100).value() == 30);
    CHECK(cl->has("no-vsync"));
    CHECK(cl->positional() == std::vector<std::string>{"extra"});
    auto width = cl->get_int("width", 0, 1, 10);
    REQUIRE_FALSE(width.ok());
    CHECK(width.error().message.find("--width") != std::string::npos);
    CHECK(cl->get_int("height", 720, 1, 8192).value() == 720);
    CHECK(cl->unknown({"level", "frames", "no-vsync"}) == std::vector<std::string>{"--width"});

    const char* missing[] = {"prog", "--level"};
    CHECK_FALSE(CommandLine::parse(2, missing, {}).ok());
    const char* range[] = {"prog", "--frames", "0"};
    CHECK_FALSE(CommandLine::parse(3, range, {})->get_int("frames", 1, 1, 10).ok());
    const char* nan[] = {"prog", "--speed", "nan"};
    CHECK_FALSE(CommandLine::parse(3, nan, {})->get_double("speed", 1.0).ok());
}

TEST_CASE("FixedStepClock runs the same number of steps at any frame rate") {
    for (double fps : {15.0, 30.0, 60.0, 144.0, 240.0}) {
        FixedStepClock clock(1.0 / 120.0);
        long long steps = 0;
        int frames = static_cast<int>(std::lround(fps * 10.0)); // ten seconds
        for (int i = 0; i < frames; ++i) steps += clock.advance(1.0 / fps);
        CAPTURE(fps);
        CHECK(std::llabs(steps - 1200) <= 1);
        CHECK(clock.alpha() >= 0.0);
        CHECK(clock.alpha() < 1.0);
    }
}

TEST_CASE("FixedStepClock sub-steps a 1 s hitch and ignores dt = 0, negative and NaN") {
    FixedStepClock clock(1.0 / 120.0);
    CHECK(clock.advance(1.0) == 120);
    CHECK(clock.advance(0.0) == 0);
    CHECK(clock.advance(-1.0) == 0);
    CHECK(clock.advance(std::nan("")) == 0);
    CHECK(clock.advance(1e-6) == 0);
    CHECK(clock.total_steps() == 120);

    FixedStepClock capped(1.0 / 120.0, 10);
    CHECK(capped.advance(1.0) == 10); // at most 10 now...
    CHECK(capped.advance(0.0) == 10); // ...the rest is kept, not dropped
    long long total = capped.total_steps();
    while (capped.advance(0.0) > 0) total = capped.total_steps();
    CHECK(total == 120);
}

TEST_CASE("parse_pose: five finite numbers separated by commas, nothing else") {
    auto pose = parse_pose("1.5,-2,3e1,90,-45");
    REQUIRE(pose.ok());
    CHECK(pose->position == Vec3(1.5f, -2.0f, 30.0f));
    CHECK(pose->yaw_degrees == 90.0f);
    CHECK(pose->pitch_degrees == -45.0f);
    auto spaced = parse_pose(" 0, 3 ,25,0, -10 ");
    REQUIRE(spaced.ok());
    CHECK(spaced->position == Vec3(0.0f, 3.0f, 25.0f));
    CHECK(spaced->pitch_degrees == -10.0f);

    const struct {
        const char* text;
        const char* message;
    } bad[] = {
        {"1,2,3,4,5x", "pitch '5x' is not a number"}, // trailing junk
        {"1,2,3,4,5,", "more than five values"},      // a trailing comma
        {"1,2,3,4,5,6", "more than five values"},
        {"1,2", "only 2 of the five values"},
        {"", "x '' is not a number"},
        {"1,,3,4,5", "y '' is not a number"},
        {"1,2,nan,0,0", "z 'nan' is not a finite number"}, // non-finite numbers
        {"1,2,3,inf,0", "yaw 'inf' is not a finite number"},
        {"1,2,3,0,1e99", "pitch '1e99' is not a finite number"},
        {"0x10,2,3,4,5", "x '0x10' is not a number"},
        {"1;2;3;4;5", "x '1;2;3;4;5' is not a number"},
    };
    for (const auto& [text, message] : bad) {
        CAPTURE(text);
        auto r = parse_pose(text);
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().message == std::string("expected x,y,z,yaw,pitch: ") + message);
        CHECK(r.error().hint.find("e.g. 0,3,25,0,-10") != std::string::npos);
    }
}
