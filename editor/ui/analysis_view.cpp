// The Analyze action's state and its panel (analysis_view.h); the viewport drawing is in
// playtest_overlay.cpp.
#include "ui/analysis_view.h"

#include "game/bot_profiles.h"

#include <imgui.h>

#include <cstdio>

namespace ks::editor::ui {

namespace fs = std::filesystem;

void AnalysisView::start(const level::Level& level, const fs::path& level_file) {
    if (job_) job_.reset(); // cancels and waits: a new analysis replaces the running one
    game::AnalysisOptions options;
    options.runs = runs;
    if (new_player) options.bot_profile = std::string(game::kNewPlayerProfile);
    options.level_name = level_file.empty() ? level.name : level_file.filename().string();
    if (auto checked = game::check_analysis_options(options); !checked) {
        log_("analyze: " + checked.error().str(), true);
        return;
    }
    job_ = std::make_unique<game::BackgroundAnalysis>(level, options);
    job_level_file_ = level_file;
    log_("analyzing: " + std::to_string(runs) + " bot runs of " + options.level_name + " on " +
             std::to_string(game::analysis_threads(0, runs)) + " threads",
         false);
}

void AnalysisView::cancel() {
    if (job_) job_->cancel();
}

void AnalysisView::finish() {
    auto result = job_->take_result();
    job_.reset();
    if (!result) {
        log_("analyze: " + result.error().str(), true);
        return;
    }
    if (result->runs.empty()) {
        log_("analysis cancelled before a run finished: the last report stays", false);
        return;
    }
    std::string where = "kept in memory (the level has no file yet)";
    fs::path file;
    if (!job_level_file_.empty()) {
        file = game::playtest_report_path(job_level_file_);
        if (auto saved = game::save_playtest_report(file, *result); !saved) {
            log_("analyze: " + saved.error().str(), true);
            file.clear();
        } else {
            where = "saved to " + file.string();
        }
    }
    log_(std::string(result->cancelled ? "analysis cancelled: " : "analysis done: ") +
             std::to_string(result->wins) + " of " + std::to_string(result->runs.size()) + " runs won; " +
             where,
         false);
    if (job_level_file_ != followed_file_) return; // another level was opened meanwhile: not this one's
    report_ = std::move(*result);
    report_file_ = file;
    checked_revision_ = ~0ull;
}

bool AnalysisView::load(const fs::path& file) {
    auto loaded = game::load_playtest_report(file);
    if (!loaded) {
        log_("play-test report: " + loaded.error().str(), true);
        return false;
    }
    report_ = std::move(*loaded);
    report_file_ = file;
    checked_revision_ = ~0ull;
    return true;
}

void AnalysisView::update(const level::Level& level, std::uint64_t revision, bool continuous,
                          const fs::path& level_file) {
    if (job_ && job_->finished()) finish();
    if (level_file != followed_file_) { // opened, saved as or made new: the report beside it, if any
        followed_file_ = level_file;
        const fs::path beside = level_file.empty() ? fs::path() : game::playtest_report_path(level_file);
        std::error_code ec;
        if (!beside.empty() && fs::exists(beside, ec)) {
            if (report_file_ != beside && load(beside)) log_("play-test report " + beside.string(), false);
        } else if (!report_file_.empty()) { // a report of another file
            report_.reset();
            report_file_.clear();
        }
    }
    if (report_ && revision != checked_revision_ && !continuous) {
        stale_ = game::level_fingerprint(level) != report_->level_hash;
        checked_revision_ = revision;
    }
}

void AnalysisView::numbers() const {
    const game::PlaytestReport& r = *report_;
    const int finished = static_cast<int>(r.runs.size());
    ImGui::TextColored(r.win_rate >= 0.5 ? ImVec4(0.45f, 1.0f, 0.55f, 1) : ImVec4(1.0f, 0.45f, 0.4f, 1),
                       "Won %d of %d (%.0f %%)", r.wins, finished, 100.0 * r.win_rate);
    ImGui::SameLine();
    ImGui::TextDisabled("| died %d | timed out %d%s | bot %s, %s", r.deaths, r.timeouts,
                        r.cancelled ? " | cancelled" : "", r.bot_profile.c_str(),
                        game::difficulty_name(r.difficulty));
    if (const std::string warning = game::new_player_warning(r); !warning.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.78f, 0.25f, 1), "%s", warning.c_str());
    if (r.time_to_win.count > 0)
        ImGui::Text("Time to win: mean %.1f s, median %.1f s (%.1f - %.1f s)", r.time_to_win.mean,
                    r.time_to_win.median, r.time_to_win.min, r.time_to_win.max);
    else
        ImGui::Text("Time to win: no run won (limit %.0f s)", r.seconds_limit);
    ImGui::Text("Damage taken: mean %.0f, median %.0f, max %.0f", r.damage_taken.mean, r.damage_taken.median,
                r.damage_taken.max);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Hit in %zu cells of %g x %g units; died in %zu cells", r.damage_heat.cells.size(),
                          static_cast<double>(r.damage_heat.cell_size),
                          static_cast<double>(r.damage_heat.cell_size), r.death_heat.cells.size());
}

void AnalysisView::panel(const level::Level& level, const fs::path& level_file, UiSpots& spots) {
    if (job_) {
        const bool cancelling = job_->cancelling();
        if (ImGui::Button(cancelling ? "Cancelling..." : "Cancel")) cancel();
        spots.here("analysis_cancel");
        ImGui::SameLine();
        char text[64];
        std::snprintf(text, sizeof text, "%d / %d runs", runs_done(), job_->progress().runs_total());
        ImGui::ProgressBar(progress(), ImVec2(-1, 0), text);
    } else {
        if (ImGui::Button("Analyze")) start(level, level_file);
        spots.here("analysis_start");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The autoplay bot plays this level (as it is now, saved or not) %d times, "
                              "seeds 1..%d, in the background",
                              runs, runs);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90);
        ImGui::DragInt("runs", &runs, 0.2f, 1, 200);
        ImGui::SameLine();
        ImGui::Checkbox("new player", &new_player);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The bot plays like a person new to the game: it reacts, turns and aims as "
                              "people do (docs/game.md, Bot skill profiles)");
        if (report_ && !report_file_.empty()) {
            ImGui::SameLine();
            ImGui::TextDisabled("%s", report_file_.filename().string().c_str());
        }
    }
    if (!report_) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped(
            "No report yet: Analyze has the bot play the level and shows where it took damage, "
            "where it died and the paths it took (from a terminal: killswitch-editor --analyze "
            "LEVEL).");
        ImGui::PopStyleColor();
        return;
    }
    if (stale_) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.78f, 0.25f, 1));
        ImGui::TextWrapped("Stale: the level changed since this report. Analyze again to update it.");
        ImGui::PopStyleColor();
    }
    numbers();
    ImGui::Checkbox("Show on viewport", &overlay);
    spots.here("analysis_overlay");
    // The toggles' labels in the colours they draw with (playtest_overlay.cpp): the legend.
    auto toggle = [](const char* label, bool* value, ImVec4 colour, const char* tip) {
        ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::Checkbox(label, value);
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    };
    toggle("Damage", &heat, ImVec4(1.0f, 0.6f, 0.2f, 1),
           "Cells on the floor where the bot was hit: orange for a little damage, red for the most");
    toggle("Deaths", &deaths, ImVec4(1.0f, 0.3f, 0.3f, 1), "A red cross where the bot died");
    toggle("Paths", &paths, ImVec4(0.4f, 0.8f, 1.0f, 1),
           "The bot's path in each run: blue won, red died, grey ran out of time");
}

} // namespace ks::editor::ui
