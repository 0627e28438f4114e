// ks_bench shots: the game's shots per second on a level: the closest-hit query with the shot filter (what
// Game::shoot_ray casts) against collecting every hit along the ray with ray_all and keeping the first that
// passes the filter (how shots were cast before), on the same shots, checking that both hit the same body
// at the same point. Player shots: 500 units from the eye in random directions; robot shots: 100 units
// from each muzzle toward the player, passing through other robots.
#include "bench_registry.h"
#include "bench_util.h"
#include "core/cli.h"
#include "core/paths.h"
#include "core/random.h"
#include "game/game.h"
#include "level/level_io.h"
#include "soak/soak.h"

#include <cstdio>

namespace ks::physics::bench {
namespace {

struct Shot {
    geometry::Ray ray;
    RayFilter filter;
};

bool not_a_robot(std::uint64_t user) {
    return game::user_kind(user) != game::BodyKind::Robot;
}

std::vector<Shot> make_shots(const game::Game& g, int count, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Shot> shots;
    shots.reserve(static_cast<std::size_t>(count));
    const auto robots = g.robots();
    const Vec3 eye = g.player().eye();
    while (static_cast<int>(shots.size()) < count) {
        const std::size_t k = static_cast<std::size_t>(rng.uniform(0.0f, 1.0f) * (robots.size() + 1));
        if (k >= robots.size()) {
            const float yaw = rng.uniform(0.0f, 2.0f * kPi), pitch = rng.uniform(-0.3f, 0.3f);
            const Vec3 dir(-std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                           -std::cos(yaw) * std::cos(pitch));
            shots.push_back(
                {{eye, dir, g.settings().shot_range}, RayFilter(layer::kShootable, g.player().body)});
        } else {
            const Vec3 muzzle = g.robot_muzzle(k);
            const Vec3 aim = eye + Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            Shot s{{muzzle, glm::normalize(aim - muzzle), g.settings().robot_shot_range},
                   RayFilter(layer::kShootable, robots[k].body)};
            s.filter.accept_user_data = not_a_robot;
            shots.push_back(s);
        }
    }
    return shots;
}

// The first hit of ray_all that the filter's user-data test accepts (ray_all then gets only the layers and
// the ignored body), as shots were cast before the closest-hit query took the test.
bool first_of_all(const World& w, const Shot& s, std::vector<RayHit>& scratch, RayHit& out) {
    scratch.clear();
    RayFilter layers_only(s.filter.layers, s.filter.ignore);
    w.ray_all(s.ray, scratch, HitOrder::Ascending, layers_only);
    for (const RayHit& h : scratch)
        if (!s.filter.accept_user_data || s.filter.accept_user_data(w.user_data(h.body))) {
            out = h;
            return true;
        }
    return false;
}

template <class Cast>
double shots_per_second(const std::vector<Shot>& shots, double min_seconds, Cast&& cast) {
    std::size_t done = 0;
    const double start = cpu_seconds();
    double elapsed = 0;
    do {
        for (const Shot& s : shots) cast(s);
        done += shots.size();
        elapsed = cpu_seconds() - start;
    } while (elapsed < min_seconds);
    return static_cast<double>(done) / elapsed;
}

int shots_command(int argc, const char* const* argv) {
    auto cli = CommandLine::parse(argc, argv, {"json"});
    if (!cli) {
        std::fprintf(stderr, "ks_bench shots: %s\n", cli.error().str().c_str());
        return 2;
    }
    if (auto unknown = cli->unknown({"level", "shots", "seconds", "seed", "json", "columns", "rows"});
        !unknown.empty()) {
        std::fprintf(stderr,
                     "ks_bench shots: unknown option --%s (known: --level FILE|large --columns C --rows R "
                     "--shots N --seconds S --seed S --json)\n",
                     unknown[0].c_str());
        return 2;
    }
    const std::string level_file = cli->get("level").value_or(paths::level("main.json").string());
    const int count = std::stoi(cli->get("shots").value_or("20000"));
    const double seconds = std::stod(cli->get("seconds").value_or("1.0"));
    const auto seed = static_cast<std::uint64_t>(std::stoull(cli->get("seed").value_or("7")));
    // --level large: the soak benchmark's generated grid of rooms (--columns x --rows), many more boxes.
    Result<level::Level> lv = Error("no level");
    if (level_file == "large") {
        soak::LargeLevelOptions large;
        large.columns = std::max(1, std::stoi(cli->get("columns").value_or("6")));
        large.rows = std::max(1, std::stoi(cli->get("rows").value_or("5")));
        lv = soak::large_level(large);
    } else {
        lv = level::load_level_file(level_file);
    }
    if (!lv) {
        std::fprintf(stderr, "ks_bench shots: %s\n", lv.error().str().c_str());
        return 1;
    }
    auto g = game::Game::create(*lv);
    if (!g) {
        std::fprintf(stderr, "ks_bench shots: %s\n", g.error().str().c_str());
        return 1;
    }
    const World& w = (*g)->world();
    const std::vector<Shot> shots = make_shots(**g, count, seed);

    std::vector<RayHit> scratch;
    scratch.reserve(256);
    int hits = 0, differ = 0;
    for (const Shot& s : shots) {
        RayHit a, b;
        const bool ha = w.ray_closest(s.ray, a, s.filter), hb = first_of_all(w, s, scratch, b);
        hits += ha;
        if (ha != hb || (ha && (!(a.body == b.body) || a.distance != b.distance))) ++differ;
    }
    RayHit sink;
    const double closest =
        shots_per_second(shots, seconds, [&](const Shot& s) { w.ray_closest(s.ray, sink, s.filter); });
    const double all =
        shots_per_second(shots, seconds, [&](const Shot& s) { first_of_all(w, s, scratch, sink); });
    std::printf("ks_bench shots: %s, %zu bodies, %d shots (%d hit), load %s\n", level_file.c_str(),
                w.body_count(), count, hits, load_average().c_str());
    std::printf("  %-36s %12.0f shots/s (thread CPU time)\n", "ray_all, first passing (before)", all);
    std::printf("  %-36s %12.0f shots/s  %.2fx\n", "ray_closest with the filter (now)", closest,
                closest / all);
    std::printf("  shots whose hit differs: %d\n", differ);
    if (cli->has("json"))
        std::printf("{\"bench\":\"shots\",\"shots\":%d,\"hits\":%d,\"differ\":%d,\"ray_all_sps\":%.0f,"
                    "\"closest_sps\":%.0f}\n",
                    count, hits, differ, all, closest);
    return differ == 0 ? 0 : 1;
}

const ks::bench::Registrar registrar(
    {"shots", "game shots/s: closest-hit with filter vs ray_all + first; --level FILE", shots_command});

} // namespace
} // namespace ks::physics::bench
