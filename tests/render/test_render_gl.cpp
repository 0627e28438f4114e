// Renderer tests that need GL (hidden window under Xvfb + llvmpipe in CI): shaders compile, the quality path
// follows the driver, assets load, missing/corrupt files give the placeholder with one warning, each asset
// renders right on its own (non-blank, expected colours, no magenta, the control panel's screen upright),
// killswitch --screenshot writes PNG files, and textures get anisotropic filtering. The main level's
// pictures (the golden image, the fast path, light and feature switches) are test_render_gl_main_level.cpp's.
#include "gl_test_support.h"
#include "render_gl_support.h"
#include "test_support.h"

#include "core/log.h"
#include "core/paths.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "render/shaders.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <stb_image.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace ks;
using namespace ks::render;
namespace fs = std::filesystem;
using ks::test::render_offscreen;

namespace ks::test::render_gl {
namespace {

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
    const int count = ks::test::check_every_program_builds();
    // pbr, fast, fast_level, fast_level_lit, shadow, particle, line, view_model_composite, view_model_mask,
    // contact_shadow and the six fast_model programs
    CHECK(count == 16);
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

} // namespace ks::test::render_gl
