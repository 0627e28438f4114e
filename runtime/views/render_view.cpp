#include "views/render_view.h"

#include "core/cli.h"
#include "core/log.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/model.h"
#include "render/scene_renderer.h"
#include "render/view_model.h"
#include "shell/app_shell.h"
#include "shell/hud.h"
#include "views/fly_camera.h"
#include "views/model_viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

namespace ks::runtime {

const std::vector<std::string>& render_view_options() {
    static const std::vector<std::string> options = {"level", "camera", "view",   "msaa",
                                                     "help",  "no-hud", "effects"};
    return options;
}

void print_render_view_help() {
    std::printf(
        "usage: killswitch [--level FILE] [--camera x,y,z,yaw,pitch] [--view MODEL] [--msaa N] [--no-hud]\n"
        "                  [--effects] [--width W] [--height H] [--screenshot FILE --frames N] [--no-vsync]\n"
        "  --level FILE      render a level (default levels/main.json) from its player start\n"
        "  --camera ...      eye position and yaw/pitch in degrees (yaw 0 looks along -z)\n"
        "  --view MODEL      show one model (a path or a name in assets/models) on a turntable\n"
        "  --msaa N          0, 2, 4 or 8 samples (default: 4 on GPUs, 0 on software renderers)\n"
        "  --effects         spawn demo particle effects (fire, smoke) in front of the camera\n"
        "interactive: WASD move, Q/E down/up, Shift faster, hold the right mouse button to look, Esc "
        "quits\n");
}

namespace {

struct ViewOptions {
    shell::ShellConfig config;
    int msaa = -1;                    // -1: the GL renderer's default
    std::optional<std::string> model; // --view
    level::Level level;
    std::optional<geometry::Camera> camera; // --camera
    bool hud = true;
    bool effects = false;
};

Result<ViewOptions> parse_view_options(const CommandLine& cl) {
    std::vector<std::string> known = shell::shell_options();
    known.insert(known.end(), render_view_options().begin(), render_view_options().end());
    if (auto unknown = cl.unknown(known); !unknown.empty())
        return Error("unknown option --" + unknown.front() + " (see killswitch --help)");
    ViewOptions options;
    auto config = shell::shell_config_from_command_line(cl, {});
    if (!config) return config.error();
    options.config = *config;
    options.config.msaa_samples = 0; // the shell's window stays single-sampled; the renderer owns MSAA
    auto msaa = cl.get_int("msaa", -1, -1, 16);
    if (!msaa) return msaa.error();
    options.msaa = *msaa;
    if (cl.has("view")) options.model = cl.get_or("view", "robot");
    if (!options.model) {
        auto path = paths::resolve_user_path(cl.get_or("level", paths::level("main.json").string()));
        level::LoadReport report;
        auto loaded = level::load_level_file(path, &report);
        if (!loaded) return loaded.error();
        for (const auto& d : report.diagnostics) log::warn(d.error.str());
        options.level = std::move(*loaded);
    }
    if (auto c = cl.get("camera")) {
        const Result<PoseArgument> pose = parse_pose(*c);
        if (!pose) return Error("--camera '" + *c + "': " + pose.error().message, {}, pose.error().hint);
        geometry::Camera camera;
        camera.position = pose->position;
        camera.yaw = radians(pose->yaw_degrees);
        camera.pitch = radians(std::clamp(pose->pitch_degrees, -89.0f, 89.0f));
        options.camera = camera;
    }
    options.hud = !options.model && !cl.has("no-hud");
    options.effects = cl.has("effects");
    return options;
}

// Fire with smoke above it, ten metres in front of the camera.
void add_demo_effects(const geometry::Camera& camera,
                      std::vector<std::unique_ptr<render::ParticleEmitter>>& emitters) {
    Vec3 ahead = camera.position + camera.forward() * 10.0f;
    render::ParticleParams fire;
    fire.position = Vec3(ahead.x, std::max(ahead.y - 2.5f, 0.5f), ahead.z);
    fire.spawn_radius = Vec3(0.8f, 0.3f, 0.8f);
    fire.size = 1.5f;
    fire.velocity = Vec3(0.3f, 2.5f, 0.3f);
    fire.duration = 0.0f;
    fire.per_frame = 2;
    fire.grow = 2.0f;
    render::ParticleParams smoke = fire;
    smoke.texture = "smoke";
    smoke.blend = render::ParticleBlend::Alpha;
    smoke.position.y += 2.0f;
    smoke.life = 2.0f;
    smoke.size = 2.0f;
    smoke.per_frame = 1;
    smoke.color_start = Vec3(0.35f);
    smoke.color_end = Vec3(0.2f);
    emitters.push_back(std::make_unique<render::ParticleEmitter>(smoke, 2));
    emitters.push_back(std::make_unique<render::ParticleEmitter>(fire, 1));
}

// What one view draws each frame: a turntable or a level scene, its lights and effects.
struct ViewStage {
    std::unique_ptr<render::LevelScene> scene;
    std::optional<ModelViewer> turntable;
    render::Environment environment;
    std::vector<render::MeshInstance> instances;
    std::vector<render::Light> lights;
    std::vector<render::ShadowCaster> casters; // the level's robots, pickups and cylinders
    std::vector<Mat4> scratch;
    render::ViewModel view_model;
    std::vector<std::unique_ptr<render::ParticleEmitter>> emitters;
    std::vector<const render::ParticleEmitter*> emitter_list;
    geometry::Camera camera;
    double time = 0.0;
};

void build_stage(const ViewOptions& options, render::AssetLibrary& assets,
                 const render::LevelSceneOptions& scene_options, ViewStage& stage) {
    const float aspect = static_cast<float>(options.config.width) / static_cast<float>(options.config.height);
    if (options.camera) stage.camera = *options.camera;
    if (options.model) {
        stage.turntable.emplace(assets, *options.model, stage.environment, stage.lights);
    } else {
        stage.scene = render::LevelScene::build(options.level, assets, scene_options);
        stage.environment = stage.scene->environment();
        if (!options.camera) stage.camera = render::player_start_camera(options.level, aspect);
        if (options.effects) add_demo_effects(stage.camera, stage.emitters);
        for (auto& e : stage.emitters) stage.emitter_list.push_back(e.get());
    }
    stage.camera.aspect = aspect;
}

int run_view_loop(shell::AppShell& shell, const ViewOptions& options, render::AssetLibrary& assets,
                  render::SceneRenderer& renderer) {
    ViewStage stage;
    build_stage(options, assets, render::level_scene_options(renderer.settings()), stage);
    const render::Model& rifle = assets.model("rifle");
    FlyCamera fly;
    shell::HudState hud_state;
    render::FrameStats last_stats;

    shell::ShellHooks hooks;
    hooks.fixed_update = [&](double step) {
        stage.time += step;
        for (auto& e : stage.emitters) e->update(static_cast<float>(step));
    };
    hooks.render = [&](const shell::FrameInfo& info) {
        if (!shell.screenshot_mode()) fly.update(shell.window(), info.frame_dt, stage.camera);
        stage.camera.aspect = static_cast<float>(info.width) / std::max(1, info.height);
        render::SceneFrame frame;
        frame.width = info.width;
        frame.height = info.height;
        frame.environment = stage.environment;
        if (stage.turntable) {
            stage.turntable->emit(stage.time, stage.scratch, stage.instances, stage.camera);
        } else {
            stage.scene->emit(stage.instances, stage.lights, &stage.casters);
            frame.shadow_casters = &stage.casters;
            stage.view_model.instances.clear();
            if (options.hud)
                rifle.emit(render::rifle_view_transform(0.0f), stage.scratch, stage.view_model.instances);
            frame.view_model = &stage.view_model;
            frame.particles = &stage.emitter_list;
        }
        frame.camera = stage.camera;
        frame.instances = &stage.instances;
        frame.lights = &stage.lights;
        last_stats = renderer.render(frame);
    };
    hooks.imgui = [&](const shell::FrameInfo& info) {
        ImDrawList* draw = ImGui::GetForegroundDrawList();
        if (options.hud) {
            shell::HudFonts fonts{shell.fonts().hud};
            shell::draw_hud(draw, hud_state, fonts, static_cast<float>(info.width),
                            static_cast<float>(info.height));
        }
        if (!shell.screenshot_mode()) {
            char text[160];
            std::snprintf(text, sizeof(text), "%.1f ms  %d draws  %lld tris  %d lights",
                          info.frame_dt * 1000.0, last_stats.draw_calls, last_stats.triangles,
                          last_stats.lights_in_view);
            draw->AddText(shell.fonts().mono, 0.0f, ImVec2(10.0f, static_cast<float>(info.height) - 24.0f),
                          IM_COL32(255, 255, 255, 200), text);
        }
    };
    hooks.wants_close = [&]() { return glfwGetKey(shell.window(), GLFW_KEY_ESCAPE) == GLFW_PRESS; };
    return shell.run(hooks);
}

} // namespace

int run_render_view(const CommandLine& cl) {
    if (cl.has("help")) {
        print_render_view_help();
        return 0;
    }
    auto options = parse_view_options(cl);
    if (!options) {
        log::error(options.error().str());
        return 2;
    }
    if (!shell::display_available()) {
        std::fprintf(stderr, "%s\n", shell::no_display_message("killswitch").c_str());
        return 3;
    }
    auto shell = shell::AppShell::create(options->config);
    if (!shell) {
        log::error(shell.error().str());
        return 1;
    }
    int exit_code = 1;
    {
        render::AssetLibrary assets(paths::asset(""));
        render::RendererSettings settings = render::renderer_settings_from_environment();
        settings.msaa_samples =
            options->msaa >= 0 ? options->msaa : render::default_msaa_for((*shell)->gl_renderer());
        if (auto renderer = render::SceneRenderer::create(assets.textures(), settings); renderer)
            exit_code = run_view_loop(**shell, *options, assets, **renderer);
        else
            log::error(renderer.error().str());
    }
    shell::AppShell::destroy(*shell);
    return exit_code;
}

} // namespace ks::runtime
