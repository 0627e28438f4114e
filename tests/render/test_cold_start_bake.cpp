// The game's cold start (LevelSceneOptions::background_bake): the direct light first, the full bake on a
// worker (render/background_bake.h) swapped in when done and stored in the disk cache, the next start reads
// it; the result is the bake a synchronous build makes, texel for texel.
#include "gl_test_support.h"
#include "test_support.h"

#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/background_bake.h"
#include "render/level_scene.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

using namespace ks;
using namespace ks::render;

namespace {
// XDG_CACHE_HOME pointed at a fresh folder for the test's life (the bake cache is the user's).
class ScratchCache {
  public:
    ScratchCache() {
        const char* old = std::getenv("XDG_CACHE_HOME");
        had_ = old != nullptr;
        saved_ = old ? old : "";
        setenv("XDG_CACHE_HOME", dir_.path().c_str(), 1);
    }
    ~ScratchCache() { had_ ? setenv("XDG_CACHE_HOME", saved_.c_str(), 1) : unsetenv("XDG_CACHE_HOME"); }

  private:
    test::ScratchDir dir_;
    bool had_ = false;
    std::string saved_;
};

LevelSceneOptions background(bool on) {
    LevelSceneOptions options;
    options.bake = BakeSettings::preview(); // a small level at the editor's quality: quick, still bounced
    options.cache_bake = true;
    options.background_bake = on;
    return options;
}

// The light map as the scene draws it (emit() re-combines the lights' switches).
std::vector<Vec3> texels(LevelScene& scene) {
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    scene.emit(instances, lights);
    return scene.light_bake().texels();
}

void finish(BackgroundBake& bake, LevelScene& scene) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (!bake.finish(scene, 1) && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
}
} // namespace

TEST_CASE("background bake: direct light first, the full bake swapped in, stored, read on the next start") {
    REQUIRE_MESSAGE(test::gl_context(), "no display: run the GL tests under xvfb-run (./run.sh test does)");
    auto level = level::load_level_file(test::source_dir() / "levels" / "archive.json");
    REQUIRE(level);
    AssetLibrary assets(test::source_dir() / "assets");
    ScratchCache cache;

    // What a screenshot run (and the game before) shows: the bake done before the first frame.
    LevelSceneOptions synchronous = background(false);
    synchronous.cache_bake = false;
    auto reference = LevelScene::build(*level, assets, synchronous);
    CHECK_FALSE(reference->pending_bake());

    auto cold = LevelScene::build(*level, assets, background(true));
    REQUIRE(cold->pending_bake());
    CHECK(cold->light_bake().laid_out());
    CHECK(cold->bake_stats().rays == 0); // the direct light only, for now
    CHECK(texels(*cold) != texels(*reference));
    BackgroundBake worker;
    worker.start(*cold, 1, *cold->pending_bake(), cold->pending_bake_store());
    finish(worker, *cold);
    CHECK_FALSE(cold->pending_bake());
    CHECK(cold->bake_stats().rays > 0);
    CHECK(texels(*cold) == texels(*reference));

    auto warm = LevelScene::build(*level, assets, background(true)); // stored by the worker
    CHECK_FALSE(warm->pending_bake());
    CHECK(texels(*warm) == texels(*reference));
}
