#include "runtime/model/hud_presentation.h"

#include <algorithm>

namespace ks::runtime {

void ObjectiveFlash::after_step(const game::Game& game, float dt) {
    time_left_ = std::max(0.0f, time_left_ - std::max(0.0f, dt));
    const auto objectives = game.logic().objectives();
    for (const game::Event& e : game.events()) {
        if (e.type != game::EventType::ObjectiveCompleted) continue;
        const auto index = static_cast<std::size_t>(std::max(0.0f, e.amount));
        text_.assign(index < objectives.size() ? std::string_view(objectives[index].text) : e.cue);
        time_left_ = kSeconds;
    }
}

ObjectiveRows objective_rows(int count, int current) {
    ObjectiveRows rows;
    const int shown = std::min(count, ObjectiveRows::kMaxRows);
    const int anchor = current < 0 ? count - shown : std::max(0, current - 2);
    rows.first = std::clamp(anchor, 0, count - shown);
    rows.end = rows.first + shown;
    rows.hidden_before = rows.first;
    rows.hidden_after = count - rows.end;
    return rows;
}

float message_alpha(const game::ShownMessage& message) {
    if (!message.visible()) return 0.0f;
    const float shown_for = message.duration - message.time_left;
    return std::clamp(std::min(shown_for / 0.2f, message.time_left / 0.5f), 0.0f, 1.0f);
}

float hud_scale(float height) {
    return std::max(0.5f, height / 720.0f);
}

HudBox status_bars_box(float s) {
    return {14.0f * s, 14.0f * s, 374.0f * s, (14.0f + 3.0f * 28.0f + 2.0f * 10.0f) * s};
}

HudBox objective_panel_box(float w, float s, float widest_text, int lines) {
    const float widest = std::max(0.0f, widest_text) + 16.0f * s + 12.0f * s * 3.0f;
    const float panel_w = std::clamp(widest, std::min(240.0f * s, w * 0.42f), w * 0.42f);
    return {w - 14.0f * s - panel_w, 14.0f * s, w - 14.0f * s,
            14.0f * s + 30.0f * s + 30.0f * s * static_cast<float>(std::max(0, lines)) + 7.2f * s};
}

MessageLayout message_layout(float w, float h, float s, const HudBox& panel, const MeasureText& measure) {
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

} // namespace ks::runtime
