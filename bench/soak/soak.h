#pragma once
// The soak run (issue 8, item 4), header-only so that `ks_bench soak` and the short version in
// tests/hardening/test_soak.cpp run the same code: the headless game plays a level with the autoplay bot
// for a long stretch of simulated time, checks after every step that nothing in the game state is NaN or
// infinite, and samples the process's resident memory (VmRSS) every simulated minute.
//
// When the bot wins (or dies) before the time is up, one of two things keeps the world busy:
//   restart_on_end  a new round starts: a fresh Game of the same level (next seed) and a fresh bot, so the
//                   level is played again and again (on the main level a round lasts ~20 s), which also
//                   builds and frees whole worlds all hour: a leak shows in the RSS curve;
//   otherwise       the same game keeps running with the player idle: Game::step still simulates every
//                   robot, door, cylinder fuse and the physics world in the Won and Dead phases (on the
//                   large level ~80 robots are still wandering), so one world lives for the whole hour.
//
// large_level() generates the big test level: a grid of 40 x 40 rooms (walls 16 tall, doorways with
// sliding doors or open), robots in every room but the first, a pickup, a gas cylinder and lights in each,
// a stair and platform in every fourth, and the control panel in the far corner.
#include "core/random.h"
#include "game/autoplay.h"
#include "game/game.h"
#include "level/level.h"
#include "level/shutdown_objective.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

namespace ks::soak {

// Resident set size of this process in KiB (0 where /proc is unavailable).
inline long read_rss_kib() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    long kib = 0;
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, "VmRSS:", 6) == 0) {
            kib = std::strtol(line + 6, nullptr, 10);
            break;
        }
    std::fclose(f);
    return kib;
}

inline double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct LargeLevelOptions {
    int columns = 6, rows = 5; // rooms
    int robots_per_room = 4;   // in every room but the player's
    std::uint64_t seed = 1;
};

inline level::Level large_level(const LargeLevelOptions& o = {}) {
    constexpr float kRoom = 40.0f, kHeight = 16.0f, kThick = 0.5f, kDoor = 5.0f, kLintel = 5.0f;
    level::Level lv;
    lv.name = "soak: generated " + std::to_string(o.columns) + " x " + std::to_string(o.rows) + " rooms";
    Rng rng(o.seed);
    const float width = o.columns * kRoom, depth = o.rows * kRoom;
    const Vec3 middle(width * 0.5f, 0.0f, -depth * 0.5f);
    auto& ground = lv.add(level::EntityType::Floor, middle, "ground");
    ground.as<level::FloorProps>().size = Vec2(width, depth);
    auto& ceiling = lv.add(level::EntityType::Floor, middle + Vec3(0, kHeight, 0), "ceiling");
    ceiling.as<level::FloorProps>().size = Vec2(width, depth);
    ceiling.as<level::FloorProps>().ceiling = true;

    // A wall piece from a to b on the ground (along x or z), `height` tall starting at `base` (y).
    auto wall = [&](Vec3 a, Vec3 b, float base, float height, const char* name) {
        const Vec3 centre = (a + b) * 0.5f;
        const float length = glm::length(b - a);
        auto& w = lv.add(level::EntityType::Wall, Vec3(centre.x, base, centre.z), name);
        w.as<level::WallProps>().size = Vec3(length, height, kThick);
        w.rotation.x = std::abs(b.x - a.x) > std::abs(b.z - a.z) ? 0.0f : 90.0f;
    };
    // A wall with a doorway in the middle; a sliding door in it half of the time.
    auto wall_with_doorway = [&](Vec3 a, Vec3 b) {
        const Vec3 dir = glm::normalize(b - a);
        const float length = glm::length(b - a);
        const Vec3 d0 = a + dir * ((length - kDoor) * 0.5f), d1 = a + dir * ((length + kDoor) * 0.5f);
        wall(a, d0, 0.0f, kHeight, "wall");
        wall(d1, b, 0.0f, kHeight, "wall");
        wall(d0, d1, kLintel, kHeight - kLintel, "lintel");
        if (rng.chance(0.5f)) {
            auto& door = lv.add(level::EntityType::Door, (d0 + d1) * 0.5f, "door");
            door.rotation.x = std::abs(dir.x) > 0.5f ? 0.0f : 90.0f;
            door.as<level::DoorProps>().width = kDoor;
            door.as<level::DoorProps>().height = kLintel;
        }
    };
    // Outer walls, then the walls between rooms.
    wall({0, 0, 0}, {width, 0, 0}, 0.0f, kHeight, "outer wall");
    wall({0, 0, -depth}, {width, 0, -depth}, 0.0f, kHeight, "outer wall");
    wall({0, 0, 0}, {0, 0, -depth}, 0.0f, kHeight, "outer wall");
    wall({width, 0, 0}, {width, 0, -depth}, 0.0f, kHeight, "outer wall");
    for (int r = 0; r < o.rows; ++r)
        for (int c = 1; c < o.columns; ++c)
            wall_with_doorway({c * kRoom, 0, -r * kRoom}, {c * kRoom, 0, -(r + 1) * kRoom});
    for (int r = 1; r < o.rows; ++r)
        for (int c = 0; c < o.columns; ++c)
            wall_with_doorway({c * kRoom, 0, -r * kRoom}, {(c + 1) * kRoom, 0, -r * kRoom});

    const char* pickup_kinds[] = {"health", "ammo", "shield"};
    for (int r = 0; r < o.rows; ++r)
        for (int c = 0; c < o.columns; ++c) {
            const float x0 = c * kRoom, z0 = -(r + 1) * kRoom; // room's min corner (x, z)
            auto inside = [&](float margin) {
                return Vec3(rng.uniform(x0 + margin, x0 + kRoom - margin), 0.0f,
                            rng.uniform(z0 + margin, z0 + kRoom - margin));
            };
            const Vec3 centre(x0 + kRoom * 0.5f, 0.0f, z0 + kRoom * 0.5f);
            lv.add(level::EntityType::TopLight, centre + Vec3(0, kHeight, 0), "top light");
            const bool first = r == 0 && c == 0, last = r == o.rows - 1 && c == o.columns - 1;
            if ((r * o.columns + c) % 4 == 3) { // a stair up to a platform against the room's far wall
                lv.add(level::EntityType::Stair, Vec3(x0 + 10.0f, 0, z0 + 20.0f), "stair");
                auto& top = lv.add(level::EntityType::Floor, Vec3(x0 + 10.0f, 6.0f, z0 + 8.0f), "platform");
                top.as<level::FloorProps>().size = Vec2(12.0f, 12.0f);
            }
            if (last) {
                lv.add(level::EntityType::ControlPanel, centre + Vec3(8.0f, 0, 0), "control panel");
                continue;
            }
            auto& pickup = lv.add(level::EntityType::Pickup, inside(6.0f), "pickup");
            pickup.as<level::PickupProps>().kind.value = pickup_kinds[rng.below(3)];
            pickup.as<level::PickupProps>().amount = 10.0f;
            lv.add(level::EntityType::GasCylinder, inside(6.0f), "cylinder").rotation.x =
                rng.uniform(-180, 180);
            lv.add(level::EntityType::FloorLight, Vec3(x0 + 2.0f, 0, z0 + 2.0f), "floor light").rotation.x =
                -45.0f;
            if (first) continue;
            for (int k = 0; k < o.robots_per_room; ++k)
                lv.add(level::EntityType::Robot, inside(5.0f), "robot").rotation.x = rng.uniform(-180, 180);
        }
    lv.player_start.position = Vec3(kRoom * 0.5f, 0.0f, -kRoom * 0.5f);
    level::add_shutdown_objective(lv); // the panel wins
    return lv;
}

struct SoakOptions {
    double sim_seconds = 3600.0;
    double sample_every = 60.0; // simulated seconds between RSS samples
    std::uint64_t seed = 1;
    bool immortal = false;       // the player cannot die (a bot among 100+ robots otherwise dies in a minute)
    bool restart_on_end = false; // a won or lost game is replaced by a fresh round (see the top)
};

struct SoakSample {
    double sim_time = 0.0;
    long rss_kib = 0;
    double cpu_s = 0.0; // process CPU time spent in the run so far
    int robots_alive = 0;
    int robots_engaged = 0; // alert, chasing, aiming or shooting
    int robots_moving = 0;  // horizontal velocity this step
    int shots = 0, kills = 0, ammo = 0;
    float to_panel = -1.0f; // the player's horizontal distance to the control panel (the bot's goal)
    game::Phase phase = game::Phase::Playing;
};

struct SoakResult {
    std::vector<SoakSample> samples;
    std::string problem;             // the first non-finite value seen (what and when); empty when none
    std::string outcome = "timeout"; // what the bot's first game came to: win, death, timeout
    double outcome_time = -1.0;      // simulated seconds when it did
    int rounds = 1, wins = 0, deaths = 0;
    std::int64_t steps = 0; // over all rounds
    double cpu_s = 0.0;
    std::uint64_t state_hash = 0;
    int robots = 0, events = 0;
    // Largest RSS growth over the run after `warm_up` simulated seconds, against the first sample after it.
    long rss_growth_after(double warm_up) const {
        long base = -1, growth = 0;
        for (const SoakSample& s : samples) {
            if (s.sim_time < warm_up) continue;
            if (base < 0) base = s.rss_kib;
            growth = std::max(growth, s.rss_kib - base);
        }
        return growth;
    }
};

namespace detail {
inline bool finite(float v) {
    return std::isfinite(v);
}
inline bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Describes the first non-finite number in the game's state (empty when all are finite).
inline std::string first_non_finite(const game::Game& g) {
    const game::PlayerState& p = g.player();
    if (!finite(p.feet) || !finite(p.velocity) || !finite(p.knockback)) return "player position or velocity";
    if (!finite(p.yaw) || !finite(p.pitch) || !finite(p.health) || !finite(p.shield))
        return "player view or health";
    const auto robots = g.robots();
    for (std::size_t i = 0; i < robots.size(); ++i) {
        const game::Robot& r = robots[i];
        if (!finite(r.feet) || !finite(r.yaw) || !finite(r.health) || !finite(r.knockback) ||
            !finite(r.mode_time))
            return "robot " + std::to_string(r.entity_id) + " state";
        if (r.mode != game::RobotMode::Dead && !finite(g.world().transform(r.body).position))
            return "robot " + std::to_string(r.entity_id) + " body";
    }
    for (const game::Door& d : g.doors())
        if (!finite(d.progress)) return "door " + std::to_string(d.entity_id);
    for (const game::Cylinder& c : g.cylinders())
        if (!finite(c.centre) || !finite(c.fuse)) return "cylinder " + std::to_string(c.entity_id);
    for (const game::Event& e : g.events())
        if (!finite(e.position) || !finite(e.end) || !finite(e.amount))
            return "event of type " + std::to_string(static_cast<int>(e.type));
    return {};
}
} // namespace detail

// Plays `level` for options.sim_seconds. `on_sample` (optional) is called with each sample as it is taken.
template <class OnSample>
SoakResult run_soak(const level::Level& level, const SoakOptions& options, OnSample&& on_sample) {
    SoakResult result;
    game::GameOptions game_options;
    game_options.seed = options.seed;
    if (options.immortal) { // and with ammo to match, or the bot's 150 rounds are gone in the first minute
        game_options.settings.max_health = game_options.settings.start_health = 1e9f;
        game_options.settings.max_ammo = game_options.settings.start_ammo = 1000000;
    }
    // One mesh for every round, built with the first: the bot never changes it, and rebuilding it would cost
    // more than a round.
    std::shared_ptr<nav::NavMesh> mesh;
    std::unique_ptr<game::Game> g;
    std::unique_ptr<game::Autoplay> bot;
    auto new_round = [&]() -> bool {
        bot.reset();
        g.reset();
        auto created = game::Game::create(level, game_options);
        if (!created) {
            result.problem = "the level did not load: " + created.error().str();
            return false;
        }
        g = std::move(*created);
        if (!mesh) {
            auto built = game::build_autoplay_mesh(level, game::AutoplaySettings{}.cylinder_keep_out);
            if (!built) {
                result.problem = "the bot's navigation mesh did not build: " + built.error().str();
                return false;
            }
            mesh = std::move(*built);
        }
        bot = std::make_unique<game::Autoplay>(*g, mesh, game_options.seed);
        return true;
    };
    if (!new_round()) return result;
    result.robots = static_cast<int>(g->robots().size());
    const double step = g->settings().step;
    const double cpu0 = cpu_seconds();
    const auto total_steps = static_cast<std::int64_t>(options.sim_seconds / step + 0.5);
    const auto sample_steps =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(options.sample_every / step + 0.5));
    auto sample = [&](std::int64_t done) {
        SoakSample s;
        s.sim_time = static_cast<double>(done) * step;
        s.rss_kib = read_rss_kib();
        s.cpu_s = cpu_seconds() - cpu0;
        for (const game::Robot& r : g->robots()) {
            if (!r.alive()) continue;
            ++s.robots_alive;
            s.robots_engaged += r.mode != game::RobotMode::Idle;
            const Vec3 v = g->world().character(r.body).movement.velocity;
            s.robots_moving += v.x * v.x + v.z * v.z > 1e-4f;
        }
        s.shots = g->player().shots;
        s.kills = g->robots_killed();
        s.ammo = g->player().ammo;
        if (!g->panels().empty()) {
            const Vec3 d = g->panels().front().centre - g->player().feet;
            s.to_panel = std::sqrt(d.x * d.x + d.z * d.z);
        }
        s.phase = g->phase();
        result.samples.push_back(s);
        on_sample(s);
    };
    sample(0);
    for (std::int64_t i = 0; i < total_steps; ++i) {
        const bool playing = g->phase() == game::Phase::Playing;
        g->step(playing ? bot->decide(*g) : game::Input{});
        ++result.steps;
        result.events += static_cast<int>(g->events().size());
        if (std::string bad = detail::first_non_finite(*g); !bad.empty()) {
            char when[96];
            std::snprintf(when, sizeof when, " is not finite at %.3f s of round %d (step %lld)", g->time(),
                          result.rounds, static_cast<long long>(g->steps()));
            result.problem = bad + when;
            break;
        }
        if ((i + 1) % sample_steps == 0) sample(i + 1);
        if (playing && g->phase() != game::Phase::Playing) {
            const bool won = g->phase() == game::Phase::Won;
            (won ? result.wins : result.deaths) += 1;
            if (result.rounds == 1) {
                result.outcome = won ? "win" : "death";
                result.outcome_time = g->time();
            }
            if (options.restart_on_end && i + 1 < total_steps) {
                ++game_options.seed;
                ++result.rounds;
                if (!new_round()) break;
            }
        }
    }
    result.cpu_s = cpu_seconds() - cpu0;
    result.state_hash = g ? g->state_hash() : 0;
    return result;
}

inline SoakResult run_soak(const level::Level& level, const SoakOptions& options) {
    return run_soak(level, options, [](const SoakSample&) {});
}

} // namespace ks::soak
