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

// Where the logic HUD's pieces sit, in pixels; GL-free so tests check that they never overlap.
struct HudBox {
    float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
    bool empty() const { return !(x1 > x0 && y1 > y0); }
    bool overlaps(const HudBox& o) const {
        return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

// The HUD's own scale (shell/hud.cpp): the bars, the objective list and the message grow and shrink together.
inline float hud_scale(float height) {
    return std::max(0.5f, height / 720.0f);
}

// The health, shield and ammo bars at the top left (shell/hud.cpp: three 360 x 28 bars, 10 apart, from 14,
// 14).
inline HudBox status_bars_box(float s) {
    return {14.0f * s, 14.0f * s, 374.0f * s, (14.0f + 3.0f * 28.0f + 2.0f * 10.0f) * s};
}

// The objective panel at the top right: as wide as its widest text (within 240 px and 42 % of the window),
// a header and `lines` rows (objectives plus the "+N done" / "+N more" lines).
inline HudBox objective_panel_box(float w, float s, float widest_text, int lines) {
    const float widest = std::max(0.0f, widest_text) + 16.0f * s + 12.0f * s * 3.0f;
    const float panel_w = std::clamp(widest, std::min(240.0f * s, w * 0.42f), w * 0.42f);
    return {w - 14.0f * s - panel_w, 14.0f * s, w - 14.0f * s,
            14.0f * s + 30.0f * s + 30.0f * s * static_cast<float>(std::max(0, lines)) + 7.2f * s};
}

// The message line's place: its text's top left, its wrap width and its pill. Upper middle at 17 % of the
// height, pushed below the bars and the objective panel wherever it would cover them; if that pushes it down
// into the "Objective complete" banner's band, it goes into the column between the bars and the panel.
// `measure(wrap)` gives the text's {width, height} wrapped at `wrap`.
struct MessageLayout {
    float text_x = 0.0f, text_y = 0.0f, wrap = 0.0f;
    HudBox box;
};
template <class Measure>
MessageLayout message_layout(float w, float h, float s, const HudBox& panel, Measure measure) {
    const float pad_x = 24.0f * s, pad_y = 11.0f * s, gap = 12.0f * s;
    const HudBox bars = status_bars_box(s);
    auto place = [&](float column_x0, float column_x1, float text_y, float wrap) {
        const auto [tw, th] = measure(wrap);
        MessageLayout l;
        l.wrap = wrap;
        l.text_x = column_x0 + (column_x1 - column_x0 - tw) * 0.5f;
        l.text_y = text_y;
        l.box = {l.text_x - pad_x, text_y - pad_y, l.text_x + tw + pad_x, text_y + th + pad_y};
        return l;
    };
    MessageLayout middle = place(0.0f, w, h * 0.17f, w * 0.6f);
    for (int pass = 0; pass < 2;
         ++pass) // push below whichever it covers; twice, as one push can meet the other
        for (const HudBox* in_the_way : {&bars, &panel})
            if (middle.box.overlaps(*in_the_way))
                middle = place(0.0f, w, in_the_way->y1 + gap + pad_y, w * 0.6f);
    const float banner_top = h * 0.32f - 30.0f * s; // draw_flash's band at its resting size
    if (middle.box.y1 <= banner_top) return middle;
    const float column_x0 = bars.x1 + gap, column_x1 = panel.empty() ? w - gap : panel.x0 - gap;
    const float column_wrap = column_x1 - column_x0 - 2.0f * pad_x;
    if (column_wrap < 160.0f * s) return middle;
    const MessageLayout column = place(column_x0, column_x1, bars.y0 + pad_y, column_wrap);
    return column.box.y1 <= banner_top ? column : middle;
}

// The objective list (top right), the message line and the banner, over the world while playing.
void draw_logic_hud(ImDrawList* draw, const game::Game& game, const ObjectiveFlash& flash,
                    const shell::Fonts& fonts, float width, float height);

} // namespace ks::runtime
