#pragma once
// What the HUD shows of the level's logic (game/level_logic.h) and where, without a window: the "Objective
// complete" banner's timer, the objective rows to show, the message line's fade, and the places of the bars,
// the objective panel and the message line (which never overlap). runtime/app/logic_hud.cpp draws them.
#include "game/game.h"

#include <algorithm>
#include <functional>
#include <string>
#include <utility>

namespace ks::runtime {

// The "Objective complete" banner: set by an ObjectiveCompleted event, shown for kSeconds, fading out at the
// end. Advanced by game steps, so a paused game holds it and scripted runs are deterministic.
class ObjectiveFlash {
  public:
    static constexpr float kSeconds = 2.5f;
    static constexpr float kFadeSeconds = 0.6f;

    // After each game step: counts down and picks up the step's completed objective (the last, if several).
    void after_step(const game::Game& game, float dt);
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
ObjectiveRows objective_rows(int count, int current);

// The message line's opacity: in over 0.2 s, out over the last 0.5 s of its time on screen.
float message_alpha(const game::ShownMessage& message);

// Where the logic HUD's pieces sit, in pixels; GL-free so tests check that they never overlap.
struct HudBox {
    float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
    bool empty() const { return !(x1 > x0 && y1 > y0); }
    bool overlaps(const HudBox& o) const {
        return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

// The HUD's own scale (shell/hud.cpp): the bars, the objective list and the message grow and shrink together.
float hud_scale(float height);

// The health, shield and ammo bars at the top left (shell/hud.cpp: three 360 x 28 bars, 10 apart, from 14,
// 14).
HudBox status_bars_box(float s);

// The objective panel at the top right: as wide as its widest text (within 240 px and 42 % of the window),
// a header and `lines` rows (objectives plus the "+N done" / "+N more" lines).
HudBox objective_panel_box(float w, float s, float widest_text, int lines);

// The message line's place: its text's top left, its wrap width and its pill. Upper middle at 17 % of the
// height, pushed below the bars and the objective panel wherever it would cover them; if that pushes it down
// into the "Objective complete" banner's band, it goes into the column between the bars and the panel.
struct MessageLayout {
    float text_x = 0.0f, text_y = 0.0f, wrap = 0.0f;
    HudBox box;
};
// The text's {width, height} wrapped at a width.
using MeasureText = std::function<std::pair<float, float>(float wrap)>;
MessageLayout message_layout(float w, float h, float s, const HudBox& panel, const MeasureText& measure);

} // namespace ks::runtime
