#pragma once
// What the HUD shows of the level's logic (game/level_logic.h): the objective list (the current objective
// highlighted, completed ones ticked), the message line (a message entity's text while it lasts) and a brief
// "Objective complete" banner when one completes. The banner's timer and the rows to show are GL-free and
// header-only so tests read them directly; draw_logic_hud (logic_hud.cpp) draws them with ImGui.
#include "game/game.h"

#include <algorithm>
#include <string>

struct ImDrawList;

namespace ks::shell {
struct Fonts;
}

namespace ks::runtime {

// The "Objective complete" banner: set by an ObjectiveCompleted event, shown for kSeconds, fading out at the
// end. Advanced by game steps, so a paused game holds it and scripted runs are deterministic.
class ObjectiveFlash {
  public:
    static constexpr float kSeconds = 2.5f;
    static constexpr float kFadeSeconds = 0.6f;

    // After each game step: counts down and picks up the step's completed objective (the last, if several).
    void after_step(const game::Game& game, float dt) {
        time_left_ = std::max(0.0f, time_left_ - std::max(0.0f, dt));
        const auto objectives = game.logic().objectives();
        for (const game::Event& e : game.events()) {
            if (e.type != game::EventType::ObjectiveCompleted) continue;
            const auto index = static_cast<std::size_t>(std::max(0.0f, e.amount));
            text_.assign(index < objectives.size() ? std::string_view(objectives[index].text) : e.cue);
            time_left_ = kSeconds;
        }
    }
    bool visible() const { return time_left_ > 0.0f; }
    // 0..1: full while fresh, fading over the last kFadeSeconds.
    float strength() const { return std::clamp(time_left_ / kFadeSeconds, 0.0f, 1.0f); }
    // 0..1: how far into its showing the banner is (its entrance pops in over the first tenth).
    float age() const { return 1.0f - std::clamp(time_left_ / kSeconds, 0.0f, 1.0f); }
    const std::string& text() const { return text_; } // the completed objective's text

  private:
    float time_left_ = 0.0f;
    std::string text_; // keeps its capacity: no allocation per step
};

// The rows of the objective list: at most kMaxRows around the current objective (two completed ones before
// it, then the rest), or the last ones once all are complete.
struct ObjectiveRows {
    static constexpr int kMaxRows = 6;
    int first = 0, end = 0; // [first, end) of game.logic().objectives()
    int hidden_before = 0, hidden_after = 0;
};
inline ObjectiveRows objective_rows(int count, int current) {
    ObjectiveRows rows;
    const int shown = std::min(count, ObjectiveRows::kMaxRows);
    const int anchor = current < 0 ? count - shown : std::max(0, current - 2);
    rows.first = std::clamp(anchor, 0, count - shown);
    rows.end = rows.first + shown;
    rows.hidden_before = rows.first;
    rows.hidden_after = count - rows.end;
    return rows;
}

// The message line's opacity: in over 0.2 s, out over the last 0.5 s of its time on screen.
inline float message_alpha(const game::ShownMessage& message) {
    if (!message.visible()) return 0.0f;
    const float shown_for = message.duration - message.time_left;
    return std::clamp(std::min(shown_for / 0.2f, message.time_left / 0.5f), 0.0f, 1.0f);
}

// The objective list (top right), the message line and the banner, over the world while playing.
void draw_logic_hud(ImDrawList* draw, const game::Game& game, const ObjectiveFlash& flash,
                    const shell::Fonts& fonts, float width, float height);

} // namespace ks::runtime
