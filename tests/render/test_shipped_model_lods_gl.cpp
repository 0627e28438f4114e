// The shipped models drawn at the asset generator's levels of detail (render::AssetLibrary::model_levels,
// LevelScene, pick_model_level): each loads with the levels its list names, every level with the model's
// nodes; a robot far away is drawn coarser and looks the same within about a pixel; a bad list or level is
// one warning and the model is drawn in full.
#include "gl_test_support.h"
#include "test_support.h"

#include "core/log.h"
#include "core/paths.h"
#include "level/level.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/png_writer.h"
#include "render/scene_renderer.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::render {
namespace {

int triangles(const Model& model) {
    int n = 0;
    for (const ModelMesh& m : model.meshes) n += m.gpu->index_count() / 3;
    return n;
}

// Pixels whose largest channel difference is over `threshold` (0..255).
int pixels_changed_over(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
                        int threshold) {
    int n = 0;
    for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[i + c]) - int(b[i + c])));
        n += worst > threshold ? 1 : 0;
    }
    return n;
}

// Pixels that differ from the backdrop (the robot's coverage).
int pixels_covered(const std::vector<unsigned char>& image, const std::vector<unsigned char>& empty) {
    return pixels_changed_over(image, empty, 8);
}

} // namespace

TEST_CASE(
    "the shipped models load with the generator's levels of detail, every level with the model's nodes") {
    KS_REQUIRE_GL();
    AssetLibrary assets(test::source_dir() / "assets");
    for (const char* name :
         {"robot", "door", "floor_light", "top_light", "control_panel", "gas_cylinder", "pickup_health"}) {
        const std::string model_name = name;
        CAPTURE(model_name);
        const ModelLevels& levels = assets.model_levels(name);
        CHECK(&assets.model(name) == &levels.full());
        REQUIRE(levels.levels.size() >= 2);
        REQUIRE(levels.relative_errors.size() == levels.levels.size());
        CHECK(levels.relative_errors[0] == 0.0f);
        for (std::size_t k = 1; k < levels.levels.size(); ++k) {
            CHECK_FALSE(levels.levels[k]->placeholder);
            CHECK(levels.levels[k]->node_names() == levels.full().node_names());
            CHECK(levels.relative_errors[k] > levels.relative_errors[k - 1]);
            CHECK(levels.relative_errors[k] < 0.06f); // each a fraction of the model's size
            CHECK(triangles(*levels.levels[k]) < triangles(*levels.levels[k - 1]));
        }
    }
    CHECK(assets.model_levels("rifle").levels.size() == 1); // held in the hand: always in full
}

TEST_CASE("a robot far away is drawn at a coarser level and looks the same within about a pixel") {
    KS_REQUIRE_GL();
    auto* ctx = test::gl_context();
    AssetLibrary assets(test::source_dir() / "assets");
    level::Level level;
    level.add(level::EntityType::Robot, {0, 0, 0}, "Robot");
    const int id = level.entities.back().id;
    RendererSettings settings;
    settings.quality = RenderQuality::Fast;
    settings.render_scale = 1.0f;
    auto renderer = SceneRenderer::create(assets.textures(), settings);
    REQUIRE(renderer);
    LevelSceneOptions options;
    options.bake_light_map = false;
    auto scene = LevelScene::build(level, assets, options);
    std::vector<MeshInstance> instances, none;
    std::vector<Light> lights;
    auto draw = [&](const geometry::Camera& camera, const std::vector<MeshInstance>& what) {
        ctx->bind();
        SceneFrame frame;
        frame.camera = camera;
        frame.environment = scene->environment();
        frame.instances = &what;
        frame.lights = &lights;
        frame.width = ctx->width();
        frame.height = ctx->height();
        (*renderer)->render(frame);
        return ctx->read_rgb();
    };
    int coarsest = 0;
    for (float distance : {3.0f, 6.0f, 12.0f, 24.0f, 48.0f}) {
        CAPTURE(distance);
        geometry::Camera camera;
        camera.position = {0.0f, 1.5f, distance};
        camera.aspect = static_cast<float>(test::kGlWidth) / test::kGlHeight;
        scene->set_model_lods(true);
        scene->set_view(camera, test::kGlHeight);
        scene->emit(instances, lights);
        const int lod = scene->model_lod(id);
        CHECK(lod >= coarsest); // farther never finer
        coarsest = lod;
        const auto coarse = draw(camera, instances);
        scene->set_model_lods(false);
        scene->emit(instances, lights);
        CHECK(scene->model_lod(id) == 0);
        const auto full = draw(camera, instances);
        const auto empty = draw(camera, none);
        const int covered = pixels_covered(full, empty);
        const int changed = pixels_changed_over(coarse, full, 48);
        MESSAGE("distance " << distance << ": level " << lod << ", " << covered << " robot pixels, "
                            << changed << " changed by more than 48/255, mean difference "
                            << test::mean_abs_diff(coarse, full));
        if (const char* dir = std::getenv("KS_TEST_SHOTS")) {
            const std::string stem = std::string(dir) + "/robot_lod_" + std::to_string(int(distance));
            (void)write_png_rgb(stem + "_coarse.png", test::kGlWidth, test::kGlHeight, coarse.data(),
                                test::kGlWidth * 3);
            (void)write_png_rgb(stem + "_full.png", test::kGlWidth, test::kGlHeight, full.data(),
                                test::kGlWidth * 3);
        }
        // An error of at most about a pixel moves edges by about a pixel: the changed pixels stay a thin
        // share of the robot's.
        CHECK(changed <= std::max(4, covered / 10));
        CHECK(test::mean_abs_diff(coarse, full) < 1.0);
    }
    CHECK(coarsest >= 2);
}

TEST_CASE("a broken level list or level is one warning and the model is drawn in full") {
    KS_REQUIRE_GL();
    test::ScratchDir dir;
    const auto models = test::source_dir() / "assets/models";
    std::filesystem::create_directories(dir / "models");
    std::filesystem::create_directory_symlink(test::source_dir() / "assets/textures", dir / "textures");
    for (const char* file : {"robot.gltf", "robot.bin", "gas_cylinder.gltf", "gas_cylinder.bin"})
        std::filesystem::copy_file(models / file, dir / "models" / file);
    const std::string list = test::read_file(models / "robot.lods.json");
    struct Case {
        std::string list_text;
        const char* level_from; // copied as robot_lod1.gltf/.bin (nullptr: none)
        std::string expected;
    };
    const Case cases[] = {
        {"{ \"format\": ", nullptr, "robot.lods.json:1:"},
        {list, nullptr, "robot_lod1"},              // a level that is not there
        {list, "gas_cylinder", "its nodes differ"}, // a level of another model
    };
    for (const Case& c : cases) {
        CAPTURE(c.expected);
        test::write_file(dir / "models/robot.lods.json", c.list_text);
        for (const char* ext : {".gltf", ".bin"})
            std::filesystem::remove(dir / "models" / ("robot_lod1" + std::string(ext)));
        if (c.level_from) {
            // The bin keeps its own name inside the glTF, so copy both under the level's names.
            std::string gltf = test::read_file(models / (std::string(c.level_from) + ".gltf"));
            const std::string bin = std::string(c.level_from) + ".bin";
            gltf.replace(gltf.find(bin), bin.size(), "robot_lod1.bin");
            test::write_file(dir / "models/robot_lod1.gltf", gltf);
            std::filesystem::copy_file(models / bin, dir / "models/robot_lod1.bin");
        }
        log::Capture capture;
        AssetLibrary assets(dir.path());
        const ModelLevels& levels = assets.model_levels("robot");
        CHECK(levels.levels.size() == 1);
        CHECK_FALSE(levels.full().placeholder);
        CHECK_MESSAGE(test::contains_text(capture.text(), c.expected), capture.text());
        CHECK(test::contains_text(capture.text(), "robot"));
    }
}

} // namespace ks::render
