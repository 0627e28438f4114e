// render::BackgroundBake: a scene built with its light map laid out (defer_bake) gets the light map a worker
// thread computed, equal to the bake done on the spot; a bake of an older build, or a cancelled one, is
// never handed over.
#include "gl_test_support.h"
#include "test_support.h"

#include "render/asset_library.h"
#include "render/background_bake.h"
#include "render/level_scene.h"

#include <doctest/doctest.h>

#include <chrono>
#include <thread>

using namespace ks;
using namespace ks::render;

namespace {

level::Level lit_room() {
    level::Level level;
    auto& floor = level.add(level::EntityType::Floor, Vec3(0.0f), "Floor").as<level::FloorProps>();
    floor.size = Vec2(12.0f, 12.0f);
    level.add(level::EntityType::Wall, Vec3(0.0f, 0.0f, -4.0f), "Wall");
    level.add(level::EntityType::TopLight, Vec3(0.0f, 6.0f, 2.0f), "Lamp");
    return level;
}

// Waits (up to a minute: a loaded machine) for the worker, then hands its bake over.
bool finish_when_done(BackgroundBake& bake, LevelScene& scene, unsigned long long build) {
    for (int i = 0; i < 6000 && bake.running(); ++i) {
        if (bake.finish(scene, build)) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

} // namespace

TEST_CASE("a background bake hands the scene the light map a bake on the spot computes") {
    REQUIRE_MESSAGE(test::gl_context(), "no display: run the GL tests under xvfb-run (./run.sh test does)");
    AssetLibrary assets(test::source_dir() / "assets");
    const level::Level level = lit_room();
    LevelSceneOptions now = test::direct_light_only();
    auto baked = LevelScene::build(level, assets, now);
    LevelSceneOptions later = now;
    later.defer_bake = true;
    auto scene = LevelScene::build(level, assets, later);
    REQUIRE(scene->light_bake().laid_out());
    REQUIRE(scene->light_bake().texels().empty());

    BackgroundBake bake;
    bake.start(*scene, 7, BakeSettings::direct_only());
    CHECK(bake.running());
    REQUIRE(finish_when_done(bake, *scene, 7));
    CHECK_FALSE(bake.running());
    CHECK(scene->light_bake().texels() == baked->light_bake().texels());

    SUBCASE("a bake for an older build is dropped") {
        auto other = LevelScene::build(level, assets, later);
        bake.start(*other, 8, BakeSettings::direct_only());
        CHECK_FALSE(finish_when_done(bake, *other, 9));
        CHECK(other->light_bake().texels().empty());
    }
    SUBCASE("a cancelled bake is not handed over, and a scene without a laid-out map starts none") {
        auto other = LevelScene::build(level, assets, later);
        bake.start(*other, 8, BakeSettings::full());
        bake.cancel();
        CHECK_FALSE(bake.running());
        CHECK_FALSE(bake.finish(*other, 8));
        CHECK(other->light_bake().texels().empty());
        LevelSceneOptions none = now;
        none.bake_light_map = false;
        auto unlit = LevelScene::build(level, assets, none);
        bake.start(*unlit, 9, BakeSettings::direct_only());
        CHECK_FALSE(bake.running());
    }
}
