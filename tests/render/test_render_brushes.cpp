// Brush entities drawn by the level scene on both render paths: visible, textured face by face with their
// materials, casting the sun's shadow onto a brush floor (shadow map on the full path, light map on the
// fast path), and a level with 500 brushes against the same level without them; a designer's model emitted at
// its level of detail.
#include "gl_test_support.h"
#include "test_support.h"

#include "brush/brush_build.h"
#include "core/log.h"
#include "core/paths.h"
#include "level/level.h"
#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace ks;
using namespace ks::render;

namespace {

brush::FaceAttributes material(const char* name, double scale = 4.0) {
    brush::FaceAttributes at;
    at.material = name;
    at.scale = {scale, scale};
    return at;
}

level::Entity brush_entity(int id, const brush::Brush& b) {
    level::Entity e;
    e.id = id;
    level::BrushProps props;
    props.brush = b;
    e.props = props;
    return e;
}

// A 40 x 40 brush floor (top at y = 0), a ramp (x -9..-3, rising toward -z to 4 high at z = -8) and a wall
// (x 2..8, 6 high, z -6..-5) whose front face (+z) is wood and every other face metal. The sun travels
// toward +z and down at 45 degrees, so the wall's shadow falls on the floor in front of it, z -5..1.
level::Level brush_level(bool with_brushes) {
    level::Level level;
    level.settings.sun_direction = Vec3(0.0f, -1.0f, 1.0f);
    level.settings.sun_intensity = 2.5f;
    level.settings.ambient_intensity = 0.6f;
    level.settings.fog_density = 0.0f;
    auto floor = brush::make_box({-20, -1, -20}, {20, 0, 20}, material("tiles"));
    REQUIRE(floor.ok());
    level.entities.push_back(brush_entity(1, *floor));
    if (!with_brushes) return level;
    const DVec3 profile[] = {{-9, 0, 0}, {-9, 0, -8}, {-9, 4, -8}};
    auto ramp = brush::make_extrusion(profile, {6, 0, 0}, material("concrete"));
    REQUIRE(ramp.ok());
    level.entities.push_back(brush_entity(2, *ramp));
    auto wall = brush::make_box({2, 0, -6}, {8, 6, -5}, material("metal"));
    REQUIRE(wall.ok());
    std::vector<brush::Face> faces = wall->faces();
    faces[5].attributes = material("wood"); // +z
    auto two_materials = brush::Brush::from_faces(faces);
    REQUIRE(two_materials.ok());
    level.entities.push_back(brush_entity(3, *two_materials));
    return level;
}

geometry::Camera brush_camera() {
    geometry::Camera cam;
    cam.position = Vec3(0.0f, 9.0f, 16.0f);
    cam.pitch = radians(-25.0f);
    cam.fov_y = radians(45.0f);
    cam.aspect = static_cast<float>(test::kGlWidth) / static_cast<float>(test::kGlHeight);
    return cam;
}

struct Frame {
    std::vector<unsigned char> rgb;
    FrameStats stats;
};

Frame draw_level(const level::Level& level, RenderQuality quality) {
    auto* ctx = test::gl_context();
    AssetLibrary assets(test::source_dir() / "assets");
    RendererSettings settings;
    settings.quality = quality;
    settings.render_scale = 1.0f;
    auto renderer = SceneRenderer::create(assets.textures(), settings);
    REQUIRE(renderer);
    auto scene = LevelScene::build(level, assets, level_scene_options((*renderer)->settings()));
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    scene->emit(instances, lights);
    ctx->bind(); // the frame is drawn into the bound target (the renderer's set-up binds its own)
    SceneFrame frame;
    frame.camera = brush_camera();
    frame.environment = scene->environment();
    frame.instances = &instances;
    frame.lights = &lights;
    frame.width = ctx->width();
    frame.height = ctx->height();
    Frame out;
    out.stats = (*renderer)->render(frame);
    out.rgb = ctx->read_rgb();
    return out;
}

// Mean colour of the 5 x 5 pixels around where `world` appears.
Vec3 colour_at(const std::vector<unsigned char>& rgb, const Vec3& world) {
    Vec2 pixel;
    REQUIRE(geometry::world_to_screen(brush_camera(), world, Vec2(test::kGlWidth, test::kGlHeight), pixel));
    const int cx = static_cast<int>(pixel.x), cy = static_cast<int>(pixel.y);
    REQUIRE((cx >= 2 && cy >= 2 && cx < test::kGlWidth - 2 && cy < test::kGlHeight - 2));
    Vec3 sum(0.0f);
    for (int y = cy - 2; y <= cy + 2; ++y)
        for (int x = cx - 2; x <= cx + 2; ++x)
            for (int c = 0; c < 3; ++c)
                sum[c] += static_cast<float>(rgb[(static_cast<std::size_t>(y) * test::kGlWidth + x) * 3 + c]);
    return sum / 25.0f;
}

float luma(const Vec3& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

} // namespace

TEST_CASE("brushes: drawn with their materials on both paths, casting the sun's shadow on a brush floor") {
    REQUIRE_MESSAGE(test::gl_context(), "no display: run the GL tests under xvfb-run (./run.sh test does)");
    const level::Level with = brush_level(true), without = brush_level(false);
    for (RenderQuality q : {RenderQuality::Full, RenderQuality::Fast}) {
        CAPTURE(static_cast<int>(q));
        log::Capture capture;
        const Frame a = draw_level(with, q), b = draw_level(without, q);
        CHECK(capture.count(log::Level::Warn) == 0); // every material found
        CHECK(a.stats.fast_path == (q == RenderQuality::Fast));
        const test::ImageStats stats = test::image_stats(a.rgb, test::kGlWidth, test::kGlHeight);
        CHECK(stats.magenta_fraction < 0.001);
        // The ramp's slope and the wall's faces are there (the image changes where they stand).
        const Vec3 slope(-6, 2, -4), wall_front(5, 3, -5), wall_side(2, 3, -5.5f);
        for (const Vec3& p : {slope, wall_front, wall_side})
            CHECK(glm::length(colour_at(a.rgb, p) - colour_at(b.rgb, p)) > 20.0f);
        // Two materials on one brush: the wood front is warm (red well above blue), the metal side far less
        // so.
        const Vec3 wood = colour_at(a.rgb, wall_front), metal = colour_at(a.rgb, wall_side);
        MESSAGE("wood ", wood.r, " ", wood.g, " ", wood.b, "; metal ", metal.r, " ", metal.g, " ", metal.b);
        REQUIRE((wood.b > 1.0f && metal.b > 1.0f));
        CHECK(wood.r / wood.b > 1.6f * (metal.r / metal.b));
        // The wall's shadow on the brush floor in front of it, against the floor beside it and against the
        // same spot without the wall.
        const Vec3 shaded = colour_at(a.rgb, Vec3(5, 0, -2)), beside = colour_at(a.rgb, Vec3(11, 0, -2));
        const Vec3 unshaded = colour_at(b.rgb, Vec3(5, 0, -2));
        MESSAGE("floor luma: in the wall's shadow ", luma(shaded), ", beside it ", luma(beside), ", no wall ",
                luma(unshaded));
        CHECK(luma(shaded) < 0.7f * luma(beside));
        CHECK(luma(shaded) < 0.7f * luma(unshaded));
        // The ramp's slope faces up toward the sun's side less than the floor does: lit, not black.
        CHECK(luma(colour_at(a.rgb, slope)) > 10.0f);
    }
}

TEST_CASE("brushes: the main level with 500 brushes added, against without (surfaces, bake, frame time)") {
    REQUIRE_MESSAGE(test::gl_context(), "no display: run the GL tests under xvfb-run (./run.sh test does)");
    auto loaded = level::load_level_file(test::source_dir() / "levels" / "main.json");
    REQUIRE(loaded.ok());
    level::Level with = *loaded;
    // 500 pillars and ramps over the ground (x -18..97, z -98..88), alternately, turned every which way.
    const DVec3 profile[] = {{-1, 0, 1}, {-1, 0, -1}, {-1, 1, -1}};
    auto ramp = brush::make_extrusion(profile, {2, 0, 0}, material("concrete", 2.0));
    auto pillar = brush::make_box({-0.3, 0, -0.3}, {0.3, 2.5, 0.3}, material("metal", 2.0));
    REQUIRE((ramp.ok() && pillar.ok()));
    int id = 10000;
    for (int k = 0; k < 500; ++k) {
        level::Entity e = brush_entity(id++, k % 2 ? *ramp : *pillar);
        e.position = Vec3(-18.0f + 4.8f * static_cast<float>(k / 20), 0.0f,
                          -98.0f + 9.8f * static_cast<float>(k % 20));
        e.rotation = Vec3(static_cast<float>((k * 37) % 360), 0.0f, 0.0f);
        with.entities.push_back(e);
    }
    auto* ctx = test::gl_context();
    AssetLibrary assets(test::source_dir() / "assets");
    LevelScene::build(with, assets, LevelSceneOptions{false}); // loads every model and material once
    for (RenderQuality q : {RenderQuality::Fast, RenderQuality::Full}) {
        CAPTURE(static_cast<int>(q));
        RendererSettings settings;
        settings.quality = q;
        settings.render_scale = 1.0f;
        auto renderer = SceneRenderer::create(assets.textures(), settings);
        REQUIRE(renderer);
        double median_ms[2] = {0, 0};
        int surfaces[2] = {0, 0};
        for (int variant = 0; variant < 2; ++variant) {
            const level::Level& level = variant == 0 ? *loaded : with;
            const auto build_start = std::chrono::steady_clock::now();
            auto scene = LevelScene::build(level, assets, level_scene_options((*renderer)->settings()));
            const double build_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - build_start)
                    .count();
            surfaces[variant] = scene->surface_count();
            std::vector<MeshInstance> instances;
            std::vector<Light> lights;
            scene->emit(instances, lights);
            ctx->bind();
            SceneFrame frame;
            frame.camera = player_start_camera(level, static_cast<float>(ctx->width()) /
                                                          static_cast<float>(ctx->height()));
            frame.environment = scene->environment();
            frame.instances = &instances;
            frame.lights = &lights;
            frame.width = ctx->width();
            frame.height = ctx->height();
            std::vector<double> times;
            FrameStats stats;
            for (int i = 0; i < 3; ++i) (*renderer)->render(frame); // first uses: textures, shadow map
            for (int i = 0; i < 15; ++i) {
                const auto start = std::chrono::steady_clock::now();
                stats = (*renderer)->render(frame);
                ctx->read_rgb(); // waits for the frame
                times.push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                        .count());
            }
            std::sort(times.begin(), times.end());
            median_ms[variant] = times[times.size() / 2];
            MESSAGE((variant ? "500 brushes" : "no brushes "), ": build ", build_ms, " ms (bake ",
                    scene->bake_stats().bake_ms, " ms CPU, ", scene->bake_stats().faces, " faces), ",
                    surfaces[variant], " surfaces, frame median ", median_ms[variant], " ms at ",
                    ctx->width(), "x", ctx->height(), ", ", stats.draw_calls, " draws, ",
                    stats.instances_culled, " culled, ", stats.instances_occluded, " occluded");
        }
        // Every brush is drawn, one surface each (one material each).
        CHECK(surfaces[1] == surfaces[0] + 500);
        CHECK(median_ms[1] > 0.0);
    }
}

TEST_CASE("a designer's model is emitted at its level of detail by its size on screen") {
    REQUIRE_MESSAGE(test::gl_context(), "no display: run the GL tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    const char* old_home = std::getenv("XDG_DATA_HOME");
    const std::string saved = old_home ? old_home : "";
    setenv("XDG_DATA_HOME", dir.path().c_str(), 1);
    { // a UV sphere of 64 x 32 quads, radius 1, in the user's models folder
        std::string obj;
        const int rings = 32, segments = 64;
        for (int r = 0; r <= rings; ++r)
            for (int s = 0; s < segments; ++s) {
                const double t = kPi * r / rings, p = 2 * kPi * s / segments;
                obj += "v " + std::to_string(std::sin(t) * std::cos(p)) + " " +
                       std::to_string(1 + std::cos(t)) + " " + std::to_string(std::sin(t) * std::sin(p)) +
                       "\n";
            }
        for (int r = 0; r < rings; ++r)
            for (int s = 0; s < segments; ++s) {
                const int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1;
                obj += "f " + std::to_string(a) + " " + std::to_string(a + segments) + " " +
                       std::to_string(b + segments) + " " + std::to_string(b) + "\n";
            }
        std::filesystem::create_directories(dir / "killswitch/models");
        test::write_file(dir / "killswitch/models/ball.obj", obj);
    }
    level::Level level;
    level.add(level::EntityType::Model, {0, 0, 0}, "Ball").as<level::ModelProps>().file = "ball.obj";
    const int id = level.entities.back().id;
    AssetLibrary assets(paths::asset(""));
    LevelSceneOptions options;
    options.bake_light_map = false;
    auto scene = LevelScene::build(level, assets, options);
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    auto triangles_at = [&](float distance) {
        geometry::Camera camera;
        camera.position = {0.0f, 1.0f, distance};
        scene->set_view(camera, 720);
        scene->emit(instances, lights);
        int indices = 0;
        for (const MeshInstance& inst : instances) indices += inst.mesh->index_count();
        return indices / 3;
    };
    const int near = triangles_at(3.0f);
    CHECK(scene->model_lod(id) == 0);
    CHECK(scene->coarse_model_count() == 0);
    const int far = triangles_at(400.0f);
    CHECK(scene->model_lod(id) == 3);
    CHECK(scene->coarse_model_count() == 1);
    CHECK(far * 5 < near);
    CHECK(triangles_at(3.0f) == near);
    scene->set_model_lods(false);
    CHECK(triangles_at(400.0f) == near);
    old_home ? setenv("XDG_DATA_HOME", saved.c_str(), 1) : unsetenv("XDG_DATA_HOME");
}
