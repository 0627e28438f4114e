// The campaign and the custom level list: Campaign plays the campaign file's levels in order (a win shows the
// summary, the last one the campaign-complete screen; a death offers Retry of the same level); Custom level…
// lists the shipped and the player's levels and plays the one clicked on its own.
#include "game_app_internal.h"

#include "level/campaign.h"

namespace ks::runtime {

void GameApp::open_campaign() {
    if (campaign_save_ && !campaign_save_->won.empty() && !campaign_save_->finished()) {
        open_sub(Screen::CampaignChoice);
        return;
    }
    if (auto started = start_campaign(); !started)
        error_ = "Could not start the campaign: " + started.error().str();
}

Result<void> GameApp::start_campaign(bool resume) {
    const std::filesystem::path file = resume && campaign_save_ ? campaign_save_->campaign : campaign_path_;
    auto campaign = level::load_campaign(file);
    if (!campaign) return campaign.error();
    campaign_.emplace(std::move(*campaign), file);
    if (resume && campaign_save_) campaign_->restore(campaign_save_->won);
    if (!resume) write_save(); // a new run replaces the saved one at once
    error_.clear();
    load(campaign_->current_path(), false, Screen::Playing);
    return {};
}

// The run so far, written atomically; only by a real player's run (a --screenshot run without a script
// leaves the player's saves alone).
void GameApp::write_save() {
    if (!campaign_ || !interactive()) return;
    const std::filesystem::path path = campaign_save_path();
    if (save_unreadable_) { // never overwrite what could not be read: move it aside, once
        save_unreadable_ = false;
        std::filesystem::path aside = path;
        aside += ".unreadable";
        std::error_code ec;
        std::filesystem::rename(path, aside, ec);
        if (ec)
            log::warn(path.string(), ": could not keep the unreadable save as ", aside.string(), ": ",
                      ec.message(), " (campaign progress not saved)");
        else
            log::warn(path.string(), ": the unreadable save is kept as ", aside.string());
        if (ec) return;
    }
    campaign_save_ = save_of(*campaign_);
    if (auto written = write_campaign_save(path, *campaign_save_); !written)
        log::warn(written.error().str(), " (campaign progress not saved)");
}

LevelResult GameApp::result_now() const {
    LevelResult r;
    if (!session_ || !session_->game) return r;
    const game::Game& g = *session_->game;
    r.title = session_->level.name.empty() ? session_->file.stem().string() : session_->level.name;
    r.seconds = session_->play_seconds;
    // Destroyed: shot down, dying included (the game counts a kill once its death clip ends, and a level can
    // be won before that).
    for (const game::Robot& robot : g.robots()) r.robots_killed += robot.alive() ? 0 : 1;
    r.robots_total = static_cast<int>(g.robots().size());
    r.shots = g.player().shots;
    r.hits = g.player().hits;
    r.difficulty = game::difficulty_title(g.settings().difficulty);
    return r;
}

// The level in play was won: the win screen on its own, else the campaign's summary or its end.
void GameApp::level_won() {
    win_ = result_now();
    if (!campaign_) {
        screen_ = Screen::Won;
        return;
    }
    campaign_->record_win(win_);
    write_save();
    screen_ = campaign_->finished() ? Screen::CampaignComplete : Screen::Summary;
}

void GameApp::next_level() {
    if (!campaign_) {
        to_menu();
        return;
    }
    if (campaign_->advance())
        load(campaign_->current_path(), false, Screen::Playing);
    else if (campaign_->finished())
        screen_ = Screen::CampaignComplete;
}

void GameApp::open_custom_levels() {
    custom_levels_ = scan_custom_levels();
    picked_level_ = nullptr;
    open_sub(Screen::CustomLevels);
}

void GameApp::play_custom(const level::LevelFileEntry& entry) {
    campaign_.reset();
    error_.clear();
    // A file that loaded in the list may still fail now (changed on disk since): back to the list with it.
    load(entry.file, false, Screen::Playing, Screen::CustomLevels);
}

Result<void> GameApp::win_at_panel() {
    auto& g = *session_->game;
    // Stand in front of the control panel (trying each side), face it and press E.
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
        return Error("could not win at a control panel in this level", Location(session_->file.string()),
                     "use a level whose control panel wins it (levels/main.json)");
    level_won();
    return {};
}

} // namespace ks::runtime
