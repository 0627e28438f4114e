// killswitch: the game runtime. Routes to the playable game (runtime/app: menus, game, Dojo), to the headless
// runner (--headless), or to the renderer's views: a level from --camera with the
// first-person rifle and HUD, flies freely when interactive, and shows one model on a turntable (--view).
#include "app/game_app.h"
#include "core/cli.h"
#include "core/log.h"
#include "core/paths.h"
#include "fly_camera.h"
#include "game/headless.h"
#include "level/level_io.h"
#include "shell/app_shell.h"
#include "render/asset_library.h"
#include "shell/hud.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "render/view_model.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include <cstdio>

namespace {
const std::vector<std::string> kFlags = {"no-vsync", "help", "no-hud", "effects"};

void print_help() {
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

void print_headless_help() {
    std::printf(
        "usage: killswitch --headless [--level FILE] [--seconds S] [--seed N] [--autoplay]\n"
        "                  [--record FILE | --replay FILE] [--stats-json FILE|-]\n"
        "  runs the game without a window at a fixed 120 Hz step, as fast as the CPU allows\n"
        "  --level FILE      the level to play (default levels/main.json)\n"
        "  --seconds S       simulated time limit (default 300)\n"
        "  --seed N          the game's random seed (default 1)\n"
        "  --autoplay        a bot plays (walks the level, fights, reaches the control panel)\n"
        "  --record FILE     save every step's input (replays bit-exactly)\n"
        "  --replay FILE     play a recording back with its recorded seed\n"
        "  --stats-json F    write the outcome, time, kills, damage and state hash as JSON (- = stdout)\n"
        "exit code 0 when the run completed (whatever its outcome), 2 on bad options or a bad level\n");
}

// The turntable's stage: a tiled floor disc, a sky-ish ambient, a sun and two coloured key lights.
struct Turntable {
    const ks::render::Model* model = nullptr;
    std::unique_ptr<ks::render::GpuMesh> floor;
    const ks::render::Material* floor_material = nullptr;
};
} // namespace

int main(int argc, char** argv) {
    using namespace ks;
    std::vector<std::string> flags = kFlags;
    flags.insert(flags.end(), runtime::game_app_flags().begin(), runtime::game_app_flags().end());
    flags.insert(flags.end(), game::headless_flags().begin(), game::headless_flags().end());
    auto cl = CommandLine::parse(argc, argv, flags);
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    // Routing: --headless → the game without a window; --view / --camera → the renderer's turntable and
    // render-only views (below); anything else → the playable game (menus, game, Dojo).
    if (cl->has("headless")) {
        if (cl->has("help")) {
            print_headless_help();
            return 0;
        }
        if (auto unknown = cl->unknown(game::headless_option_names()); !unknown.empty()) {
            log::error("unknown option ", unknown.front(), " for --headless (see common/game/headless.h)");
            return 2;
        }
        auto options = game::parse_headless_options(*cl);
        if (!options) {
            log::error(options.error().str());
            return 2;
        }
        auto stats = game::run_headless(*options);
        if (!stats) {
            log::error(stats.error().str());
            return 2;
        }
        std::printf("%s\n", stats->summary().c_str());
        return 0;
    }
    if (!cl->has("view") && !cl->has("camera")) {
        std::vector<std::string> app_known = shell::shell_options();
        app_known.insert(app_known.end(), runtime::game_app_options().begin(),
                         runtime::game_app_options().end());
        app_known.push_back("no-vsync");
        if (auto unknown = cl->unknown(app_known); !unknown.empty()) {
            log::error("unknown option ", unknown.front(), " (see killswitch --help)");
            return 2;
        }
        auto app_config = shell::shell_config_from_command_line(*cl, {});
        if (!app_config) {
            log::error(app_config.error().str());
            return 2;
        }
        return runtime::run_game_app(*cl, *app_config);
    }
    if (cl->has("help")) {
        print_help();
        return 0;
    }
    std::vector<std::string> known = shell::shell_options();
    known.insert(known.end(), {"level", "camera", "view", "msaa", "help", "no-hud", "effects"});
    if (auto unknown = cl->unknown(known); !unknown.empty()) {
        log::error("unknown option --", unknown.front(), " (see killswitch --help)");
        return 2;
    }
    auto config = shell::shell_config_from_command_line(*cl, {});
    if (!config) {
        log::error(config.error().str());
        return 2;
    }
    auto msaa_option = cl->get_int("msaa", -1, -1, 16);
    if (!msaa_option) {
        log::error(msaa_option.error().str());
        return 2;
    }
    const bool view_mode = cl->has("view");
    level::Level level;
    if (!view_mode) {
        auto path = paths::resolve_user_path(cl->get_or("level", paths::level("main.json").string()));
        level::LoadReport report;
        auto loaded = level::load_level_file(path, &report);
        if (!loaded) {
            log::error(loaded.error().str());
            return 2;
        }
        for (const auto& d : report.diagnostics) log::warn(d.error.str());
        level = std::move(*loaded);
    }
    render::Camera camera;
    bool camera_given = false;
    if (auto c = cl->get("camera")) {
        if (!runtime::parse_camera(*c, camera)) {
            log::error("--camera '", *c,
                       "': expected x,y,z,yaw,pitch with finite numbers, e.g. --camera 0,3,25,0,0");
            return 2;
        }
        camera_given = true;
    }
    if (!shell::display_available()) {
        std::fprintf(stderr, "%s\n", shell::no_display_message("killswitch").c_str());
        return 3;
    }
    config->msaa_samples = 0; // the shell's window stays single-sampled; the renderer owns MSAA
    auto shell = shell::AppShell::create(*config);
    if (!shell) {
        log::error(shell.error().str());
        return 1;
    }
    int exit_code = 0;
    {
        render::AssetLibrary assets(paths::asset(""));
        render::RendererSettings settings;
        settings.msaa_samples =
            *msaa_option >= 0 ? *msaa_option : render::default_msaa_for((*shell)->gl_renderer());
        auto renderer = render::SceneRenderer::create(assets.textures(), settings);
        if (!renderer) {
            log::error(renderer.error().str());
            shell::AppShell::destroy(*shell);
            return 1;
        }
        const float aspect = static_cast<float>(config->width) / static_cast<float>(config->height);
        std::unique_ptr<render::LevelScene> scene;
        Turntable turntable;
        render::Environment environment;
        std::vector<render::MeshInstance> instances;
        std::vector<render::Light> lights;
        std::vector<Mat4> scratch;
        render::ViewModel view_model;
        const render::Model& rifle = assets.model("rifle");
        std::vector<std::unique_ptr<render::ParticleEmitter>> emitters;
        std::vector<const render::ParticleEmitter*> emitter_list;
        double time = 0.0;
        float turntable_radius = 3.0f;

        if (view_mode) {
            std::string name = cl->get_or("view", "robot");
            std::filesystem::path p(name);
            if (p.has_extension()) name = paths::resolve_user_path(p).string();
            turntable.model = &assets.model(name);
            render::MeshData floor;
            render::append_box(floor, Vec3(0, -0.05f, 0), Vec3(40, 0.1f, 40), Mat4(1.0f), 2.0f);
            turntable.floor = std::make_unique<render::GpuMesh>(floor);
            turntable.floor_material = &assets.surface("tiles");
            environment.sky_color = Vec3(0.35f, 0.38f, 0.45f);
            environment.ground_color = Vec3(0.12f, 0.11f, 0.1f);
            environment.sun_direction = Vec3(-0.4f, -1.0f, -0.5f);
            environment.sun_color = Vec3(0.55f, 0.52f, 0.48f);
            environment.fog_color = Vec3(0.02f, 0.025f, 0.035f);
            environment.fog_density = 0.04f;
            const auto& b = turntable.model->bounds;
            turntable_radius = std::max(1.0f, glm::length(b.max - b.min)) * 1.1f;
            lights.push_back({render::Light::Type::Point, Vec3(2.5f, 3.0f, 3.0f) * (turntable_radius / 3.0f),
                              Vec3(0, -1, 0), Vec3(1.0f, 0.85f, 0.7f), 0.6f, turntable_radius * 4.0f, 0.8f,
                              0.9f});
            lights.push_back({render::Light::Type::Point,
                              Vec3(-3.0f, 2.0f, -2.0f) * (turntable_radius / 3.0f), Vec3(0, -1, 0),
                              Vec3(0.5f, 0.7f, 1.0f), 0.5f, turntable_radius * 4.0f, 0.8f, 0.9f});
        } else {
            scene = render::LevelScene::build(level, assets);
            environment = scene->environment();
            if (!camera_given) camera = render::player_start_camera(level, aspect);
            if (cl->has("effects")) {
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
                for (auto& e : emitters) emitter_list.push_back(e.get());
            }
        }
        camera.aspect = aspect;
        runtime::FlyCamera fly;
        const bool hud = !view_mode && !cl->has("no-hud");
        shell::HudState hud_state;
        render::FrameStats last_stats;

        shell::ShellHooks hooks;
        hooks.fixed_update = [&](double step) {
            time += step;
            for (auto& e : emitters) e->update(static_cast<float>(step));
        };
        hooks.render = [&](const shell::FrameInfo& info) {
            if (!(*shell)->screenshot_mode()) fly.update((*shell)->window(), info.frame_dt, camera);
            camera.aspect = static_cast<float>(info.width) / std::max(1, info.height);
            render::SceneFrame frame;
            frame.width = info.width;
            frame.height = info.height;
            frame.environment = environment;
            if (view_mode) {
                instances.clear();
                float angle = static_cast<float>(time) * 0.6f + 0.6f;
                Mat4 root = glm::rotate(Mat4(1.0f), angle, Vec3(0, 1, 0));
                const auto& b = turntable.model->bounds;
                root = glm::translate(root, Vec3(-b.center().x, -b.min.y, -b.center().z));
                turntable.model->emit(root, scratch, instances);
                instances.push_back(
                    {turntable.floor.get(), turntable.floor_material, Mat4(1.0f), 1.0f, false});
                float h = b.max.y - b.min.y;
                Vec3 target(0.0f, h * 0.45f, 0.0f);
                camera.position = target + Vec3(0.0f, turntable_radius * 0.35f, turntable_radius * 1.15f);
                Vec3 d = glm::normalize(target - camera.position);
                camera.yaw = std::atan2(-d.x, -d.z);
                camera.pitch = std::asin(d.y);
                camera.fov_y = radians(45.0f);
            } else {
                scene->emit(instances, lights);
                view_model.instances.clear();
                if (hud) rifle.emit(render::rifle_view_transform(0.0f), scratch, view_model.instances);
                frame.view_model = &view_model;
                frame.particles = &emitter_list;
            }
            frame.camera = camera;
            frame.instances = &instances;
            frame.lights = &lights;
            last_stats = (*renderer)->render(frame);
        };
        hooks.imgui = [&](const shell::FrameInfo& info) {
            ImDrawList* draw = ImGui::GetForegroundDrawList();
            if (hud) {
                shell::HudFonts fonts{(*shell)->fonts().hud};
                shell::draw_hud(draw, hud_state, fonts, static_cast<float>(info.width),
                                 static_cast<float>(info.height));
            }
            if (!(*shell)->screenshot_mode()) {
                char text[160];
                std::snprintf(text, sizeof(text), "%.1f ms  %d draws  %lld tris  %d lights",
                              info.frame_dt * 1000.0, last_stats.draw_calls, last_stats.triangles,
                              last_stats.lights_in_view);
                draw->AddText((*shell)->fonts().mono, 0.0f,
                              ImVec2(10.0f, static_cast<float>(info.height) - 24.0f),
                              IM_COL32(255, 255, 255, 200), text);
            }
        };
        hooks.wants_close = [&]() { return glfwGetKey((*shell)->window(), GLFW_KEY_ESCAPE) == GLFW_PRESS; };
        exit_code = (*shell)->run(hooks);
    }
    shell::AppShell::destroy(*shell);
    return exit_code;
}
