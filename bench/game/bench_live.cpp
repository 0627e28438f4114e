// ks_bench live: what a live play-test edit costs the running game (docs/performance.md, "Live edits (issue
// 29 item 1)"), the way before and the way now, in one run on one level (levels/main.json):
//   - a moved robot: the game's rebuild (game/live_update.h) and the view: the level scene and its light bake
//     built again (before) or kept because the scenery is the same (level/scenery.h, now);
//   - a moved wall: the navigation mesh built whole (before) or only its touched tiles (NavMesh::rebuild,
//     now), and the view's scene: laid out and baked on the spot (full bake) against laid out alone with
//     the bake computed afterwards (preview and full quality).
// Median wall milliseconds over --reps runs (3). Needs GL for the scene (xvfb-run -a ks_bench live).
#include "bench_registry.h"
#include "core/cli.h"
#include "core/log.h"
#include "core/paths.h"
#include "editor/median_time.h"
#include "game/game.h"
#include "game/live_update.h"
#include "level/level_io.h"
#include "level/scenery.h"
#include "nav/nav_mesh.h"
#include "render/level_scene.h"
#include "shell/offscreen_context.h"

#include <cstdio>
#include <string>

namespace ks::bench {
namespace {

// The part of the level the game's view builds its scene from (runtime/app/world_view.h, static_part).
level::Level scenery_of(const level::Level& level) {
    level::Level out = level;
    std::erase_if(out.entities, [](const level::Entity& e) { return !level::is_scenery(e.type()); });
    return out;
}

level::Entity* named(level::Level& level, const std::string& name, level::EntityType type) {
    for (auto& e : level.entities)
        if (e.type() == type && (name.empty() || e.name == name)) return &e;
    return nullptr;
}

int run_live(int argc, const char* const* argv) {
    auto cl = CommandLine::parse(argc, argv, {});
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    if (auto unknown = cl->unknown({"level", "reps"}); !unknown.empty()) {
        log::error("ks_bench live: unknown option --", unknown.front(), " (use --level FILE --reps N)");
        return 2;
    }
    auto reps_arg = cl->get_int("reps", 3, 1, 50);
    if (!reps_arg) {
        log::error(reps_arg.error().str());
        return 2;
    }
    const int reps = *reps_arg;
    auto path = paths::resolve_user_path(cl->get_or("level", paths::level("main.json").string()));
    auto before = level::load_level_file(path);
    if (!before) {
        log::error(before.error().str());
        return 2;
    }
    auto ctx = shell::OffscreenContext::create(64, 64);
    if (!ctx) {
        log::error(ctx.error().str(), "\n  run it as: xvfb-run -a ks_bench live");
        return 3;
    }
    render::AssetLibrary assets(paths::asset(""));
    auto running = game::Game::create(*before, {});
    if (!running || !(*running)->navigation()) {
        log::error(running ? (*running)->navigation_error() : running.error().str());
        return 2;
    }
    const game::Game& game = **running;
    const nav::NavMesh& mesh = *game.navigation();

    level::Level robot_moved = *before, wall_moved = *before;
    level::Entity* robot = named(robot_moved, "", level::EntityType::Robot);
    level::Entity* wall = named(wall_moved, "Room 1 east wall", level::EntityType::Wall);
    if (!wall) wall = named(wall_moved, "", level::EntityType::Wall);
    if (!robot || !wall) {
        log::error("ks_bench live: the level needs a robot and a wall");
        return 2;
    }
    robot->position.x += 2.0f;
    wall->position.x += 1.0f;

    render::LevelSceneOptions baked; // the fast path's (llvmpipe): the full bake, not cached
    render::LevelSceneOptions deferred = baked;
    deferred.defer_bake = true;
    auto time_game = [&](const level::Level& edited) {
        if (auto check = game::rebuild_for_edit(game, *before, edited, {}); !check) {
            log::error(check.error().str());
            return -1.0;
        }
        return median_ms(reps, [&] { (void)game::rebuild_for_edit(game, *before, edited, {}); });
    };
    auto time_scene = [&](const level::Level& edited, const render::LevelSceneOptions& options) {
        const level::Level part = scenery_of(edited);
        return median_ms(reps, [&] { (void)render::LevelScene::build(part, assets, options); });
    };

    std::printf("level %s, %d nav tiles (%d x %d), median of %d\n\n", path.filename().string().c_str(),
                mesh.stats().tile_columns * mesh.stats().tile_rows, mesh.stats().tile_columns,
                mesh.stats().tile_rows, reps);
    std::printf("| edit | step | before ms | now ms |\n|---|---|---|---|\n");

    const double same_scenery_ms = median_ms(reps, [&] { (void)level::same_scenery(*before, robot_moved); });
    const double robot_game = time_game(robot_moved);
    std::printf("| moved robot | game rebuild | %.1f | %.1f |\n", robot_game, robot_game);
    std::printf("| moved robot | view (scene + full bake / kept) | %.0f | %.2f |\n",
                time_scene(robot_moved, baked), same_scenery_ms);

    int built = 0;
    const double nav_full = median_ms(reps, [&] { (void)nav::NavMesh::build(wall_moved, mesh.settings()); });
    const double nav_tiles =
        median_ms(reps, [&] { (void)nav::NavMesh::rebuild(mesh, *before, wall_moved, &built); });
    std::printf("| moved wall | navigation mesh (all tiles / %d built) | %.0f | %.0f |\n", built, nav_full,
                nav_tiles);
    std::printf("| moved wall | game rebuild (with the mesh) | - | %.0f |\n", time_game(wall_moved));
    const double scene_baked = time_scene(wall_moved, baked);
    const double scene_laid_out = time_scene(wall_moved, deferred);
    auto scene = render::LevelScene::build(scenery_of(wall_moved), assets, deferred);
    auto bake_ms = [&](const render::BakeSettings& settings) {
        return median_ms(reps, [&] {
            render::LightBake copy = scene->light_bake();
            (void)copy.compute(scene->environment(), scene->bake_lights(), settings);
        });
    };
    std::printf("| moved wall | view: scene + full bake / scene laid out | %.0f | %.0f |\n", scene_baked,
                scene_laid_out);
    std::printf("| moved wall | bake alone, preview / full | %.0f | %.0f |\n",
                bake_ms(render::BakeSettings::preview()), bake_ms(render::BakeSettings::full()));
    return 0;
}

const Registrar kLive({"live", "a live play-test edit's cost: moved robot and moved wall, before and now",
                       run_live, false});

} // namespace
} // namespace ks::bench
