// The short soak (issue 8, item 4): the same run as `ks_bench soak` (bench/soak/soak.h), for 2 simulated
// minutes of the main level and 1 of the generated large level: the bot plays, every step is checked for
// NaN, and resident memory is sampled every simulated 20 s. The hour-long run is `ks_bench soak`.
#include "bench/soak/soak.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <limits>

namespace ks::soak {
namespace {

// Under AddressSanitizer freed memory sits in a quarantine (256 MB by default) before it is reused, so RSS
// grows with every allocation however well memory is managed: the RSS bound holds in normal builds only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kRssMeaningful = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kRssMeaningful = false;
#else
constexpr bool kRssMeaningful = true;
#endif
#else
constexpr bool kRssMeaningful = true;
#endif

void check_run(const SoakResult& r, double seconds) {
    INFO("problem: " << r.problem);
    CHECK(r.problem.empty());
    CHECK(r.steps == static_cast<std::int64_t>(seconds * 120.0 + 0.5));
    REQUIRE(r.samples.size() >= 3);
    for (const SoakSample& s : r.samples) {
        CHECK(s.rss_kib > 0);
        CHECK(s.cpu_s >= 0.0);
    }
}

TEST_CASE("soak: the bot plays the main level for 2 simulated minutes, all finite, memory flat") {
    auto lv = level::load_level_file(paths::level("main.json"));
    REQUIRE(lv.ok());
    SoakOptions options;
    options.sim_seconds = 120.0;
    options.sample_every = 20.0;
    options.restart_on_end = true;
    const SoakResult r = run_soak(*lv, options);
    check_run(r, options.sim_seconds);
    MESSAGE("main: " << r.robots << " robots, first round " << r.outcome << " at " << r.outcome_time << " s, "
                     << r.rounds << " rounds (" << r.wins << " won, " << r.deaths << " lost), " << r.events
                     << " events, RSS " << r.samples.front().rss_kib << " -> " << r.samples.back().rss_kib
                     << " KiB, " << r.steps / std::max(1e-9, r.cpu_s) << " steps per CPU s");
    CHECK(r.robots == 8);
    // The bot finishes the level in well under 2 minutes, so rounds follow one another all the time.
    CHECK(r.rounds >= 3);
    CHECK(r.wins + r.deaths >= r.rounds - 1);
    CHECK(r.events > 100 * r.rounds / 2);
    // Warm-up is the first 40 s (nav grid, paths, pools reaching their size); after it RSS must stay flat.
    const long growth = r.rss_growth_after(40.0);
    MESSAGE("RSS growth after the 40 s warm-up: " << growth << " KiB");
    if (kRssMeaningful) CHECK(growth <= 512);
}

TEST_CASE("soak: the generated large level (112 robots in 28 rooms) runs a simulated minute, all finite") {
    const level::Level lv = large_level();
    int robots = 0, doors = 0;
    for (const level::Entity& e : lv.entities) {
        robots += e.type() == level::EntityType::Robot;
        doors += e.type() == level::EntityType::Door;
    }
    CHECK(robots == 28 * 4); // 30 rooms: none in the player's, the panel's room is empty too
    CHECK(doors > 10);
    SoakOptions options;
    options.sim_seconds = 60.0;
    options.sample_every = 20.0;
    options.immortal = true;
    const SoakResult r = run_soak(lv, options);
    check_run(r, options.sim_seconds);
    REQUIRE(r.robots == robots);
    const SoakSample& last = r.samples.back();
    MESSAGE("large: " << r.robots << " robots, " << last.robots_alive << " alive, " << last.robots_engaged
                      << " engaged, " << last.robots_moving << " moving, " << last.shots << " shots, "
                      << last.kills << " kills, RSS " << r.samples.front().rss_kib << " -> " << last.rss_kib
                      << " KiB, " << r.steps / std::max(1e-9, r.cpu_s) << " steps per CPU s");
    // The world is busy: robots wander (idle robots drive about), and the bot fights its way.
    CHECK(last.robots_moving > 20);
    CHECK(last.shots > 0);
    // Immortal and with ammo, the bot fights its way through the rooms and doors to the panel (46 s).
    CHECK(r.outcome == "win");
}

TEST_CASE("soak: a level that cannot be built is reported, not crashed on") {
    level::Level lv = large_level({2, 1, 1, 3});
    for (level::Entity& e : lv.entities)
        if (auto* w = e.try_as<level::WallProps>()) w->size.x = std::numeric_limits<float>::quiet_NaN();
    SoakOptions options;
    options.sim_seconds = 1.0;
    const SoakResult r = run_soak(lv, options);
    CHECK(r.problem.find("did not load") != std::string::npos);
    CHECK(r.steps == 0);
}

} // namespace
} // namespace ks::soak
