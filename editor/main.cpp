// killswitch-editor: the level editor. `--script FILE` runs editor commands without a window; otherwise a
// window with the viewport and panels (editor/ui/), optionally rendering N frames to a PNG (--screenshot).
#include "analyze_cli.h"
#include "core/cli.h"
#include "core/log.h"
#include "core/paths.h"
#include "core/version.h"
#include "model/script.h"
#include "model/script_command.h"
#include "shell/app_shell.h"
#include "ui/editor_app.h"
#include "ui/sound_audition.h"

#include <cstdio>

namespace {
const std::vector<std::string> kFlags = {"no-vsync", "help",     "help-script", "dojo",
                                         "navmesh",  "textures", "version"};

void print_help() {
    std::printf(
        "usage: killswitch-editor [--level FILE] [--script FILE] [--run FILE] [--camera x,y,z,yaw,pitch] "
        "[--dojo] [--navmesh]\n"
        "                         [--dojo-file FILE] [--dojo-view clip=NAME,time=S,onion=1]\n"
        "                         [--view top|front|side|perspective|4up] [--inspector TAB] [--status-file "
        "FILE]\n"
        "                         [--report FILE] [--gizmo move|rotate|scale[,local]] [--textures]\n"
        "                         [--left-tab outliner|layers|prefabs]\n"
        "       killswitch-editor --version  (prints \"killswitch-editor VERSION\" and exits)\n"
        "       killswitch-editor --analyze LEVEL|CAMPAIGN [--runs N] [--report FILE] [--seconds S] "
        "[--threads T]\n"
        "                         [--bot-profile perfect|experienced|new-player[,...]] [--difficulty "
        "easy|normal|hard[,...]]\n"
        "                         [--width W] [--height H] [--screenshot FILE --frames N] [--no-vsync]\n"
        "  --level FILE      open a level file (default: a new untitled level)\n"
        "  --script FILE     run editor commands (docs/editor.md) without a window, then exit:\n"
        "                    0 when every line ran, 1 with 'file:line: message' otherwise\n"
        "  --help-script     list every script command (its forms and what it does) and exit\n"
        "  --run FILE        run editor commands in the window session before the first frame\n"
        "  --camera ...      viewport camera x,y,z,yaw,pitch in degrees (yaw 0 looks along -z)\n"
        "  --dojo            start in the dojo (animation) tab\n"
        "  --dojo-file FILE  the dojo's clip file (default: assets/animations/robot.json)\n"
        "  --dojo-view V     where the dojo starts: clip=NAME (shown), time=S (paused there), onion=1\n"
        "  --navmesh         show the robots' navigation mesh (View > Navigation mesh)\n"
        "  --view V          start in the top, front or side (orthographic) or perspective view, or in the\n"
        "                    4-up view (all four at once; Numpad 0 or View > 4-up toggles it)\n"
        "  --report FILE     show this play-test report over the viewport (default: LEVEL.playtest.json\n"
        "                    beside the level, when there is one)\n"
        "  --analyze LEVEL   play LEVEL N times with the autoplay bot (seeds 1..N, --runs, default 20) on\n"
        "                    every core, without a window; write the report (default LEVEL.playtest.json\n"
        "                    beside it; --seconds: time limit per run, default 300), print a summary;\n"
        "                    a campaign, or several profiles or difficulties (comma lists): a table of\n"
        "                    win rates and where the bot died\n"
        "  --inspector TAB   start with the inspector's properties, links or objectives tab shown\n"
        "  --gizmo MODE      start with the gizmo in move, rotate or scale mode (rotate,local: own axes)\n"
        "  --textures        open the texture browser for the selection (select it with --run)\n"
        "  --left-tab TAB    start with the left column's outliner, layers or prefabs tab shown\n"
        "  --status-file F   rewrite F with a JSON snapshot of the session (selection, entity count, undo\n"
        "                    depth, dirty flag, play-test, where the palette and gizmo are) when it changes\n"
        "  $KS_PLAYTEST_COMMAND  the runtime F5 starts (default: killswitch next to the editor)\n"
        "  --screenshot FILE render N frames (--frames, default 3), save the window as PNG and exit\n"
        "keys: see the Help menu and docs/editor.md (Using the editor)\n");
}

int run_script_mode(const std::string& file) {
    auto report = ks::editor::run_script(ks::paths::resolve_user_path(file));
    if (!report) {
        std::fprintf(stderr, "%s\n", report.error().str().c_str());
        return 1;
    }
    std::printf("%s: %d lines, %d expectations, %zu files saved\n", file.c_str(), report->lines_run,
                report->expectations_checked, report->saved.size());
    return 0;
}
} // namespace

int main(int argc, char** argv) {
    using namespace ks;
    auto cl = CommandLine::parse(argc, argv, kFlags);
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    if (cl->has("help")) {
        print_help();
        return 0;
    }
    if (cl->has("help-script")) {
        std::printf("script commands (killswitch-editor --script FILE; docs/editor.md):\n%s",
                    editor::script_usage_listing().c_str());
        return 0;
    }
    if (cl->has("version")) {
        std::printf("%s\n", version::line("killswitch-editor").c_str());
        return 0;
    }
    std::vector<std::string> known = shell::shell_options();
    known.insert(known.end(),
                 {"level", "script", "run", "camera", "help", "help-script", "dojo", "view", "status-file",
                  "navmesh", "dojo-file", "dojo-view", "inspector", "gizmo", "textures", "left-tab"});
    for (const auto& name : editor::analyze_option_names()) known.push_back(name);
    if (auto unknown = cl->unknown(known); !unknown.empty()) {
        log::error("unknown option ", unknown.front(), " (see killswitch-editor --help)");
        return 2;
    }
    if (auto script = cl->get("script")) return run_script_mode(*script);
    if (cl->has("analyze")) return editor::run_analyze_mode(*cl);
    for (const char* analyze_only : {"seconds", "threads", "bot-profile", "difficulty"})
        if (cl->has(analyze_only)) {
            log::error("--", analyze_only, " goes with --analyze LEVEL (see killswitch-editor --help)");
            return 2;
        }

    shell::ShellConfig defaults;
    defaults.title = "Killswitch Editor";
    auto config = shell::shell_config_from_command_line(*cl, defaults);
    if (!config) {
        log::error(config.error().str());
        return 2;
    }
    if (!shell::display_available()) {
        std::fprintf(stderr, "%s\n", shell::no_display_message("killswitch-editor").c_str());
        return 3;
    }
    config->msaa_samples = 0; // the renderer owns MSAA in the viewport's own target
    editor::ui::AppOptions options;
    if (auto level = cl->get("level")) options.level = paths::resolve_user_path(*level);
    options.start_in_dojo = cl->has("dojo");
    if (auto file = cl->get("dojo-file")) options.dojo_file = paths::resolve_user_path(*file);
    options.dojo_view = cl->get("dojo-view");
    options.gizmo = cl->get("gizmo");
    options.texture_browser = cl->has("textures");
    options.show_navmesh = cl->has("navmesh");
    if (auto run = cl->get("run")) options.run_script = paths::resolve_user_path(*run);
    options.camera = cl->get("camera");
    if (auto view = cl->get("view")) {
        const std::string v = *view;
        if (v == "top")
            options.view = editor::ViewMode::Top;
        else if (v == "front")
            options.view = editor::ViewMode::Front;
        else if (v == "side")
            options.view = editor::ViewMode::Side;
        else if (v == "perspective")
            options.view = editor::ViewMode::Perspective;
        else if (v == "4up")
            options.quad_view = true;
        else {
            log::error("--view '", v, "': expected top, front, side, perspective or 4up");
            return 2;
        }
    }
    if (auto tab = cl->get("inspector")) {
        options.inspector_tab = editor::ui::parse_inspector_tab(*tab);
        if (!options.inspector_tab) {
            log::error("--inspector '", *tab, "': expected properties, links or objectives");
            return 2;
        }
    }
    if (auto tab = cl->get("left-tab")) {
        options.left_tab = editor::ui::parse_left_tab(*tab);
        if (!options.left_tab) {
            log::error("--left-tab '", *tab, "': expected outliner, layers or prefabs");
            return 2;
        }
    }
    if (auto report = cl->get("report")) options.report = paths::resolve_user_path(*report);
    if (auto runs = cl->get_int("runs", options.analysis_runs, 1, 200); !runs) {
        log::error(runs.error().str());
        return 2;
    } else {
        options.analysis_runs = *runs;
    }
    if (auto status = cl->get("status-file")) {
        options.status_file = paths::resolve_user_path(*status);
        config->heartbeat_seconds =
            shell::kStatusHeartbeatSeconds; // tests count frames to know input was seen
    }
    options.executable_dir = std::filesystem::absolute(argv[0]).parent_path();
    options.audition = editor::ui::make_sound_audition();
    auto shell = shell::AppShell::create(*config);
    if (!shell) {
        log::error(shell.error().str());
        return 1;
    }
    int code = 0;
    {
        auto app = editor::ui::EditorApp::create(**shell, options);
        if (!app) {
            log::error(app.error().str());
            code = 1;
        } else {
            code = (*app)->run();
        }
    }
    shell::AppShell::destroy(*shell);
    return code;
}
