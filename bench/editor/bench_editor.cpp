// ks_bench editor: what a level designer waits on, headless (the editor's model code, no window).
//   1. live validation: the rules without the walk check (they run after every edit) and the walk check
//      itself (reachability on the player's navigation mesh: it runs when walkability changes), on the main
//      level and on generated levels of 1 to 144 rooms;
//   2. speed against error of the walk check's mesh cell size: a room split by a wall with a gap of width w
//      (1.50 .. 3.00) at eight sub-cell offsets; the truth is geometric (the body, radius r, passes iff
//      w >= 2r); wrong answers per cell size against the time one check (mesh build + queries) takes;
//   3. edits on a large level: place + undo, move of every entity + undo, a pick ray, save and open.
// Writes docs/bench/editor_walk_cell.csv (not with --quick).
#include "bench_registry.h"
#include "core/paths.h"
#include "editor/median_time.h"
#include "level/level_io.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/editor.h"
#include "model/reachability.h"
#include "model/validation.h"
#include "soak/soak.h"
#include "view/picking.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace ks;
using Clock = std::chrono::steady_clock;

std::filesystem::path out_dir() {
    return std::filesystem::path(KS_SOURCE_DIR) / "docs" / "bench";
}

using bench::median_ms;

// A 40 x 40 room split along z = 0 by a wall with a gap `width` wide centred at x = `offset`; the player
// starts on one side, the control panel stands on the other.
level::Level gap_level(float width, float offset) {
    level::Level lv;
    lv.name = "gap";
    lv.add(level::EntityType::Floor, Vec3(0.0f), "ground").as<level::FloorProps>().size = Vec2(40.0f, 40.0f);
    auto wall = [&](float x0, float x1) {
        auto& w = lv.add(level::EntityType::Wall, Vec3((x0 + x1) * 0.5f, 0.0f, 0.0f), "divider");
        w.as<level::WallProps>().size = Vec3(x1 - x0, 16.0f, 0.5f);
    };
    wall(-22.0f, offset - width * 0.5f);
    wall(offset + width * 0.5f, 22.0f);
    lv.add(level::EntityType::ControlPanel, Vec3(0.0f, 0.0f, -12.0f), "panel");
    lv.player_start.position = Vec3(0.0f, 0.0f, 12.0f);
    return lv;
}

int run_editor(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--quick")) quick = true;
    const int reps = quick ? 3 : 9;
    // A walk check on a large level builds a navigation mesh for seconds: fewer repetitions there.
    const int walk_reps = quick ? 1 : 3;

    // 1. Live validation against level size.
    std::printf("editor benchmark: the model code behind the editor's panels (no window)\n\n");
    std::printf("1. live validation: every rule but the walk check (median of %d), the walk check alone "
                "(median of %d)\n",
                reps, walk_reps);
    std::printf("%-22s %9s %14s %14s %12s %10s\n", "level", "entities", "no walk ms", "walk ms", "polygons",
                "reachable");
    struct Case {
        std::string name;
        level::Level level;
    };
    std::vector<Case> cases;
    if (auto main_level = level::load_level_file(paths::level("main.json")))
        cases.push_back({"main.json", std::move(*main_level)});
    else
        std::fprintf(stderr, "%s\n", main_level.error().str().c_str());
    for (int side : {1, 3, 6, 12}) {
        if (quick && side > 6) continue;
        soak::LargeLevelOptions o;
        o.columns = side, o.rows = side;
        cases.push_back({std::to_string(side) + "x" + std::to_string(side) + " rooms", soak::large_level(o)});
    }
    for (const Case& c : cases) {
        editor::ValidationOptions with, without;
        without.check_reachability = false;
        const double rules = median_ms(reps, [&] { (void)editor::validate_design(c.level, without); });
        editor::WalkCheck walk;
        const double walk_ms =
            median_ms(walk_reps, [&] { walk = editor::walk_to_control_panel(c.level, with); });
        std::printf("%-22s %9zu %14.3f %14.1f %12d %10s\n", c.name.c_str(), c.level.entities.size(), rules,
                    walk_ms, walk.polygons,
                    !walk.decided    ? "undecided"
                    : walk.reachable ? "yes"
                                     : "no");
    }

    // 2. The walk check's cell size: speed against error.
    const int offsets = quick ? 2 : 8;
    std::printf("\n2. walk check (nav mesh) cell size against error: a wall gap of width w in [1.50, 3.00] "
                "(step 0.05) at %d offsets;\n   truth: passable iff w >= 2 x radius (%.2f); time per check "
                "(mesh build + queries) on this 40 x 40 room\n",
                offsets, 2.0f * editor::CharacterLimits{}.radius);
    std::printf("%8s %10s %14s %16s %12s %14s\n", "cell", "cases", "false open", "false closed", "error %",
                "ms per check");
    std::FILE* csv = nullptr;
    std::error_code ec;
    if (!quick) {
        std::filesystem::create_directories(out_dir(), ec);
        csv = std::fopen((out_dir() / "editor_walk_cell.csv").string().c_str(), "w");
    }
    if (csv) std::fprintf(csv, "cell,cases,false_open,false_closed,error_percent,ms_per_check\n");
    const float radius = editor::CharacterLimits{}.radius;
    // Divisors of the radius (erosion is whole cells) and 0.4, which erodes a third of a cell too far.
    for (float cell : {0.1f, 0.2f, 0.25f, 0.4f, 0.5f}) {
        if (quick && cell < 0.2f) continue;
        editor::ValidationOptions o;
        o.walk_cell = cell;
        int total = 0, false_open = 0, false_closed = 0;
        double seconds = 0.0;
        for (int k = 0; k < offsets; ++k) {
            const float offset = 0.173f * static_cast<float>(k);
            for (int i = 0; i <= 30; ++i) {
                const float width = 1.5f + 0.05f * static_cast<float>(i);
                const level::Level lv = gap_level(width, offset);
                const auto t0 = Clock::now();
                const auto stats = editor::walk_to_control_panel(lv, o);
                seconds += std::chrono::duration<double>(Clock::now() - t0).count();
                const bool truth = width >= 2.0f * radius;
                ++total;
                if (!stats.decided) continue;
                if (stats.reachable && !truth) ++false_open;
                if (!stats.reachable && truth) ++false_closed;
            }
        }
        const double error = 100.0 * (false_open + false_closed) / total, ms = 1000.0 * seconds / total;
        std::printf("%8.3f %10d %14d %16d %12.1f %14.3f\n", cell, total, false_open, false_closed, error, ms);
        if (csv)
            std::fprintf(csv, "%g,%d,%d,%d,%.2f,%.4f\n", cell, total, false_open, false_closed, error, ms);
    }
    if (csv) std::fclose(csv);

    // 3. Edits on a large level, through the same Editor the panels call.
    soak::LargeLevelOptions big;
    big.columns = quick ? 6 : 12, big.rows = quick ? 5 : 10;
    const auto dir = std::filesystem::temp_directory_path() / ("ks-bench-editor-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir, ec);
    const auto file = dir / "large.json";
    if (auto r = level::save_level_file(file, soak::large_level(big)); !r) {
        std::fprintf(stderr, "%s\n", r.error().str().c_str());
        return 1;
    }
    editor::Editor ed;
    if (auto r = open(ed, file); !r) {
        std::fprintf(stderr, "%s\n", r.error().str().c_str());
        return 1;
    }
    const size_t entities = ed.level().entities.size();
    std::printf("\n3. edits on a generated %d x %d room level (%zu entities), median of %d (%d for the wall "
                "move: it rebuilds the mesh twice)\n",
                big.columns, big.rows, entities, reps, walk_reps);
    std::printf("%-44s %12s\n", "operation", "ms");
    auto row = [](const char* what, double ms) { std::printf("%-44s %12.4f\n", what, ms); };
    row("place a robot + undo (no validation)", median_ms(reps, [&] {
            (void)place(ed, level::EntityType::Robot, Vec3(20.0f, 0.0f, -20.0f));
            ed.undo();
        }));
    row("place a robot + undo + live validation", median_ms(reps, [&] {
            (void)place(ed, level::EntityType::Robot, Vec3(20.0f, 0.0f, -20.0f));
            (void)ed.issues();
            ed.undo();
            (void)ed.issues();
        }));
    {
        // A wall moved is what the walk check reads: it runs after the edit and after the undo.
        int wall = 0;
        for (const auto& e : ed.level().entities)
            if (e.type() == level::EntityType::Wall) wall = e.id;
        (void)select(ed, {wall});
        const size_t walks = ed.validation().walk_checks_run();
        row("move a wall + undo + live validation", median_ms(walk_reps, [&] {
                (void)move_selection(ed, Vec3(0.5f, 0.0f, 0.0f));
                (void)ed.issues();
                ed.undo();
                (void)ed.issues();
            }));
        std::printf("%-44s %12zu\n", "  (walk checks run by those edits)",
                    ed.validation().walk_checks_run() - walks);
    }
    select_all(ed);
    row("move every entity + undo", median_ms(reps, [&] {
            (void)move_selection(ed, Vec3(1.0f, 0.0f, 0.0f));
            ed.undo();
        }));
    ed.clear_selection();
    {
        // Rays straight down over the level, as a top-view click.
        const int rays = 1000;
        const float width = 40.0f * static_cast<float>(big.columns),
                    depth = 40.0f * static_cast<float>(big.rows);
        int hits = 0;
        const double ms = median_ms(reps, [&] {
            hits = 0;
            for (int i = 0; i < rays; ++i) {
                geometry::Ray ray;
                ray.origin = Vec3(width * static_cast<float>((i * 37) % rays) / rays, 100.0f,
                                  -depth * static_cast<float>((i * 61) % rays) / rays);
                ray.direction = Vec3(0.0f, -1.0f, 0.0f);
                hits += editor::pick_entity(ed.doc(), ray, [](const level::Entity&) { return true; }).id != 0;
            }
        });
        std::printf("%-44s %12.4f   (%d of %d rays hit)\n", "pick one entity under a click", ms / rays, hits,
                    rays);
    }
    row("save (validate + atomic write)", median_ms(reps, [&] { (void)save(ed); }));
    row("open (parse + load)", median_ms(reps, [&] { (void)open(ed, file); }));
    std::filesystem::remove_all(dir, ec);
    return 0;
}

bench::Registrar
    registrar({"editor",
               "editor model: live validation vs level size, walk-check mesh cell vs error, edits on a "
               "large level",
               run_editor});

} // namespace
