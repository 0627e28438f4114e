#include "hud_feedback.h"

#include "menu_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ks::runtime {

namespace {
ImU32 with_alpha(int r, int g, int b, float alpha) {
    return IM_COL32(r, g, b, static_cast<int>(std::clamp(alpha, 0.0f, 1.0f) * 255.0f));
}
// The point at `radius` from `c` in the direction `angle` (clockwise from up, screen y down).
ImVec2 on_ring(ImVec2 c, float radius, float angle) {
    return ImVec2(c.x + radius * std::sin(angle), c.y - radius * std::cos(angle));
}
} // namespace

void draw_hit_marker(ImDrawList* d, float strength, float w, float h) {
    if (!(strength > 0.0f)) return;
    const float k = std::clamp(strength, 0.0f, 1.0f);
    const float s = ui::ui_scale(w, h);
    const ImVec2 c(w * 0.5f, h * 0.5f);
    const float pop = 1.0f + 0.25f * k * k; // starts larger, settles as it fades
    const float r0 = 8.0f * s * pop, r1 = 18.0f * s * pop;
    for (int pass = 0; pass < 2; ++pass) {
        const ImU32 colour = pass == 0 ? with_alpha(0, 0, 0, 0.6f * k) : with_alpha(255, 255, 255, k);
        const float width = (pass == 0 ? 5.0f : 3.0f) * s;
        for (int i = 0; i < 4; ++i) {
            const float angle = kPi * (0.25f + 0.5f * static_cast<float>(i));
            d->AddLine(on_ring(c, r0, angle), on_ring(c, r1, angle), colour, width);
        }
    }
}

void draw_damage_arcs(ImDrawList* d, std::span<const feedback::DamageArc> arcs, float w, float h) {
    const float s = ui::ui_scale(w, h);
    const ImVec2 c(w * 0.5f, h * 0.5f);
    const float radius = 95.0f * s, half_span = 0.42f, thickness = 12.0f * s;
    for (const feedback::DamageArc& arc : arcs) {
        const float k = std::clamp(arc.strength, 0.0f, 1.0f);
        if (!(k > 0.0f) || !std::isfinite(arc.angle)) continue;
        // ImGui measures angles from +x, clockwise on screen; ours from up.
        const float a0 = arc.angle - half_span - kPi * 0.5f, a1 = arc.angle + half_span - kPi * 0.5f;
        d->PathArcTo(c, radius, a0, a1, 24);
        d->PathStroke(with_alpha(20, 0, 0, 0.55f * k), 0, thickness + 4.0f * s);
        d->PathArcTo(c, radius, a0, a1, 24);
        d->PathStroke(with_alpha(235, 30, 20, 0.9f * k), 0, thickness);
        // A notch just outside the arc's middle, pointing at the source.
        const ImVec2 tip = on_ring(c, radius + thickness * 0.5f + 16.0f * s, arc.angle);
        const ImVec2 left = on_ring(c, radius + thickness * 0.5f, arc.angle - 0.11f);
        const ImVec2 right = on_ring(c, radius + thickness * 0.5f, arc.angle + 0.11f);
        d->AddTriangleFilled(left, tip, right, with_alpha(235, 30, 20, 0.9f * k));
    }
}

} // namespace ks::runtime
