// GameApp::start: the first screen and the scenario the command line asks for (--screen, --campaign, --warp,
// --fire, --dojo-key, --dojo-time), set up before the first frame for tests and screenshots.
#include "game_app_internal.h"

namespace ks::runtime {

namespace {
// The screens --screen reaches by winning the campaign's levels.
bool campaign_screen(std::optional<Screen> screen) {
    return screen == Screen::Summary || screen == Screen::CampaignComplete;
}
// The screens --screen shows over a level being played (the Dojo is one too).
bool world_screen(std::optional<Screen> screen) {
    return screen == Screen::Playing || screen == Screen::Paused || screen == Screen::Dead ||
           screen == Screen::Won || campaign_screen(screen);
}
// "--screen win: ..." for an error met while setting up that screen.
Error screen_error(Screen screen, const Error& e) {
    return Error("--screen " + std::string(command_line_name(screen)) + ": " + e.message, e.where, e.hint);
}
} // namespace

Result<void> GameApp::start(const Automation& a) {
    auto opened = AppAudio::open(a.audio_out);
    if (!opened) return opened.error();
    audio_ = std::move(*opened);
    audio_->apply_options(options_);
    status_path_ = a.status_file;
    scale_control_.configure(!shell_.screenshot_mode() || a.target_fps, a.target_fps.value_or(60.0));
    apply_render_options();
    logic_debug_.configure(a.logic_trace, a.logic_break);
    if (a.logic_break) logic_debug_visible_ = true;
    if (a.difficulty) options_.difficulty = *a.difficulty;
    script_ = a.script;
    scripted_ = a.scripted;
    // A scripted run reads no real pad (a controller on the desk must not disturb a test): only the script's.
    if (scripted_) shell_.inject_gamepad(shell::GamepadState{});
    campaign_path_ = a.campaign.empty() ? paths::level("campaign.json") : a.campaign;
    // A screenshot without --screen shows the game (what the render-only view used to show, now playable);
    // a scripted screenshot run starts where a player does, at the loading screen.
    const std::optional<Screen> screen =
        !a.screen && shell_.screenshot_mode() && !a.scripted ? Screen::Playing : a.screen;
    const bool dojo = a.dojo;
    if (!dojo && (a.start_campaign || campaign_screen(screen))) {
        auto campaign = level::load_campaign(campaign_path_);
        if (!campaign) return campaign.error();
        campaign_.emplace(std::move(*campaign), campaign_path_);
    }
    const bool wants_world = world_screen(screen) || dojo || (a.start_campaign && !screen);
    const std::filesystem::path first = dojo        ? paths::level("dojo.json")
                                        : campaign_ ? campaign_->current_path()
                                                    : level_path_;
    load(first, dojo, wants_world ? Screen::Playing : Screen::Menu);
    if (screen == Screen::Loading) {
        // Stop half way: the bar shows progress and the label the step in hand.
        for (int i = 0; i < 6; ++i) step_loader();
        freeze_loader_ = true;
        return {};
    }
    if (!screen && !dojo) {
        pending_warp_ = a.warp; // interactive: load across frames with the bar, then warp
        return {};
    }
    if (auto done = finish_loading_now(); !done) return done;
    if (!session_) return Error("loading failed", Location(first.string()));
    return set_up_scenario(a, screen);
}

// After the first level has loaded: the player's place and shot, the Dojo's clip, then the screen asked for.
Result<void> GameApp::set_up_scenario(const Automation& a, std::optional<Screen> screen) {
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
    switch (screen.value_or(Screen::Playing)) {
    case Screen::Menu:
        screen_ = Screen::Menu;
        break;
    case Screen::HowTo:
    case Screen::Credits:
    case Screen::Options:
        open_sub(*screen);
        break;
    case Screen::Controls:
        open_sub(Screen::Options);
        screen_ = Screen::Controls; // Back returns to Options
        break;
    case Screen::CustomLevels:
        open_custom_levels();
        break;
    case Screen::CampaignChoice:
        if (!campaign_save_ || campaign_save_->won.empty() || campaign_save_->finished())
            return screen_error(*screen, Error("no campaign run in progress is saved",
                                               Location(campaign_save_path().string()),
                                               "win a campaign level first, or set XDG_DATA_HOME to a "
                                               "folder with a save"));
        open_sub(Screen::CampaignChoice);
        break;
    case Screen::Paused:
        pause();
        break;
    case Screen::Dead:
        g.damage_player(1.0e6f);
        // Run the death camera to its end so the menu shows.
        for (int i = 0; i < 1000 && !g.death_camera().menu_ready; ++i) {
            advance({}, static_cast<float>(g.settings().step));
        }
        screen_ = Screen::Dead;
        break;
    case Screen::Won:
    case Screen::Summary:
    case Screen::CampaignComplete:
        // Win for real, at the control panel; the campaign-complete screen wins every level in turn.
        if (auto won = win_at_panel(); !won) return screen_error(*screen, won.error());
        while (screen == Screen::CampaignComplete && campaign_ && !campaign_->finished()) {
            next_level();
            if (auto done = finish_loading_now(); !done) return done;
            if (auto won = win_at_panel(); !won) return screen_error(*screen, won.error());
        }
        if (screen == Screen::Summary) screen_ = Screen::Summary; // also for a campaign of one level
        break;
    case Screen::Loading: // stopped before the level loaded (start)
    case Screen::Playing:
        break;
    }
    // A menu's buttons take the mouse (a scripted run captured it when the level started).
    if (screen_ != Screen::Playing) input_.release(shell_.window(), events_.state());
    return {};
}

} // namespace ks::runtime
