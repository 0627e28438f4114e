// ks_bench nav: navigation mesh build time (levels/main.json and a generated level ten times its floor
// area), path query time (median and p99 over random reachable pairs), and the cell-size sweep (build time
// against path-length error and wrongly closed gaps, nav_sweep.h). Writes docs/bench/nav_cell_size.csv and
// nav_cell_size.png; --quick runs a short version and leaves docs/bench/ as it is.
#include "bench_registry.h"
#include "nav/nav_sweep.h"
#include "physics/bench_util.h"
#include "soak/soak.h"

#include "core/paths.h"
#include "level/level_io.h"
#include "nav/nav_mesh.h"
#include "physics/character.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace ks::bench {
namespace {

using physics::bench::fmt;

struct Options {
    bool quick = false;
};

nav::NavSettings robot_settings() {
    const physics::CharacterSettings character;
    return nav::robot_nav_settings(character.step_height, character.max_slope_degrees);
}

double median_build_ms(const level::Level& lv, const nav::NavSettings& s, int runs,
                       std::unique_ptr<nav::NavMesh>& mesh) {
    std::vector<double> ms;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        auto built = nav::NavMesh::build(lv, s);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        if (!built) {
            std::printf("build of '%s' failed: %s\n", lv.name.c_str(), built.error().str().c_str());
            return -1.0;
        }
        mesh = std::move(built.value());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

void open_all_doors(const level::Level& lv, nav::NavMesh& mesh) {
    for (const level::Entity& e : lv.entities)
        if (e.type() == level::EntityType::Door) (void)mesh.set_door_open(e.id, true);
}

struct QueryTimes {
    int pairs = 0;
    double median_us = 0.0, p99_us = 0.0, mean_corners = 0.0;
};

// Random pairs of points on the mesh that are reachable from each other, then find_path timed on each.
QueryTimes time_queries(nav::NavMesh& mesh, const level::Level& lv, int pairs, std::uint64_t seed) {
    (void)lv;
    std::vector<nav::NavTriangle> surface = mesh.triangles();
    std::erase_if(surface, [](const nav::NavTriangle& t) { return t.a.y > 0.5f; }); // the ground floor
    Rng rng(seed);
    const auto random_point = [&] {
        const nav::NavTriangle& t = surface[rng.below(static_cast<std::uint32_t>(surface.size()))];
        float u = rng.uniform(), v = rng.uniform();
        if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        return t.a + u * (t.b - t.a) + v * (t.c - t.a);
    };
    std::vector<std::pair<Vec3, Vec3>> chosen;
    for (int tries = 0; static_cast<int>(chosen.size()) < pairs && tries < pairs * 20; ++tries) {
        const Vec3 a = random_point(), b = random_point();
        if (mesh.reachable(a, b)) chosen.emplace_back(a, b);
    }
    std::vector<Vec3> path;
    path.reserve(1024);
    std::vector<double> us;
    double corners = 0.0;
    for (const auto& [a, b] : chosen) {
        const auto t0 = std::chrono::steady_clock::now();
        (void)mesh.find_path(a, b, path);
        us.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
        corners += static_cast<double>(path.size());
    }
    QueryTimes q;
    q.pairs = static_cast<int>(us.size());
    if (us.empty()) return q;
    std::sort(us.begin(), us.end());
    q.median_us = us[us.size() / 2];
    q.p99_us = us[std::min(us.size() - 1, us.size() * 99 / 100)];
    q.mean_corners = corners / static_cast<double>(us.size());
    return q;
}

float floor_area(const level::Level& lv) {
    float area = 0.0f;
    for (const level::Entity& e : lv.entities)
        if (const auto* f = e.try_as<level::FloorProps>(); f && !f->ceiling && e.position.y == 0.0f)
            area += f->size.x * f->size.y;
    return area;
}

void print_level_row(const char* label, const level::Level& lv, double ms, const nav::NavMesh& mesh,
                     const QueryTimes& q) {
    const nav::NavStats& s = mesh.stats();
    std::printf("%-30s %9.0f %6zu %9.1f %5dx%-4d %6d %8d %6d %9.1f %8.1f %7.1f\n", label, floor_area(lv),
                lv.entities.size(), ms, s.tile_columns, s.tile_rows, s.tiles_with_polygons, s.polygons,
                q.pairs, q.median_us, q.p99_us, q.mean_corners);
}

void write_sweep(const std::vector<nav_sweep::SweepRow>& rows) {
    std::vector<std::string> lines;
    for (const auto& r : rows)
        lines.push_back(fmt("%.2f", r.cell_size) + "," + fmt("%.1f", r.build_main_ms) + "," +
                        fmt("%.1f", r.build_field_ms) + "," + std::to_string(r.paths) + "," +
                        std::to_string(r.unreached) + "," + fmt("%.2f", r.mean_error_pct) + "," +
                        fmt("%.2f", r.max_error_pct) + "," + std::to_string(r.gaps_open) + "," +
                        std::to_string(r.wrongly_closed) + "," + std::to_string(r.gaps_closed) + "," +
                        std::to_string(r.wrongly_opened));
    physics::bench::write_csv(
        "nav_cell_size",
        "cell_size,build_main_ms,build_field_ms,paths,unreached,mean_error_pct,max_error_pct,"
        "gaps_open,wrongly_closed,gaps_closed,wrongly_opened",
        lines);
    physics::bench::plot(
        "nav_cell_size",
        "set multiplot layout 1,2\n"
        "set xlabel 'cell size (units)'\nset ylabel 'build time (ms)'\n"
        "set title 'mesh build time'\n"
        "plot 'nav_cell_size.csv' every ::1 using 1:2 with linespoints title 'levels/main.json', "
        "'' every ::1 using 1:3 with linespoints title 'obstacle field 60 x 60'\n"
        "set ylabel 'path length error (%) / gaps'\nset title 'error against the exact reference'\n"
        "plot 'nav_cell_size.csv' every ::1 using 1:6 with linespoints title 'mean path error %', "
        "'' every ::1 using 1:7 with linespoints title 'max path error %', "
        "'' every ::1 using 1:9 with linespoints title 'gaps wrongly closed', "
        "'' every ::1 using 1:11 with linespoints title 'gaps wrongly opened'\n"
        "unset multiplot\n");
}

int run(int argc, const char* const* argv) {
    Options o;
    const std::optional<bool> quick = ks::bench::quick_option(argc, argv);
    if (!quick) return 2;
    o.quick = *quick;
    const nav::NavSettings settings = robot_settings();
    auto main_level = level::load_level_file(paths::level("main.json"));
    if (!main_level) {
        std::printf("cannot load levels/main.json: %s\n", main_level.error().str().c_str());
        return 1;
    }
    soak::LargeLevelOptions large_options;
    large_options.columns = 15, large_options.rows = 10, large_options.robots_per_room = 0;
    const level::Level large = soak::large_level(large_options);

    std::printf(
        "load average %s; cell %.2f x %.2f, tiles of %d cells, agent r %.2f h %.2f climb %.2f slope %.0f\n\n",
        physics::bench::load_average().c_str(), settings.cell_size, settings.cell_height,
        settings.tile_size_cells, settings.agent_radius, settings.agent_height, settings.agent_climb,
        settings.agent_max_slope_degrees);
    std::printf("%-30s %9s %6s %9s %10s %6s %8s %6s %9s %8s %7s\n", "level", "floor", "ents", "build ms",
                "tiles", "filled", "polys", "pairs", "path µs", "p99 µs", "corners");
    const int runs = o.quick ? 1 : 3;
    std::unique_ptr<nav::NavMesh> mesh;
    const double main_ms = median_build_ms(*main_level, settings, runs, mesh);
    if (!mesh) return 1;
    open_all_doors(*main_level, *mesh);
    print_level_row("levels/main.json", *main_level, main_ms, *mesh,
                    time_queries(*mesh, *main_level, o.quick ? 100 : 2000, 1));
    nav::NavSettings plain = settings;
    plain.any_angle_paths = false;
    const double plain_ms = median_build_ms(*main_level, plain, 1, mesh);
    if (!mesh) return 1;
    open_all_doors(*main_level, *mesh);
    print_level_row("levels/main.json, plain A*", *main_level, plain_ms, *mesh,
                    time_queries(*mesh, *main_level, o.quick ? 100 : 2000, 1));
    const double large_ms = median_build_ms(large, settings, o.quick ? 1 : 2, mesh);
    if (!mesh) return 1;
    open_all_doors(large, *mesh);
    print_level_row(large.name.c_str(), large, large_ms, *mesh,
                    time_queries(*mesh, large, o.quick ? 50 : 500, 2));

    const auto field = nav_sweep::make_obstacle_field(24, o.quick ? 40 : 200, 3);
    const auto gaps = nav_sweep::make_gap_strips(settings.agent_radius, 4);
    std::printf("\ncell-size sweep: %zu field paths against the exact visibility-graph lengths, %zu gaps of "
                "2r-0.35 .. 2r+1.15\n",
                field.queries.size(), gaps.gaps.size());
    std::printf("%6s %6s %12s %13s %10s %8s %8s %14s %14s\n", "cell", "tile", "main ms", "field ms",
                "unreached", "mean %", "max %", "wrong closed", "wrong opened");
    std::vector<nav_sweep::SweepRow> rows;
    const std::vector<float> cells =
        o.quick ? std::vector<float>{0.2f, 0.4f, 0.8f} : std::vector<float>{0.2f, 0.3f, 0.4f, 0.6f, 0.8f};
    for (float cell : cells) {
        const auto r = nav_sweep::measure_cell_size(cell, settings, field, gaps, *main_level);
        std::printf("%6.2f %6d %12.1f %13.1f %6d/%-4d %8.2f %8.2f %8d/%-5d %8d/%-5d\n", r.cell_size,
                    nav_sweep::tile_cells_for(cell, settings), r.build_main_ms, r.build_field_ms, r.unreached,
                    r.paths, r.mean_error_pct, r.max_error_pct, r.wrongly_closed, r.gaps_open,
                    r.wrongly_opened, r.gaps_closed);
        rows.push_back(r);
    }
    if (o.quick) {
        std::printf("\n--quick: docs/bench/nav_* left as they are\n");
        return 0;
    }
    write_sweep(rows);
    return 0;
}

const Registrar registrar({"nav", "navigation mesh build time, path query time, cell size vs error", run});

} // namespace
} // namespace ks::bench
