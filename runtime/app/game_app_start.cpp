// GameApp::start: the first screen and the scenario the command line asks for (--screen, --warp, --fire,
// --dojo-key, --dojo-time), set up before the first frame for tests and screenshots.
#include "game_app_internal.h"

namespace ks::runtime {

Result<void> GameApp::start(const Automation& a) {
    auto opened = AppAudio::open(a.audio_out);
    if (!opened) return opened.error();
    audio_ = std::move(*opened);
    audio_->apply_options(options_);
    status_path_ = a.status_file;
    script_ = a.script;
    scripted_ = a.scripted;
    // A screenshot without --screen shows the game (what the render-only view used to show, now playable);
    // a scripted screenshot run starts where a player does, at the loading screen.
    const std::string screen =
        a.screen.empty() && shell_.screenshot_mode() && !a.scripted ? "play" : a.screen;
    const bool dojo = a.dojo || screen == "dojo";
    const bool wants_world =
        screen == "play" || screen == "pause" || screen == "death" || screen == "win" || dojo;
    load(dojo ? paths::level("dojo.json") : level_path_, dojo, wants_world ? Screen::Playing : Screen::Menu);
    if (screen == "loading") {
        // Stop half way: the bar shows progress and the label the step in hand.
        for (int i = 0; i < 6; ++i) step_loader();
        freeze_loader_ = true;
        return {};
    }
    if (screen.empty() && !dojo) {
        pending_warp_ = a.warp; // interactive: load across frames with the bar, then warp
        return {};
    }
    if (auto done = finish_loading_now(); !done) return done;
    if (!session_) return Error("loading failed", Location(level_path_.string()));
    auto& g = *session_->game;
    if (a.warp) {
        const auto& v = *a.warp;
        g.teleport_player(Vec3(v[0], v[1], v[2]), radians(v[3]), radians(v[4]));
        // A few steps so the caption and interaction target settle at the new place.
        for (int i = 0; i < 12; ++i) {
            advance({}, static_cast<float>(g.settings().step));
        }
    }
    if (a.fire) {
        game::Input in;
        in.fire = true;
        advance(in, static_cast<float>(g.settings().step));
    }
    if (session_->dojo_controller && a.dojo_key) {
        if (!session_->dojo_controller->press(a.dojo_key)) {
            std::string bound;
            for (const anim::DojoKey& k : session_->dojo_controller->entries())
                if (k.key != 0) bound += (bound.empty() ? "" : ", ") + std::string(1, k.key) + " " + k.clip;
            return Error(std::string("--dojo-key '") + a.dojo_key + "' is not bound", Location("--dojo-key"),
                         "the Dojo's keys: " + bound);
        }
    }
    if (session_->dojo_controller && a.dojo_time >= 0.0) {
        session_->dojo_controller->advance(a.dojo_time);
        freeze_dojo_ = true;
    }
    if (screen == "menu") screen_ = Screen::Menu;
    if (screen == "howto") open_sub(Screen::HowTo);
    if (screen == "credits") open_sub(Screen::Credits);
    if (screen == "options") open_sub(Screen::Options);
    if (screen == "pause") pause();
    if (screen == "death") {
        g.damage_player(1.0e6f);
        // Run the death camera to its end so the menu shows.
        for (int i = 0; i < 1000 && !g.death_camera().menu_ready; ++i) {
            advance({}, static_cast<float>(g.settings().step));
        }
        screen_ = Screen::Dead;
    }
    if (screen == "win") {
        // Win for real: stand in front of the control panel (trying each side), face it and press E.
        for (const auto& panel : g.panels()) {
            for (int side = 0; side < 4 && g.phase() != game::Phase::Won; ++side) {
                const float a = panel.yaw + static_cast<float>(side) * kPi * 0.5f;
                const Vec3 out(-std::sin(a), 0.0f, -std::cos(a)); // yaw 0 faces -z
                const float reach = std::max(panel.size.x, panel.size.z) * 0.5f + 2.0f;
                const Vec3 feet(panel.centre.x + out.x * reach, panel.centre.y - panel.size.y * 0.5f,
                                panel.centre.z + out.z * reach);
                g.teleport_player(feet, a + kPi, -0.3f); // turned round: facing the panel
                for (int i = 0; i < 4 && g.phase() != game::Phase::Won; ++i) {
                    game::Input in;
                    in.interact = i == 3;
                    advance(in, static_cast<float>(g.settings().step));
                }
            }
        }
        if (g.phase() != game::Phase::Won)
            return Error("--screen win: could not reach a control panel in this level",
                         Location(level_path_.string()),
                         "use a level with a control panel (levels/main.json has one)");
        win_ = {session_->play_seconds, g.robots_killed(), static_cast<int>(g.robots().size())};
        screen_ = Screen::Won;
    }
    return {};
}

} // namespace ks::runtime
