// The live play-test in the game (runtime/model/live_edits.h): once a frame the editor's level updates are
// read; one that builds replaces the session's level, game, view and sounds with the running state carried
// over (game/live_update.h); what happened shows as a toast for a few seconds and goes to the log (the
// editor's play-test log shows it too). The pause menu's "Back to editor" says goodbye and closes the game.
#include "game_app_internal.h"

#include <chrono>

namespace ks::runtime {
namespace {
constexpr double kToastSeconds = 4.0;
}

void GameApp::start_live() {
    live_ = LiveEdits::from_environment();
    if (live_) log::info("live play-test: this game takes the editor's edits as they are made");
}

void GameApp::poll_live() {
    if (!live_ || !session_ || !session_->game || session_->dojo || screen_ == Screen::Loading) return;
    const double now = glfwGetTime();
    game::GameOptions options;
    options.seed = seed_;
    options.settings.difficulty = options_.difficulty;
    const auto started = std::chrono::steady_clock::now();
    auto edit = live_->poll(now, *session_->game, session_->level, options);
    const auto rebuilt = std::chrono::steady_clock::now();
    for (const auto& note : live_->notes()) {
        if (note.error)
            log::warn(note.text);
        else
            log::info(note.text);
        live_toast_ = note;
        live_toast_until_ = now + kToastSeconds;
    }
    if (!edit) return;
    Session& s = *session_;
    s.level = std::move(edit->level);
    s.game = std::move(edit->rebuild.game);
    if (edit->scenery_changed || !s.view) {
        // The edit shows at once; its light map (the fast path's) follows from a worker thread.
        auto scene_options = render::level_scene_options(renderer_.settings());
        scene_options.defer_bake = scene_options.bake_light_map;
        s.view = WorldView::build(s.level, *s.game, assets_, scene_options);
    } else {
        s.view->follow_game(*s.game);
    }
    if (audio_) s.sounds = std::make_unique<soundscape::Soundscape>(audio_->engine(), s.level);
    logic_debug_.start(s.level, *s.game);
    auto ms = [](auto from, auto to) { return std::chrono::duration<double, std::milli>(to - from).count(); };
    log::info("live edit: the game rebuilt in ", ms(started, rebuilt), " ms, the view ",
              edit->scenery_changed ? "rebuilt" : "kept its scene", " in ",
              ms(rebuilt, std::chrono::steady_clock::now()), " ms");
}

void GameApp::draw_live_toast(float w) {
    if (!live_ || live_toast_.text.empty() || glfwGetTime() > live_toast_until_) return;
    const ImU32 colour = live_toast_.error ? IM_COL32(255, 120, 110, 255) : IM_COL32(150, 230, 150, 255);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 size = ImGui::CalcTextSize(live_toast_.text.c_str());
    const ImVec2 at(std::max(10.0f, (w - size.x) * 0.5f), 12.0f);
    draw->AddRectFilled(ImVec2(at.x - 8, at.y - 4), ImVec2(at.x + size.x + 8, at.y + size.y + 4),
                        IM_COL32(0, 0, 0, 170), 4.0f);
    draw->AddText(at, colour, live_toast_.text.c_str());
}

void GameApp::back_to_editor() {
    if (live_) live_->say_bye();
    quit_ = true;
}

} // namespace ks::runtime
