// run_game_app: the game's command line (automation options, seed, MSAA, level check), its window,
// renderer and GameApp.
#include "game_app_internal.h"

#include "core/cli.h"
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "core/startup_trace.h"
#include "level/campaign.h"
#include "level/level_io.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace ks::runtime {

namespace {

void print_help() {
    std::printf(
        "usage: killswitch [--level FILE | --campaign FILE] [--dojo] [--seed N] [--msaa N] [--width W] "
        "[--height H]\n"
        "                  [--screen NAME --screenshot FILE --frames N] [--warp x,y,z,yaw,pitch]\n"
        "                  [--dojo-key K --dojo-time S] [--no-vsync]\n"
        "  (no option)       loading screen, then the main menu (Campaign, Play, Custom level..., Dojo, How "
        "to "
        "Play,\n"
        "                    Options, Credits, Quit)\n"
        "  --level FILE      the level Play starts (default levels/main.json)\n"
        "  --campaign FILE   play this campaign from its first level at once (the menu's Campaign plays it "
        "too;\n"
        "                    default levels/campaign.json)\n"
        "  --dojo            go straight to the Dojo (levels/dojo.json)\n"
        "  --screen NAME     start on one screen: loading menu howto credits options controls custom-levels\n"
        "                    campaign-choice play pause death win summary campaign-complete (summary and\n"
        "                    campaign-complete win the campaign's levels at their control panels) or dojo;\n"
        "                    the status file's names (paused, dead, won, ...) are taken too\n"
        "  --warp ...        put the player's feet at x,y,z facing yaw,pitch (degrees) before the first "
        "frame\n"
        "  --fire            fire one shot on the first step (after --warp)\n"
        "  --dojo-key K      in the Dojo, press key K (0-9) before the first frame\n"
        "  --dojo-time S     ... and advance the animation S seconds, then hold it (for screenshots)\n"
        "  --seed N          the game's random seed (default 1)\n"
        "  --target-fps N    the frame rate the automatic render scale holds on a software rasteriser\n"
        "                    (default 60: full resolution whenever the machine keeps up); also turns it on\n"
        "                    for a --screenshot run, which otherwise keeps a fixed scale\n"
        "  --difficulty D    easy, normal or hard for this run (default: the options' choice)\n"
        "  --status-file F   rewrite F each frame the state changes: screen, buttons, player, doors, ...\n"
        "  --audio-out F.wav record the sound mix to a 48 kHz stereo WAV instead of playing it (with\n"
        "                    --screenshot --frames the frames are a fixed 1/60 s: the same run, the same "
        "file)\n"
        "  --logic-trace F   write each level's logic events and actions as they happen (- = stdout; the\n"
        "                    editor's play-test log shows them; format in docs/game.md, \"Logic trace\")\n"
        "  --logic-break B   show the logic debugger (F3) and halt when the event fires: an entity id, an\n"
        "                    event or ID:EVENT, e.g. 68:on_enter (F6 halt/resume, F7 one step, F8 break)\n"
        "  --input-script F  timed key/mouse events by frame (see runtime/model/input_script.h); with\n"
        "                    --screenshot the frames are a fixed 1/60 s, so the run is deterministic\n"
        "  --view MODEL      (renderer) one model on a turntable; --camera x,y,z,yaw,pitch: render-only "
        "view\n"
        "  --headless ...    run the game without a window (see killswitch --headless --help)\n"
        "  --version         print \"killswitch VERSION\" and exit\n"
        "controls: WASD/arrows move, mouse looks, click shoots, Space jumps, E interacts, Esc pauses, M "
        "mutes,\n"
        "          F3 shows the logic debugger\n"
        "options file: $XDG_CONFIG_HOME/killswitch/options.json (or ~/.config/killswitch/options.json)\n");
}

} // namespace

int run_game_app(const CommandLine& cl, const shell::ShellConfig& shell_config) {
    if (cl.has("help")) {
        print_help();
        return 0;
    }
    GameApp::Automation automation;
    automation.dojo = cl.has("dojo");
    if (auto name = cl.get("screen"); name && !name->empty()) {
        const auto request = parse_screen_request(*name);
        if (!request) {
            log::error("--screen '", *name, "': not a screen; use one of ", screen_request_names());
            return 2;
        }
        automation.screen = request->screen;
        automation.dojo = automation.dojo || request->dojo;
    }
    if (auto status = cl.get("status-file")) automation.status_file = paths::resolve_user_path(*status);
    if (auto script = cl.get("input-script")) {
        const auto path = paths::resolve_user_path(*script);
        auto text = files::read_text(path);
        if (!text) {
            log::error(text.error().str());
            return 2;
        }
        auto events = parse_input_script(*text, path.string());
        if (!events) {
            log::error(events.error().str());
            return 2;
        }
        automation.script = std::move(*events);
        automation.scripted = true;
    }
    automation.fire = cl.has("fire");
    if (cl.has("target-fps")) {
        auto fps = cl.get_double("target-fps", 60.0);
        if (!fps || !std::isfinite(*fps) || *fps < 10.0 || *fps > 1000.0) {
            log::error("--target-fps '", cl.get_or("target-fps", ""),
                       "': give the frame rate to hold, 10 .. 1000 (e.g. --target-fps 60)");
            return 2;
        }
        automation.target_fps = *fps;
    }
    if (auto out = cl.get("audio-out")) {
        if (out->empty()) {
            log::error("--audio-out: give a file name, e.g. --audio-out run.wav");
            return 2;
        }
        automation.audio_out = paths::resolve_user_path(*out);
    }
    if (auto trace = cl.get("logic-trace")) {
        if (trace->empty()) {
            log::error(
                "--logic-trace: give a file name, e.g. --logic-trace run.trace, or - for standard output");
            return 2;
        }
        automation.logic_trace =
            *trace == "-" ? std::filesystem::path("-") : paths::resolve_user_path(*trace);
        // Refused before the window opens, as the headless run refuses it.
        if (automation.logic_trace != "-" && !std::ofstream(automation.logic_trace)) {
            log::error(automation.logic_trace.string(),
                       ": cannot write the logic trace (give --logic-trace a file in a folder that exists)");
            return 2;
        }
    }
    if (auto spec = cl.get("logic-break")) {
        auto parsed = parse_logic_break(*spec);
        if (!parsed) {
            log::error(parsed.error().str());
            return 2;
        }
        automation.logic_break = *parsed;
    }
    if (auto warp = cl.get("warp")) {
        const Result<PoseArgument> pose = parse_pose(*warp);
        if (!pose) {
            log::error("--warp '", *warp, "': ", pose.error().message, " (", pose.error().hint, ")");
            return 2;
        }
        automation.warp = {pose->position.x, pose->position.y, pose->position.z, pose->yaw_degrees,
                           pose->pitch_degrees};
    }
    if (auto key = cl.get("dojo-key")) {
        if (key->size() != 1 || (*key)[0] < '0' || (*key)[0] > '9') {
            log::error("--dojo-key '", *key, "': expected one digit 0-9");
            return 2;
        }
        automation.dojo_key = (*key)[0];
    }
    if (cl.has("dojo-time")) {
        auto t = cl.get_double("dojo-time", 0.0);
        if (!t || !std::isfinite(*t) || *t < 0.0 || *t > 600.0) {
            log::error("--dojo-time: expected seconds between 0 and 600");
            return 2;
        }
        automation.dojo_time = *t;
    }
    if (auto difficulty = cl.get("difficulty")) {
        auto parsed = game::parse_difficulty(*difficulty, Location("command line", 0, 0, "--difficulty"));
        if (!parsed) {
            log::error(parsed.error().str());
            return 2;
        }
        automation.difficulty = *parsed;
    }
    auto seed = cl.get_int("seed", 1, 0, 2147483647);
    if (!seed) {
        log::error(seed.error().str());
        return 2;
    }
    auto msaa = cl.get_int("msaa", -1, -1, 16);
    if (!msaa) {
        log::error(msaa.error().str());
        return 2;
    }
    if (auto campaign = cl.get("campaign")) {
        // Checked before a window opens, like a level: a bad file is a command-line error.
        automation.campaign = paths::resolve_user_path(*campaign);
        automation.start_campaign = true;
        if (auto loaded = level::load_campaign(automation.campaign); !loaded) {
            log::error(loaded.error().str());
            return 2;
        }
    }
    const auto level_path = paths::resolve_user_path(cl.get_or("level", paths::level("main.json").string()));
    {
        // Check the level before opening a window: a bad file is a command-line error.
        level::LoadReport report;
        auto loaded = level::load_level_file(level_path, &report);
        if (!loaded) {
            log::error(loaded.error().str());
            return 2;
        }
    }
    startup::mark("level file checked");
    if (!shell::display_available()) {
        std::fprintf(stderr, "%s\n", shell::no_display_message("killswitch").c_str());
        return 3;
    }
    shell::ShellConfig config = shell_config;
    config.msaa_samples = 0; // the renderer owns MSAA
    config.fixed_step = game::GameSettings{}.step;
    // Tests count the status file's frames to know their input was seen: frames keep coming when idle.
    if (!automation.status_file.empty()) config.heartbeat_seconds = shell::kStatusHeartbeatSeconds;
    auto shell = shell::AppShell::create(config);
    if (!shell) {
        log::error(shell.error().str());
        return 1;
    }
    startup::mark("ImGui and fonts");
    int code = 0;
    {
        render::AssetLibrary assets(paths::asset(""));
        render::RendererSettings settings = render::renderer_settings_from_environment();
        settings.msaa_samples = *msaa >= 0 ? *msaa : render::default_msaa_for((*shell)->gl_renderer());
        auto renderer = render::SceneRenderer::create(assets.textures(), settings);
        startup::mark("renderer (shaders)");
        if (!renderer) {
            log::error(renderer.error().str());
            shell::AppShell::destroy(*shell);
            return 1;
        }
        GameApp app(**shell, **renderer, assets, level_path, static_cast<std::uint64_t>(*seed));
        if (auto started = app.start(automation); !started) {
            log::error(started.error().str());
            code = 2;
        } else {
            startup::mark("app started");
            code = app.run();
        }
    }
    shell::AppShell::destroy(*shell);
    return code;
}

} // namespace ks::runtime
