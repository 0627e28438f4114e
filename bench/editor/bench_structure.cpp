// ks_bench structure: groups, layers and prefabs on a large level, headless (the editor's model code, no
// window), against the frame budget (16.7 ms at 60 Hz) and against placing one entity in the same run.
//   - a level of about 2 000 entities (generated rooms, as ks_bench editor's), each operation + its undo;
//   - prefab placement and the update of every instance when a prefab changes, against the instance count.
#include "bench_registry.h"
#include "core/files.h"
#include "core/paths.h"
#include "editor/median_time.h"
#include "level/level_io.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_groups.h"
#include "model/edit_layers.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/editor.h"
#include "model/prefab.h"
#include "soak/soak.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace ks;
constexpr double kFrameMs = 1000.0 / 60.0;

using bench::median_ms;

// Rooms until the level holds at least `entities` entities.
level::Level level_of(size_t entities) {
    soak::LargeLevelOptions options;
    options.robots_per_room = 6;
    for (int side = 4;; ++side) {
        options.columns = options.rows = side;
        level::Level lv = soak::large_level(options);
        if (lv.entities.size() >= entities) return lv;
    }
}

void fail(const Error& e) {
    std::fprintf(stderr, "%s\n", e.str().c_str());
    std::exit(1);
}

int run_structure(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--quick")) quick = true;
    const int reps = quick ? 3 : 9;
    std::error_code ec;
    const auto dir =
        std::filesystem::temp_directory_path() / ("ks-bench-structure-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir / "prefabs", ec);

    editor::Editor ed;
    ed.prefabs().set_folders({dir / "prefabs", paths::data_root() / "prefabs"});
    const level::Level big = level_of(2000);
    if (auto r = level::save_level_file(dir / "big.json", big); !r) fail(r.error());
    if (auto r = open(ed, dir / "big.json"); !r) fail(r.error());
    const size_t n = ed.level().entities.size();
    std::vector<int> half, hundred;
    for (const auto& e : ed.level().entities) {
        if (half.size() < n / 2) half.push_back(e.id);
        if (hundred.size() < 100) hundred.push_back(e.id);
    }

    std::printf("structure benchmark: groups, layers and prefabs in the editor model (no window)\n\n");
    std::printf("1. on a level of %zu entities, each with its undo; median of %d; frame = %.1f ms\n", n, reps,
                kFrameMs);
    std::printf("%-52s %10s %10s %12s\n", "operation", "ms", "frames", "x place one");
    const double base = median_ms(reps, [&] {
        (void)place(ed, level::EntityType::Robot, Vec3(20.0f, 0.0f, -20.0f));
        ed.undo();
    });
    auto row = [&](const char* what, double ms) {
        std::printf("%-52s %10.4f %10.4f %12.1f\n", what, ms, ms / kFrameMs, ms / base);
    };
    row("place one entity + undo (the baseline)", base);
    auto group_undo = [&](const std::vector<int>& ids) {
        return median_ms(reps, [&] {
            (void)select(ed, ids);
            if (auto r = group_selection(ed); !r) fail(r.error());
            ed.undo();
        });
    };
    row("group 100 entities + undo", group_undo(hundred));
    row("group half the level + undo", group_undo(half));
    (void)select(ed, half);
    if (auto r = group_selection(ed, "half"); !r) fail(r.error());
    row("click a member of the half-level group (select it)",
        median_ms(reps, [&] { (void)select_picked(ed, half[half.size() / 2]); }));
    row("move the half-level group + undo", median_ms(reps, [&] {
            (void)move_selection(ed, Vec3(1.0f, 0.0f, 0.0f));
            ed.undo();
        }));
    row("duplicate the half-level group + undo", median_ms(reps, [&] {
            (void)duplicate(ed);
            ed.undo();
        }));
    ed.undo(); // the group
    if (auto r = layer_add(ed, "half"); !r) fail(r.error());
    (void)select(ed, half);
    if (auto r = move_selection_to_layer(ed, 1); !r) fail(r.error());
    row("hide + show a layer of half the level", median_ms(reps, [&] {
            (void)layer_set_visible(ed, 1, false);
            (void)layer_set_visible(ed, 1, true);
        }));
    row("place the doorway prefab + undo", median_ms(reps, [&] {
            if (auto r = place_prefab(ed, "doorway", Vec3(10.0f, 0.0f, -10.0f)); !r) fail(r.error());
            ed.undo();
        }));

    // 2. Updating instances when a prefab changes, against how many there are.
    std::printf("\n2. a prefab changed on disk: every instance follows (update_prefab_instances + undo)\n");
    std::printf("%-12s %10s %10s %16s\n", "instances", "ms", "frames", "ms per instance");
    auto prefab = ed.prefabs().get("doorway");
    if (!prefab) fail(prefab.error());
    int placed = 0;
    for (int count : {1, 10, 50, 200}) {
        for (; placed < count; ++placed)
            if (auto r =
                    place_prefab(ed, "doorway", Vec3(20.0f * (placed % 20), 0.0f, -20.0f * (placed / 20)));
                !r)
                fail(r.error());
        editor::Prefab taller = *prefab;
        taller.name = "doorway";
        for (level::Entity& e : taller.entities)
            if (auto* wall = e.try_as<level::WallProps>()) wall->size.y = 18.0f;
        const double ms = median_ms(reps, [&] {
            // A different prefab each time, so every instance really changes.
            for (level::Entity& e : taller.entities)
                if (auto* wall = e.try_as<level::WallProps>())
                    wall->size.y = wall->size.y == 18.0f ? 20.0f : 18.0f;
            (void)files::write_atomic(dir / "prefabs" / "doorway.json", editor::prefab_to_text(taller));
            ed.prefabs().set_folders({dir / "prefabs"}); // the file's time may not move within a second
            if (auto r = update_prefab_instances(ed); !r) fail(r.error());
            ed.undo();
        });
        std::printf("%-12d %10.4f %10.4f %16.5f\n", count, ms, ms / kFrameMs, ms / count);
    }
    std::filesystem::remove_all(dir, ec);
    return 0;
}

bench::Registrar
    registrar({"structure",
               "editor groups, layers and prefabs on a 2 000-entity level, against one frame and "
               "against placing one entity",
               run_structure});

} // namespace
