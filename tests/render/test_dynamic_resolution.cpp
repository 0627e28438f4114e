// The dynamic resolution controller against made-up machines: a frame's work costs fixed + per_pixel x
// scale^2 ms, times a deterministic noise, and the controller sees each frame's time as the game's loop
// would (the frame drawn at the scale it returned last time).
#include "render/dynamic_resolution.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

using ks::render::DynamicResolution;
using ks::render::DynamicResolutionSettings;

namespace {

struct Machine {
    double fixed_ms = 5.0, per_pixel_ms = 5.0; // at scale 1
    double noise = 0.0;                        // relative, uniform in +-noise
    std::uint64_t seed = 12345;
    double frame(float scale) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        const double u = static_cast<double>(seed >> 11) / static_cast<double>(1ull << 53); // 0..1
        return (fixed_ms + per_pixel_ms * scale * scale) * (1.0 + noise * (2.0 * u - 1.0));
    }
};

// Runs `frames` frames; returns how many frames each scale drew.
std::map<float, int> run(DynamicResolution& dr, Machine& m, int frames) {
    std::map<float, int> drawn;
    float scale = dr.scale();
    for (int i = 0; i < frames; ++i) {
        const double ms = m.frame(scale);
        ++drawn[scale];
        // A capped loop: the frame period is at least 1/60 s even when the work is shorter.
        scale = dr.update(ms, std::max(ms, 1000.0 / 60.0) / 1000.0);
    }
    return drawn;
}

} // namespace

TEST_CASE("dynamic resolution climbs to full resolution on a machine that holds 60 fps there") {
    DynamicResolution dr;
    CHECK(dr.scale() == 0.5f); // starts where the automatic setting drew before
    Machine fast{4.0, 6.0};    // 10 ms at full resolution
    auto drawn = run(dr, fast, 3000);
    CHECK(dr.scale() == 1.0f);
    CHECK(dr.changes() == 4); // 0.5 -> 0.625 -> 0.75 -> 0.875 -> 1, once each
    CHECK(drawn[1.0f] > 2800);
}

TEST_CASE("dynamic resolution settles at the largest step that holds the budget") {
    // 8 + 12 s^2: 20 ms at 1, 17.2 at 0.875, 14.75 at 0.75 (the largest under 16.7), 12.7 at 0.625.
    DynamicResolution dr;
    Machine slow{8.0, 12.0};
    const int frames = 60 * 600; // ten minutes at 60 fps
    auto drawn = run(dr, slow, frames);
    CHECK(dr.scale() == 0.75f);
    // It tries 0.875 now and then (the wait doubling to 64 s), so nearly all frames are at 0.75 and the
    // number of changes stays small: about two per try over ten minutes.
    CHECK(drawn[0.75f] > frames * 95 / 100);
    CHECK(drawn[0.875f] < frames * 2 / 100);
    CHECK(drawn[1.0f] == 0);
    CHECK(dr.changes() < 40);
}

TEST_CASE("dynamic resolution never goes below its lowest step, however slow the machine") {
    DynamicResolution dr;
    Machine crawling{40.0, 40.0};
    run(dr, crawling, 2000);
    CHECK(dr.scale() == 0.5f);
    CHECK(dr.changes() == 0);

    DynamicResolutionSettings settings;
    settings.lowest_scale = 1.0f; // a GPU: the automatic scale is already full resolution
    DynamicResolution gpu(settings);
    run(gpu, crawling, 500);
    CHECK(gpu.scale() == 1.0f);
    CHECK(gpu.changes() == 0);
}

TEST_CASE("dynamic resolution under noisy frame times does not flicker between sizes") {
    // 10.5 + 7 s^2 = 17.5 ms at 1 (over), 15.9 at 0.875 (under, with 12 % noise either side of it).
    DynamicResolution dr;
    Machine marginal{10.5, 7.0, 0.12};
    const int frames = 60 * 300;
    auto drawn = run(dr, marginal, frames);
    CHECK(dr.scale() == doctest::Approx(0.875f));
    CHECK(drawn[0.875f] > frames * 9 / 10);
    CHECK(dr.changes() < 30); // five minutes: a few tries of full resolution, no flicker
}

TEST_CASE("dynamic resolution follows the load down and back up") {
    DynamicResolution dr;
    Machine m{4.0, 6.0};
    run(dr, m, 600);
    REQUIRE(dr.scale() == 1.0f);
    m = Machine{10.0, 20.0}; // a heavy room: 30 ms at 1, 15 at 0.5
    run(dr, m, 600);
    CHECK(dr.scale() == 0.5f);
    m = Machine{4.0, 6.0}; // back in a light room: climbs again once the waits have passed
    run(dr, m, 60 * 90);
    CHECK(dr.scale() == 1.0f);
}

TEST_CASE("dynamic resolution ignores frames that say nothing about the load") {
    DynamicResolution dr;
    Machine fast{4.0, 6.0};
    float scale = dr.scale();
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 2000; ++i) {
        double ms = fast.frame(scale);
        if (i % 7 == 0) ms = 900.0; // a hitch (a level load, a shader compile): not counted
        if (i % 11 == 0) ms = nan;
        if (i % 13 == 0) ms = -3.0;
        if (i % 17 == 0) ms = inf;
        scale = dr.update(ms, i % 19 == 0 ? nan : 1.0 / 60.0);
    }
    CHECK(dr.scale() == 1.0f);
    CHECK(dr.changes() == 4);

    // Hitches alone never move it.
    DynamicResolution idle;
    for (int i = 0; i < 1000; ++i) idle.update(400.0, 0.4);
    CHECK(idle.changes() == 0);

    // Bad settings are clamped: a window of 0 or 10 000 frames, a floor that is NaN.
    DynamicResolutionSettings bad;
    bad.window = 0;
    bad.lowest_scale = std::numeric_limits<float>::quiet_NaN();
    DynamicResolution clamped(bad);
    CHECK(clamped.scale() == 0.25f);
    bad.window = 10000;
    bad.lowest_scale = 0.6f; // nearest step: 0.625
    DynamicResolution wide(bad);
    CHECK(wide.scale() == 0.625f);
    run(wide, fast, 3000);
    CHECK(wide.scale() == 1.0f);
}

TEST_CASE("dynamic resolution reset starts again from the lowest step") {
    DynamicResolution dr;
    Machine fast{4.0, 6.0};
    run(dr, fast, 600);
    REQUIRE(dr.scale() == 1.0f);
    dr.reset();
    CHECK(dr.scale() == 0.5f);
    run(dr, fast, 600);
    CHECK(dr.scale() == 1.0f);
}
