// The autoplay bot wins the shipped main level headless, for several seeds, within a simulated time limit.
#include "game/autoplay.h"
#include "game/headless.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdio>

using namespace ks;
using namespace ks::game;

TEST_CASE("autoplay wins levels/main.json for several seeds") {
    for (std::uint64_t seed : {1ull, 2ull, 3ull, 4ull, 5ull, 6ull}) {
        HeadlessOptions o;
        o.level = test::source_dir() / "levels/main.json";
        o.seconds = 60.0;
        o.seed = seed;
        o.autoplay = true;
        auto stats = run_headless(o);
        if (!stats) FAIL(stats.error().str());
        MESSAGE("seed " << seed << ": " << stats->summary());
        CHECK(stats->outcome == "win");
        CHECK(stats->shots > 0);
        CHECK(stats->sim_time_s < 60.0);
        CHECK(stats->robots_killed >= 4);
    }
}
