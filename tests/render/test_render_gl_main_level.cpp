// Renderer tests that need GL (hidden window under Xvfb + llvmpipe in CI) on the main level from the player
// start: the picture is lit, textured and culled and matches a golden image within a tolerance; the fast path
// (software rasterisers) looks like the full path, and its options (trilinear mips, occlusion culling, the
// depth pre-pass) change the picture as they should; switching lights and render features off changes it
// the way it should.
#include "gl_test_support.h"
#include "render_gl_support.h"
#include "test_support.h"

#include "core/log.h"
#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "render/view_model.h"

#include <doctest/doctest.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace ks;
using namespace ks::render;
namespace fs = std::filesystem;
using ks::test::render_offscreen;

namespace ks::test::render_gl {
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

MainLevelView render_main_level_start(RendererSettings settings = full_quality(), float fog_density = -1.0f) {
    return ks::test::render_main_level_start(settings, fog_density);
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

TEST_CASE(
    "fast path: fog thickens with density as the full path's does (the cheap exponential in the shader)") {
    KS_REQUIRE_GL();
    auto mean_luma = [](const std::vector<unsigned char>& rgb) {
        return ks::test::image_stats(rgb, ks::test::kGlWidth, ks::test::kGlHeight).mean_luma;
    };
    // Down the first room to its far wall (~50 units): density 0.02 hides about two thirds of it, a darkening
    // of 11-13 in mean luma.
    const double clear_fast = mean_luma(render_main_level_start(fast_quality(1.0f), 0.0f).rgb);
    const double clear_full = mean_luma(render_main_level_start(full_quality(), 0.0f).rgb);
    const double foggy_fast = mean_luma(render_main_level_start(fast_quality(1.0f), 0.02f).rgb);
    const double foggy_full = mean_luma(render_main_level_start(full_quality(), 0.02f).rgb);
    const double level_fast = mean_luma(render_main_level_start(fast_quality(1.0f)).rgb);
    MESSAGE("mean luma, no fog / the level's 0.004 / 0.02: fast "
            << clear_fast << " / " << level_fast << " / " << foggy_fast << ", full " << clear_full
            << " / - / " << foggy_full);
    CHECK(foggy_fast < clear_fast - 8.0); // the fog reaches the pixels
    CHECK(level_fast < clear_fast);       // the level's own light fog too
    CHECK(level_fast > foggy_fast);
    // The same darkening as the full path's exact exp() (which fogs by radial distance, not view depth).
    CHECK(std::abs((clear_fast - foggy_fast) - (clear_full - foggy_full)) < 6.0);
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
    "fast path: occlusion culling, the depth pre-pass (floors left out), fast_level, the model programs and "
    "single-sided materials' back-face culling change no pixel, anywhere in the main level") {
    KS_REQUIRE_GL();
    auto level = level::load_level_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE(level.ok());
    AssetLibrary assets(assets_dir());
    auto scene = LevelScene::build(*level, assets, ks::test::direct_light_only());
    RendererSettings plain = fast_quality(1.0f);
    plain.occlusion_culling = false;
    plain.depth_prepass = false;
    plain.fast_level_shader = false;
    plain.fast_model_shaders = false;
    plain.cull_single_sided = false;
    RendererSettings floors_in_prepass = fast_quality(1.0f);
    floors_in_prepass.prepass_skips_floors = false;
    CHECK(fast_quality(1.0f).prepass_skips_floors);
    CHECK(fast_quality(1.0f).fast_model_shaders);
    auto fast = SceneRenderer::create(assets.textures(), fast_quality(1.0f));
    auto whole_prepass = SceneRenderer::create(assets.textures(), floors_in_prepass);
    REQUIRE(whole_prepass);
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
    // The rifle in view: the model programs draw it; its materials, like every generated model's, are
    // single-sided, culled on one side and not on the other.
    ViewModel rifle;
    std::vector<Mat4> scratch;
    assets.model("rifle").emit(rifle_view_transform(0.0f), scratch, rifle.instances);
    frame.view_model = &rifle;
    // Eyes on a grid over the whole level (in rooms, in walls' ends, outside), four headings each, looking
    // slightly down and up: the images must match (the pre-pass may move a depth-tied pixel by rounding).
    int views = 0, occluded_views = 0, floors_skipped = 0;
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
                FrameStats w = (*whole_prepass)->render(frame);
                std::vector<unsigned char> whole = ctx->read_rgb();
                FrameStats b = (*reference)->render(frame);
                std::vector<unsigned char> ref = ctx->read_rgb();
                const double diff = ks::test::mean_abs_diff(img, ref);
                CHECK(ks::test::mean_abs_diff(img, whole) < 0.05);
                // The floor or ceiling under or over the eye is not in the pre-pass: fewer draws.
                CHECK(a.draw_calls <= w.draw_calls);
                floors_skipped += a.draw_calls < w.draw_calls ? 1 : 0;
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
    MESSAGE(floors_skipped << " views left a floor or ceiling out of the pre-pass");
    CHECK(floors_skipped > views / 4);
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

} // namespace ks::test::render_gl
