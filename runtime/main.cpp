// killswitch: the game runtime. Routes to the playable game (runtime/app: menus, game, Dojo), to the headless
// runner (--headless), or to the render-only views (--view, --camera: runtime/views/render_view.h).
#include "app/game_app.h"
#include "core/cli.h"
#include "core/log.h"
#include "core/startup_trace.h"
#include "core/version.h"
#include "game/headless.h"
#include "game/headless_campaign.h"
#include "shell/app_shell.h"
#include "soundscape/mix_recorder.h"
#include "views/render_view.h"

#include <cstdio>

namespace {
const std::vector<std::string> kFlags = {"no-vsync", "help", "no-hud", "effects", "version"};

void print_headless_help() {
    std::printf(
        "usage: killswitch --headless [--level FILE] [--seconds S] [--seed N] [--autoplay]\n"
        "                  [--record FILE | --replay FILE] [--stats-json FILE|-] [--audio-out FILE.wav]\n"
        "                  [--logic-trace FILE|-] [--difficulty easy|normal|hard]\n"
        "                  [--bot-profile perfect|experienced|new-player]\n"
        "  runs the game without a window at a fixed 120 Hz step, as fast as the CPU allows\n"
        "  --level FILE      the level to play (default levels/main.json)\n"
        "  --seconds S       simulated time limit (default 300)\n"
        "  --seed N          the game's random seed (default 1)\n"
        "  --autoplay        a bot plays (walks the level, fights, reaches the control panel)\n"
        "  --record FILE     save every step's input (replays bit-exactly)\n"
        "  --replay FILE     play a recording back with its recorded seed and difficulty\n"
        "  --difficulty D    the robots' aim time, hit chance and damage: easy, normal (default), hard\n"
        "  --bot-profile P   who the bot plays like (with --autoplay): perfect (default), experienced,\n"
        "                    new-player (docs/game.md, \"Bot skill profiles\")\n"
        "  --stats-json F    write the outcome, time, kills, damage and state hash as JSON (- = stdout)\n"
        "  --audio-out F.wav render the run's sound (heard at the player) to a 48 kHz stereo WAV, plus\n"
        "                    2 s after the end; the same run writes the same file\n"
        "  --logic-trace F   write every level-logic event and action, a line each with its step (- = "
        "stdout;\n"
        "                    format in docs/game.md, \"Logic trace\")\n"
        "exit code 0 when the run completed (whatever its outcome), 2 on bad options or a bad level\n"
        "\n"
        "usage: killswitch --headless --campaign FILE [--seed N] [--seconds S]\n"
        "  the bot plays every level of the campaign in order (each with the seed and time limit) and stops\n"
        "  at the first level it does not win; one line per level, then the campaign's\n"
        "exit code 0 when every level was won, 1 naming the level lost, 2 on bad options or a bad file\n");
}

// --headless --campaign: every level in order with the bot (CI proves the campaign can be won).
int run_campaign(const ks::CommandLine& cl) {
    using namespace ks;
    if (auto unknown = cl.unknown(game::campaign_run_option_names()); !unknown.empty()) {
        log::error("unknown option ", unknown.front(),
                   " for --headless --campaign (see killswitch --headless --help)");
        return 2;
    }
    auto options = game::parse_campaign_run_options(cl);
    if (!options) {
        log::error(options.error().str());
        return 2;
    }
    auto result = game::run_headless_campaign(*options, [](const game::CampaignLevelRun& run) {
        std::printf("%s\n", run.summary().c_str());
        std::fflush(stdout);
    });
    if (!result) {
        log::error(result.error().str());
        return 2;
    }
    std::printf("%s\n", result->summary().c_str());
    return result->won() ? 0 : 1;
}

// --audio-out with --headless: a loopback mix of the run, heard at the player, then a 2 s tail.
using namespace ks;

void record_audio(game::HeadlessOptions& options, const std::filesystem::path& wav,
                  std::unique_ptr<soundscape::MixRecorder>& recorder) {
    options.on_start = [&recorder, wav](const level::Level& level, const game::Game&) -> Result<void> {
        auto opened = soundscape::MixRecorder::open(wav, level);
        if (!opened) return opened.error();
        recorder = std::move(*opened);
        return {};
    };
    options.after_step = [&recorder](const game::Game& g) { return recorder->after_step(g); };
    options.on_finish = [&recorder](const game::Game& g) -> Result<void> {
        for (int i = 0; i < 240; ++i)
            if (auto r = recorder->render(g, soundscape::player_listener(g), g.settings().step); !r) return r;
        return recorder->finish();
    };
}

} // namespace

int main(int argc, char** argv) {
    using namespace ks;
    startup::mark("main");
    std::vector<std::string> flags = kFlags;
    flags.insert(flags.end(), runtime::game_app_flags().begin(), runtime::game_app_flags().end());
    flags.insert(flags.end(), game::headless_flags().begin(), game::headless_flags().end());
    auto cl = CommandLine::parse(argc, argv, flags);
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    if (cl->has("version")) {
        std::printf("%s\n", version::line("killswitch").c_str());
        return 0;
    }
    // Routing: --headless → the game without a window; --view / --camera → the renderer's turntable and
    // render-only views (below); anything else → the playable game (menus, game, Dojo).
    if (cl->has("headless")) {
        if (cl->has("help")) {
            print_headless_help();
            return 0;
        }
        if (cl->has("campaign")) return run_campaign(*cl);
        std::vector<std::string> headless_known = game::headless_option_names();
        headless_known.push_back("audio-out");
        if (auto unknown = cl->unknown(headless_known); !unknown.empty()) {
            log::error("unknown option ", unknown.front(), " for --headless (see common/game/headless.h)");
            return 2;
        }
        auto options = game::parse_headless_options(*cl);
        if (!options) {
            log::error(options.error().str());
            return 2;
        }
        std::unique_ptr<soundscape::MixRecorder> recorder;
        if (auto wav = cl->get("audio-out")) {
            if (wav->empty()) {
                log::error("--audio-out: give a file name, e.g. --audio-out run.wav");
                return 2;
            }
            record_audio(*options, *wav, recorder);
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
    return runtime::run_render_view(*cl);
}
