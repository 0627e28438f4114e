// Renderer tests that need GL (hidden window under Xvfb + llvmpipe in CI): shaders compile, assets load,
// missing/corrupt files give the placeholder with one warning, and rendered images look right (non-blank,
// expected colours, no magenta) and match a golden image within a tolerance.
#include "gl_test_support.h"
#include "test_support.h"

#include "core/log.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "render/shaders.h"
#include "render/view_model.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <stb_image.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace ks;
using namespace ks::render;
namespace fs = std::filesystem;
using ks::test::render_offscreen;

namespace {
fs::path assets_dir() {
    return ks::test::source_dir() / "assets";
}

// This driver's quality path at full resolution (thin parts such as the floor light's stand, or a screen's
// text, would thin out at the test's 320x180 scaled down by half).
auto full_resolution_renderer(AssetLibrary& assets) {
    RendererSettings settings;
    settings.render_scale = 1.0f;
    return SceneRenderer::create(assets.textures(), settings);
}

} // namespace

TEST_CASE("every shader program compiles and links on this driver") {
    KS_REQUIRE_GL();
    int count = 0;
    for (const ProgramFiles* p : all_programs()) {
        CAPTURE(p->name);
        auto program = build_program(*p, default_shader_dir());
        CHECK_MESSAGE(program.ok(), (program.ok() ? "" : program.error().str()));
        ++count;
    }
    CHECK(count == 9); // pbr, fast, fast_level, fast_level_lit, shadow, particle, line, view_model_composite,
                       // contact_shadow
}

TEST_CASE("a broken shader reports file:line: message") {
    KS_REQUIRE_GL();
    ShaderSource vs{"ok.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n"};
    ShaderSource fs{"broken.frag",
                    "#version 330 core\nout vec4 c;\nvoid main() {\n  c = undefined_thing;\n}\n"};
    auto program = ShaderProgram::build(vs, fs);
    REQUIRE_FALSE(program.ok());
    CHECK(program.error().str().find("broken.frag:4:") != std::string::npos);
    // A variant with defines (fast_level_lit) reports the file's own line numbers too.
    const std::string broken_text = with_defines(fs.text, "#define VARIANT 1\n#define OTHER\n");
    REQUIRE(broken_text != fs.text);
    auto variant = ShaderProgram::build(vs, {"broken.frag", broken_text});
    REQUIRE_FALSE(variant.ok());
    CAPTURE(variant.error().str());
    CHECK(variant.error().str().find("broken.frag:4:") != std::string::npos);
}

TEST_CASE("every generated model loads with its textures and named nodes, no placeholder") {
    KS_REQUIRE_GL();
    log::Capture capture;
    AssetLibrary assets(assets_dir());
    int count = 0;
    for (const auto& entry : fs::directory_iterator(assets_dir() / "models")) {
        if (entry.path().extension() != ".gltf") continue;
        CAPTURE(entry.path().string());
        const Model& m = assets.model(entry.path().string());
        CHECK_FALSE(m.placeholder);
        CHECK_FALSE(m.meshes.empty());
        CHECK(m.bounds.valid());
        ++count;
    }
    CHECK(count >= 10);
    CHECK(capture.count(log::Level::Warn) == 0);
    // The nodes game code and animation look for.
    const Model& robot = assets.model("robot");
    for (const char* n : {"robot", "wheel_base", "wheels", "chest", "arm_r", "forearm_r", "hand_r",
                          "hand_r_tip", "arm_l", "forearm_l", "hand_l", "head"})
        CHECK_MESSAGE(robot.find_node(n) >= 0, n);
    CHECK(robot.bounds.max.y - robot.bounds.min.y == doctest::Approx(3.0f).epsilon(0.05));
    const Model& door = assets.model("door");
    CHECK(door.find_node("door_l") >= 0);
    CHECK(door.find_node("door_r") >= 0);
    CHECK(assets.model("rifle").find_node("muzzle") >= 0);
    CHECK(assets.model("floor_light").find_node("light_origin") >= 0);
    // hand_r_tip sits below the shoulder (arms hang down at rest) in world space.
    std::vector<Mat4> world;
    robot.node_transforms(Mat4(1.0f), robot.rest_pose(), world);
    Vec3 tip = Vec3(world[size_t(robot.find_node("hand_r_tip"))][3]);
    Vec3 shoulder = Vec3(world[size_t(robot.find_node("arm_r"))][3]);
    CHECK(tip.y < shoulder.y);
    CHECK(tip.z > 0.0f); // the right arm is on +z
    for (const char* s : {"concrete", "tiles", "ceiling", "metal", "wood", "dojo_floor"}) {
        CAPTURE(s);
        CHECK_FALSE(assets.surface(s).placeholder);
    }
}

TEST_CASE("a missing or corrupt model or texture gives the placeholder and one warning naming the file") {
    KS_REQUIRE_GL();
    ks::test::ScratchDir dir;
    {
        std::ofstream(dir / "corrupt.gltf") << "{ this is not json";
        std::ofstream(dir / "bad_basecolor.png") << "not a png at all";
    }
    AssetLibrary assets(dir.path());
    {
        log::Capture capture;
        const Model& m = assets.model((dir / "missing.gltf").string());
        CHECK(m.placeholder);
        CHECK(capture.count(log::Level::Warn) == 1);
        CHECK(capture.text().find("missing.gltf") != std::string::npos);
        assets.model((dir / "missing.gltf").string()); // cached: no second warning
        CHECK(capture.count(log::Level::Warn) == 1);
    }
    {
        log::Capture capture;
        CHECK(assets.model((dir / "corrupt.gltf").string()).placeholder);
        CHECK(capture.count(log::Level::Warn) == 1);
        CHECK(capture.text().find("corrupt.gltf") != std::string::npos);
    }
    {
        log::Capture capture;
        const Material& m = assets.surface("bad");
        CHECK(m.placeholder);
        CHECK(m.base_map == assets.textures().placeholder().id);
        CHECK(capture.count(log::Level::Warn) == 1);
        CHECK(capture.text().find("bad_basecolor.png") != std::string::npos);
    }
    // And it draws as the magenta checker.
    auto renderer = SceneRenderer::create(assets.textures());
    REQUIRE(renderer);
    std::vector<Mat4> scratch;
    std::vector<MeshInstance> instances;
    assets.model((dir / "missing.gltf").string())
        .emit(glm::scale(Mat4(1.0f), Vec3(3.0f)), scratch, instances);
    geometry::Camera cam;
    cam.position = Vec3(0, 1.5f, 3.5f);
    Environment env;
    env.sky_color = Vec3(1.0f);
    auto rgb = render_offscreen(**renderer, cam, env, instances, {});
    auto stats = ks::test::image_stats(rgb, ks::test::kGlWidth, ks::test::kGlHeight);
    CHECK(stats.magenta_fraction > 0.05);
}

namespace {
using MainLevelView = ks::test::OffscreenShot;

// The full-quality path at full resolution (what GPUs get): the golden image's configuration.
RendererSettings full_quality() {
    RendererSettings s;
    s.quality = RenderQuality::Full;
    s.render_scale = 1.0f;
    return s;
}

RendererSettings fast_quality(float scale = 1.0f) {
    RendererSettings s;
    s.quality = RenderQuality::Fast;
    s.render_scale = scale;
    return s;
}

MainLevelView render_main_level_start(RendererSettings settings = full_quality()) {
    auto level = level::load_level_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE_MESSAGE(level.ok(), (level.ok() ? "" : level.error().str()));
    AssetLibrary assets(assets_dir());
    auto renderer = SceneRenderer::create(assets.textures(), settings);
    REQUIRE(renderer);
    // As the game builds it for this renderer (a light map only on the fast path), with the direct light
    // alone: these cases check the renderer's switches, test_light_bake.cpp the bounce and occlusion, and
    // the full bake would add seconds of CPU to each picture here.
    LevelSceneOptions options = level_scene_options((*renderer)->settings());
    options.bake = BakeSettings::direct_only();
    auto scene = LevelScene::build(*level, assets, options);
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    scene->emit(instances, lights);
    CHECK(lights.size() >= 8);
    geometry::Camera cam = player_start_camera(*level, 16.0f / 9.0f);
    ViewModel vm;
    std::vector<Mat4> scratch;
    assets.model("rifle").emit(rifle_view_transform(0.0f), scratch, vm.instances);
    SceneFrame frame;
    frame.camera = cam;
    frame.environment = scene->environment();
    frame.instances = &instances;
    frame.lights = &lights;
    frame.view_model = &vm;
    return ks::test::render_frame_offscreen(**renderer, frame);
}
} // namespace

TEST_CASE(
    "main level from the player start: lit, textured, culled, no placeholder, matches the golden image") {
    KS_REQUIRE_GL();
    log::Capture capture;
    MainLevelView view = render_main_level_start();
    CHECK(capture.count(log::Level::Warn) == 0);
    const int w = ks::test::kGlWidth, h = ks::test::kGlHeight;
    auto all = ks::test::image_stats(view.rgb, w, h);
    CHECK(all.mean_luma > 40.0);   // not black
    CHECK(all.luma_stddev > 15.0); // not flat: textures, shading
    CHECK(all.magenta_fraction < 0.001);
    // The floor (bottom left) is the light tiled floor; the far end of room 1 (centre) is darker concrete.
    auto floor = ks::test::image_stats(view.rgb, w, h, 0, h * 3 / 4, w / 3, h);
    auto far_wall = ks::test::image_stats(view.rgb, w, h, w * 2 / 5, h * 3 / 10, w * 3 / 5, h * 2 / 5);
    CHECK(floor.mean_luma > far_wall.mean_luma);
    CHECK(view.stats.instances_culled > 0); // rooms behind the walls are not drawn
    CHECK(view.stats.draw_calls > 5);

    const fs::path golden = ks::test::source_dir() / "tests/render/golden/main_start_320x180.png";
    if (const char* update = std::getenv("KS_UPDATE_GOLDEN"); update && *update == '1') {
        fs::create_directories(golden.parent_path());
        stbi_write_png(golden.string().c_str(), w, h, 3, view.rgb.data(), w * 3);
        MESSAGE("golden image updated: " << golden.string());
    }
    int gw = 0, gh = 0, gc = 0;
    unsigned char* g = stbi_load(golden.string().c_str(), &gw, &gh, &gc, 3);
    REQUIRE_MESSAGE(g != nullptr,
                    "missing golden image " << golden.string() << " (KS_UPDATE_GOLDEN=1 writes it)");
    std::vector<unsigned char> expected(g, g + static_cast<size_t>(gw) * gh * 3);
    stbi_image_free(g);
    REQUIRE(gw == w);
    REQUIRE(gh == h);
    // Tolerance: rasteriser and driver differences (llvmpipe versions, GPU filtering) move pixels a little;
    // a broken light, texture or transform moves the mean by far more than 6/255.
    double diff = ks::test::mean_abs_diff(view.rgb, expected);
    CAPTURE(diff);
    CHECK(diff < 6.0);
}

TEST_CASE("fast path (software rasterisers): the main level start looks like the full path") {
    KS_REQUIRE_GL();
    log::Capture capture;
    MainLevelView full = render_main_level_start(full_quality());
    MainLevelView fast = render_main_level_start(fast_quality(1.0f));
    MainLevelView fast_half = render_main_level_start(fast_quality(0.5f));
    CHECK(capture.count(log::Level::Warn) == 0);
    CHECK_FALSE(full.stats.fast_path);
    CHECK(fast.stats.fast_path);
    const int w = ks::test::kGlWidth, h = ks::test::kGlHeight;
    CHECK(fast.stats.internal_width == w);
    CHECK(fast_half.stats.internal_width == w / 2);
    CHECK(fast_half.stats.internal_height == h / 2);
    // Same scene, same lights: baked light + per-vertex light + gamma 2 stay close to per-pixel PBR.
    // (Measured 2026-11: see docs/rendering.md; a missing light map, a wrong light unit or a broken
    // texture moves the mean by far more.)
    double diff = ks::test::mean_abs_diff(fast.rgb, full.rgb);
    double diff_half = ks::test::mean_abs_diff(fast_half.rgb, full.rgb);
    MESSAGE("fast vs full mean abs diff: " << diff << "/255 at scale 1, " << diff_half << "/255 at 0.5");
    CHECK(diff < 8.0);
    CHECK(diff_half < 10.0);
    auto a = ks::test::image_stats(full.rgb, w, h), b = ks::test::image_stats(fast.rgb, w, h);
    CHECK(std::abs(a.mean_luma - b.mean_luma) < 6.0);
    CHECK(b.luma_stddev > 15.0);
    CHECK(b.magenta_fraction < 0.001);
}

TEST_CASE("fast path: trilinear mips (an option; nearest mip by default) change the floor, closer to full") {
    KS_REQUIRE_GL();
    CHECK_FALSE(RendererSettings{}.fast_trilinear);
    RendererSettings trilinear_settings = fast_quality(1.0f);
    trilinear_settings.fast_trilinear = true;
    MainLevelView full = render_main_level_start(full_quality());
    MainLevelView nearest = render_main_level_start(fast_quality(1.0f));
    MainLevelView trilinear = render_main_level_start(trilinear_settings);
    const double between = ks::test::mean_abs_diff(trilinear.rgb, nearest.rgb);
    const double err_trilinear = ks::test::mean_abs_diff(trilinear.rgb, full.rgb);
    const double err_nearest = ks::test::mean_abs_diff(nearest.rgb, full.rgb);
    MESSAGE("trilinear vs nearest mip " << between << "/255; vs full path: trilinear " << err_trilinear
                                        << ", nearest " << err_nearest);
    CHECK(between > 0.05); // the sampler setting reaches the pixels
    CHECK(between < 3.0);  // and only the texture detail moves
    CHECK(err_trilinear <= err_nearest + 0.02);
}

TEST_CASE(
    "fast path: occlusion culling, the depth pre-pass and fast_level change no pixel, anywhere in the main "
    "level") {
    KS_REQUIRE_GL();
    auto level = level::load_level_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE(level.ok());
    AssetLibrary assets(assets_dir());
    auto scene = LevelScene::build(*level, assets, ks::test::direct_light_only());
    RendererSettings plain = fast_quality(1.0f);
    plain.occlusion_culling = false;
    plain.depth_prepass = false;
    plain.fast_level_shader = false;
    auto fast = SceneRenderer::create(assets.textures(), fast_quality(1.0f));
    auto reference = SceneRenderer::create(assets.textures(), plain);
    REQUIRE(fast);
    REQUIRE(reference);
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    scene->emit(instances, lights);
    auto* ctx = ks::test::gl_context();
    ctx->bind();
    SceneFrame frame;
    frame.environment = scene->environment();
    frame.instances = &instances;
    frame.lights = &lights;
    frame.width = ctx->width();
    frame.height = ctx->height();
    frame.camera = player_start_camera(*level, 16.0f / 9.0f);
    // Eyes on a grid over the whole level (in rooms, in walls' ends, outside), four headings each, looking
    // slightly down and up: the images must match (the pre-pass may move a depth-tied pixel by rounding).
    int views = 0, occluded_views = 0;
    long long drawn = 0, drawn_reference = 0;
    double worst = 0.0;
    for (float x = -6.0f; x <= 96.0f; x += 17.0f)
        for (float z = -86.0f; z <= 66.0f; z += 19.0f)
            for (int heading = 0; heading < 4; ++heading) {
                frame.camera.position = Vec3(x, heading % 2 ? 3.0f : 9.0f, z);
                frame.camera.yaw = heading * kPi * 0.5f + 0.3f;
                frame.camera.pitch = heading % 2 ? -0.15f : 0.2f;
                FrameStats a = (*fast)->render(frame);
                std::vector<unsigned char> img = ctx->read_rgb();
                FrameStats b = (*reference)->render(frame);
                std::vector<unsigned char> ref = ctx->read_rgb();
                const double diff = ks::test::mean_abs_diff(img, ref);
                CAPTURE(x);
                CAPTURE(z);
                CAPTURE(heading);
                CHECK(diff < 0.05);
                CHECK(b.instances_occluded == 0);
                worst = std::max(worst, diff);
                ++views;
                occluded_views += a.instances_occluded > 0 ? 1 : 0;
                drawn += a.instances_drawn;
                drawn_reference += b.instances_drawn;
            }
    MESSAGE(views << " views: worst mean abs diff " << worst << "/255; instances drawn " << drawn << " vs "
                  << drawn_reference << " without occlusion culling; " << occluded_views
                  << " views culled something");
    CHECK(occluded_views > views / 4);
    CHECK(drawn < drawn_reference);
}

TEST_CASE("auto quality follows the GL renderer string; overrides win") {
    CHECK(default_quality_for("llvmpipe (LLVM 15.0.6, 256 bits)") == RenderQuality::Fast);
    CHECK(default_quality_for("NVIDIA H100 80GB HBM3/PCIe/SSE2") == RenderQuality::Full);
    CHECK(default_render_scale_for("llvmpipe (LLVM 15.0.6, 256 bits)") ==
          doctest::Approx(kSoftwareRenderScale));
    CHECK(default_render_scale_for("AMD Radeon RX 7900") == 1.0f);
    // A program's own software choice (the editor asks for 1), clamped; GPUs stay at 1.
    CHECK(default_render_scale_for("llvmpipe (LLVM 15.0.6, 256 bits)", 1.0f) == 1.0f);
    CHECK(default_render_scale_for("llvmpipe (LLVM 15.0.6, 256 bits)", 0.1f) == doctest::Approx(0.25f));
    CHECK(default_render_scale_for("AMD Radeon RX 7900", 0.5f) == 1.0f);
    KS_REQUIRE_GL();
    AssetLibrary assets(assets_dir());
    auto automatic = SceneRenderer::create(assets.textures());
    REQUIRE(automatic);
    const std::string gl = ks::test::gl_context()->renderer();
    CHECK((*automatic)->quality() == default_quality_for(gl));
    CHECK((*automatic)->render_scale() == doctest::Approx(default_render_scale_for(gl)));
    RendererSettings forced;
    forced.quality = RenderQuality::Full;
    forced.render_scale = 7.0f; // clamped
    auto full = SceneRenderer::create(assets.textures(), forced);
    REQUIRE(full);
    CHECK((*full)->quality() == RenderQuality::Full);
    CHECK((*full)->render_scale() == 1.0f);
    (*full)->set_render_scale(0.1f);
    CHECK((*full)->render_scale() == 0.25f);
    (*full)->set_render_scale(std::nanf(""));
    CHECK((*full)->render_scale() == doctest::Approx(default_render_scale_for(gl)));
    (*full)->set_quality(RenderQuality::Fast);
    CHECK((*full)->quality() == RenderQuality::Fast);
    // The environment's choices replace "automatic" only: an explicit quality or scale still wins.
    RendererSettings from_environment;
    from_environment.automatic_quality =
        default_quality_for(gl) == RenderQuality::Fast ? RenderQuality::Full : RenderQuality::Fast;
    from_environment.automatic_render_scale = 0.75f;
    auto overridden = SceneRenderer::create(assets.textures(), from_environment);
    REQUIRE(overridden);
    CHECK((*overridden)->quality() == from_environment.automatic_quality);
    CHECK((*overridden)->render_scale() == doctest::Approx(0.75f));
    (*overridden)->set_render_scale(0.0f); // back to automatic: the environment's scale again
    CHECK((*overridden)->render_scale() == doctest::Approx(0.75f));
    (*overridden)->set_render_scale(0.5f);
    CHECK((*overridden)->render_scale() == doctest::Approx(0.5f));
    CHECK(level_scene_options((*overridden)->settings()).bake_light_map ==
          ((*overridden)->quality() == RenderQuality::Fast));
}

TEST_CASE("lights toggle: switching every level light off darkens the view, emissive lenses follow") {
    KS_REQUIRE_GL();
    auto level = level::load_level_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE(level.ok());
    AssetLibrary assets(assets_dir());
    // Both paths: per-pixel lights (full) and the re-combined light map (fast).
    for (RenderQuality quality : {RenderQuality::Full, RenderQuality::Fast}) {
        CAPTURE(static_cast<int>(quality));
        auto scene = LevelScene::build(*level, assets, ks::test::direct_light_only());
        RendererSettings settings;
        settings.quality = quality;
        settings.render_scale = 1.0f;
        auto renderer = SceneRenderer::create(assets.textures(), settings);
        REQUIRE(renderer);
        std::vector<MeshInstance> instances;
        std::vector<Light> lights;
        geometry::Camera cam = player_start_camera(*level, 16.0f / 9.0f);
        scene->emit(instances, lights);
        size_t lit = lights.size();
        auto on =
            ks::test::image_stats(render_offscreen(**renderer, cam, scene->environment(), instances, lights),
                                  ks::test::kGlWidth, ks::test::kGlHeight);
        for (const auto& e : level->entities)
            if (e.type() == level::EntityType::FloorLight || e.type() == level::EntityType::TopLight)
                scene->set_light_on(e.id, false);
        scene->emit(instances, lights);
        CHECK(lights.empty());
        CHECK(lit > 0);
        auto off =
            ks::test::image_stats(render_offscreen(**renderer, cam, scene->environment(), instances, lights),
                                  ks::test::kGlWidth, ks::test::kGlHeight);
        CHECK(off.mean_luma < on.mean_luma * 0.8);
    }
}

TEST_CASE(
    "each asset on the turntable stage renders non-blank without placeholder, with its dominant colour") {
    KS_REQUIRE_GL();
    AssetLibrary assets(assets_dir());
    auto renderer = full_resolution_renderer(assets);
    REQUIRE(renderer);
    Environment env;
    env.sky_color = Vec3(0.5f);
    env.ground_color = Vec3(0.25f);
    env.sun_color = Vec3(0.5f);
    struct Expect {
        const char* name;
        int channel; // -1: no colour expectation; else the channel (r/g/b) that should dominate
    };
    for (Expect e : {Expect{"robot", -1},
                     {"rifle", -1},
                     {"door", -1},
                     {"floor_light", -1},
                     {"top_light", -1},
                     {"control_panel", -1},
                     {"gas_cylinder", 0},
                     {"pickup_health", 0},
                     {"pickup_ammo", 0},
                     {"pickup_shield", 2}}) {
        CAPTURE(std::string(e.name));
        const Model& m = assets.model(e.name);
        REQUIRE_FALSE(m.placeholder);
        std::vector<MeshInstance> instances;
        std::vector<Mat4> scratch;
        float size = glm::length(m.bounds.max - m.bounds.min);
        m.emit(glm::translate(Mat4(1.0f), -m.bounds.center()), scratch, instances);
        geometry::Camera cam;
        cam.position = Vec3(size * 0.7f, size * 0.25f, size * 0.9f);
        Vec3 d = glm::normalize(-cam.position);
        cam.yaw = std::atan2(-d.x, -d.z);
        cam.pitch = std::asin(d.y);
        cam.fov_y = radians(45.0f);
        auto rgb = render_offscreen(**renderer, cam, env, instances, {});
        const int w = ks::test::kGlWidth, h = ks::test::kGlHeight;
        auto centre = ks::test::image_stats(rgb, w, h, w / 3, h / 3, w * 2 / 3, h * 2 / 3);
        auto all = ks::test::image_stats(rgb, w, h);
        CHECK(all.magenta_fraction < 0.001);
        CHECK(centre.luma_stddev + std::abs(centre.mean_luma - 0.0) > 10.0); // the model covers the centre
        CHECK(all.luma_stddev > 5.0);
        if (e.channel >= 0) {
            double sum[3] = {0, 0, 0};
            for (int y = h / 3; y < h * 2 / 3; ++y)
                for (int x = w / 3; x < w * 2 / 3; ++x)
                    for (int c = 0; c < 3; ++c) sum[c] += rgb[(static_cast<size_t>(y) * w + x) * 3 + c];
            for (int c = 0; c < 3; ++c)
                if (c != e.channel) CHECK(sum[e.channel] > sum[c]);
        }
    }
}

TEST_CASE("the control panel's screen reads upright: its big title at the top, the small status line below") {
    // assimp hands texture coordinates over bottom-up; drawn as they came, every model's textures were
    // upside down, which only the panel's text showed (issue 28).
    KS_REQUIRE_GL();
    AssetLibrary assets(assets_dir());
    auto renderer = full_resolution_renderer(assets);
    REQUIRE(renderer);
    const Model& panel = assets.model("control_panel");
    REQUIRE_FALSE(panel.placeholder);
    std::vector<MeshInstance> instances;
    std::vector<Mat4> scratch;
    panel.emit(Mat4(1.0f), scratch, instances);
    // Straight at the screen (4.4 x 2.1, centre 2.65 up, facing -X), filling about 60 % of the height.
    geometry::Camera cam;
    cam.position = Vec3(-4.0f, 2.65f, 0.0f);
    cam.yaw = std::atan2(-1.0f, 0.0f); // looking along +X
    cam.pitch = 0.0f;
    cam.fov_y = radians(45.0f);
    Environment env;
    env.sky_color = env.ground_color = env.sun_color = Vec3(0.3f);
    const auto rgb = render_offscreen(**renderer, cam, env, instances, {});
    const int w = ks::test::kGlWidth, h = ks::test::kGlHeight;
    const int screen_h = static_cast<int>(h * 1.05f / (4.0f * std::tan(radians(22.5f))));
    const int top = h / 2 - screen_h / 2, bottom = h / 2 + screen_h / 2;
    auto cyan_in_rows = [&](int y0, int y1) {
        int n = 0;
        for (int y = std::max(0, y0); y < std::min(h, y1); ++y)
            for (int x = w / 4; x < w * 3 / 4; ++x) {
                const unsigned char* p = &rgb[(static_cast<size_t>(y) * w + x) * 3];
                n += p[2] > 150 && p[1] > 120 && p[0] < 130 ? 1 : 0;
            }
        return n;
    };
    const int title = cyan_in_rows(top, top + screen_h / 5),
              footer = cyan_in_rows(bottom - screen_h / 5, bottom);
    CAPTURE(title);
    CAPTURE(footer);
    CHECK(title > 2 * footer);
    CHECK(title > 40);
}

TEST_CASE("killswitch --screenshot renders the main level and the asset viewer to PNG files") {
    KS_REQUIRE_GL();
    ks::test::ScratchDir dir;
    const std::string exe = (ks::test::bin_dir() / "killswitch").string();
    for (const char* args : {"--level levels/main.json", "--view robot"}) {
        CAPTURE(args);
        fs::path png = dir / "shot.png";
        auto r = ks::test::run_command(
            "cd '" + ks::test::source_dir().string() + "' && '" + exe + "' " + std::string(args) +
            " --width 320 --height 180 --frames 2 --screenshot '" + png.string() + "'");
        CHECK_MESSAGE(r.exit_code == 0, r.output);
        int w = 0, h = 0, c = 0;
        unsigned char* px = stbi_load(png.string().c_str(), &w, &h, &c, 3);
        REQUIRE(px != nullptr);
        std::vector<unsigned char> rgb(px, px + static_cast<size_t>(w) * h * 3);
        stbi_image_free(px);
        auto s = ks::test::image_stats(rgb, w, h);
        CHECK(s.mean_luma > 20.0);
        CHECK(s.magenta_fraction < 0.001);
        CHECK(r.output.find("warn") == std::string::npos);
    }
    auto bad = ks::test::run_command("'" + exe + "' --camera 1,2,nan,0,0 --screenshot /dev/null 2>&1");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("--camera") != std::string::npos);
}

TEST_CASE("feature switches used by ks_bench render: each changes the image the way it should") {
    KS_REQUIRE_GL();
    const MainLevelView full = render_main_level_start();
    RendererSettings flat;
    flat.surface_detail = false;
    const MainLevelView no_detail = render_main_level_start(flat);
    CHECK(ks::test::mean_abs_diff(full.rgb, no_detail.rgb) > 0.2); // normal/bump maps did something
    RendererSettings unlit;
    unlit.max_lights_per_draw = 0;
    const MainLevelView no_lights = render_main_level_start(unlit);
    RendererSettings one;
    one.max_lights_per_draw = 1;
    const MainLevelView one_light = render_main_level_start(one);
    const int w = ks::test::kGlWidth, h = ks::test::kGlHeight;
    const double l0 = ks::test::image_stats(no_lights.rgb, w, h).mean_luma;
    const double l1 = ks::test::image_stats(one_light.rgb, w, h).mean_luma;
    const double l8 = ks::test::image_stats(full.rgb, w, h).mean_luma;
    CHECK(l0 < l1);
    CHECK(l1 <= l8 + 0.5);
    RendererSettings unshadowed;
    unshadowed.shadows = false;
    const MainLevelView no_shadows = render_main_level_start(unshadowed);
    CHECK_FALSE(no_shadows.stats.shadow_rendered);
    CHECK(full.stats.shadow_rendered);
}

TEST_CASE("anisotropic filtering: off by default on software renderers, applied to every loaded texture") {
    KS_REQUIRE_GL();
    AssetLibrary assets(assets_dir());
    TextureCache& cache = assets.textures();
    const Texture& t = cache.get(assets_dir() / "textures" / "concrete_basecolor.png", ColorSpace::Srgb);
    REQUIRE_FALSE(t.placeholder);
    const std::string renderer = ks::test::gl_context()->renderer();
    if (!epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") &&
        !epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic")) {
        CHECK(cache.max_anisotropy() == 1.0f);
        return;
    }
    auto texture_anisotropy = [&] {
        float a = 0.0f;
        glBindTexture(GL_TEXTURE_2D, t.id);
        glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &a);
        return a;
    };
    if (is_software_renderer(renderer)) {
        CHECK(cache.max_anisotropy() == 1.0f);
        CHECK(texture_anisotropy() == 1.0f);
    }
    cache.set_max_anisotropy(4.0f);
    CHECK(texture_anisotropy() == cache.max_anisotropy());
    CHECK(cache.max_anisotropy() > 1.0f);
    cache.set_max_anisotropy(std::nanf(""));
    CHECK(texture_anisotropy() == 1.0f);
}
