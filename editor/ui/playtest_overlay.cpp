// The play-test report over a view of the level (analysis_view.h): damage cells on the floor where the bot
// was hit (orange for a little, red for the most, faded when the report is stale), its paths (a thin line per
// run: blue won, red died, grey timed out) and a red cross where it died. Drawn on screen over the picture,
// so it shows through walls in the perspective view, as a heat map should.
#include "ui/analysis_view.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

namespace {
constexpr float kLift = 0.05f; // above the floor the cell lies on
constexpr float kPathLift = 0.4f;

ImU32 heat_colour(float t, float alpha) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float r = 1.0f - 0.12f * t, g = 0.66f * (1.0f - t) + 0.1f * t, b = 0.12f * (1.0f - t);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, alpha));
}

ImU32 path_colour(game::RunOutcome outcome, float alpha) {
    switch (outcome) {
    case game::RunOutcome::Win:
        return ImGui::ColorConvertFloat4ToU32(ImVec4(0.35f, 0.8f, 1.0f, alpha));
    case game::RunOutcome::Death:
        return ImGui::ColorConvertFloat4ToU32(ImVec4(1.0f, 0.35f, 0.35f, alpha));
    case game::RunOutcome::Timeout:
        break;
    }
    return ImGui::ColorConvertFloat4ToU32(ImVec4(0.8f, 0.8f, 0.85f, alpha));
}

struct Projector {
    const ViewCamera& view;
    Vec2 origin;
    bool operator()(const Vec3& p, ImVec2& out) const {
        Vec2 s;
        if (!view.project(p, s)) return false;
        out = ImVec2(origin.x + s.x, origin.y + s.y);
        return true;
    }
};

// The cells of `grid` as quads on the floor, inset a little so neighbours read as cells.
void draw_cells(ImDrawList* draw, const Projector& screen, const game::HeatGrid& grid, float alpha,
                bool outline_only) {
    const float max_value = std::max(grid.max_value(), 1e-6f);
    const float inset = grid.cell_size * 0.06f;
    for (const game::HeatCell& cell : grid.cells) {
        const float x0 = grid.origin_x + static_cast<float>(cell.column) * grid.cell_size + inset;
        const float z0 = grid.origin_z + static_cast<float>(cell.row) * grid.cell_size + inset;
        const float x1 = x0 + grid.cell_size - 2.0f * inset, z1 = z0 + grid.cell_size - 2.0f * inset;
        const float y = cell.y + kLift;
        ImVec2 q[4];
        if (!screen(Vec3(x0, y, z0), q[0]) || !screen(Vec3(x1, y, z0), q[1]) ||
            !screen(Vec3(x1, y, z1), q[2]) || !screen(Vec3(x0, y, z1), q[3]))
            continue;
        const float t = cell.value / max_value;
        if (outline_only) {
            draw->AddQuad(q[0], q[1], q[2], q[3], IM_COL32(255, 40, 40, static_cast<int>(230 * alpha)), 2.0f);
            continue;
        }
        draw->AddQuadFilled(q[0], q[1], q[2], q[3], heat_colour(t, (0.45f + 0.4f * t) * alpha));
        draw->AddQuad(q[0], q[1], q[2], q[3], heat_colour(t, 0.95f * alpha), 1.5f);
        // The damage beside the cell, on a dark tab, so a small cell far away still reads.
        char text[16];
        std::snprintf(text, sizeof text, "%.0f", static_cast<double>(cell.value));
        const ImVec2 extent = ImGui::CalcTextSize(text);
        const ImVec2 at(std::max({q[0].x, q[1].x, q[2].x, q[3].x}) + 3.0f,
                        std::min({q[0].y, q[1].y, q[2].y, q[3].y}) - extent.y * 0.5f);
        draw->AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + extent.x + 2, at.y + extent.y + 1),
                            IM_COL32(15, 17, 22, static_cast<int>(170 * alpha)), 3.0f);
        draw->AddText(at, heat_colour(t, alpha), text);
    }
}

void draw_cross(ImDrawList* draw, ImVec2 at, float alpha) {
    const float r = 6.0f;
    const ImU32 shadow = IM_COL32(0, 0, 0, static_cast<int>(190 * alpha));
    const ImU32 red = IM_COL32(255, 45, 45, static_cast<int>(255 * alpha));
    for (const auto& [colour, width] : {std::pair{shadow, 5.0f}, std::pair{red, 2.5f}}) {
        draw->AddLine(ImVec2(at.x - r, at.y - r), ImVec2(at.x + r, at.y + r), colour, width);
        draw->AddLine(ImVec2(at.x - r, at.y + r), ImVec2(at.x + r, at.y - r), colour, width);
    }
    draw->AddCircle(at, r + 3.0f, red, 16, 1.5f);
}
} // namespace

void AnalysisView::draw(ImDrawList* draw, const ViewCamera& view, Vec2 origin) const {
    if (!report_ || !overlay) return;
    const Vec2 size = view.viewport();
    draw->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    const Projector screen{view, origin};
    const float alpha = stale_ ? 0.5f : 1.0f;
    if (heat) draw_cells(draw, screen, report_->damage_heat, alpha, false);
    if (paths)
        for (const game::RunRecord& run : report_->runs) {
            const ImU32 colour = path_colour(run.outcome, 0.6f * alpha);
            ImVec2 previous;
            bool have_previous = false;
            for (const Vec3& p : run.path) {
                ImVec2 at;
                if (!screen(p + Vec3(0.0f, kPathLift, 0.0f), at)) {
                    have_previous = false;
                    continue;
                }
                if (have_previous) {
                    const float dx = at.x - previous.x, dy = at.y - previous.y;
                    if (dx * dx + dy * dy < 2.0f) continue; // standing still, or too far to tell apart
                    draw->AddLine(previous, at, colour, 1.5f);
                }
                previous = at;
                have_previous = true;
            }
        }
    if (deaths) {
        draw_cells(draw, screen, report_->death_heat, alpha, true);
        for (const game::RunRecord& run : report_->runs) {
            ImVec2 at;
            if (run.death && screen(*run.death + Vec3(0.0f, kPathLift, 0.0f), at))
                draw_cross(draw, at, alpha);
        }
        for (const game::HeatCell& cell : report_->death_heat.cells) {
            if (cell.value < 2.0f) continue;
            const game::HeatGrid& g = report_->death_heat;
            const Vec3 corner(g.origin_x + static_cast<float>(cell.column + 1) * g.cell_size, cell.y + kLift,
                              g.origin_z + static_cast<float>(cell.row) * g.cell_size);
            ImVec2 at;
            if (!screen(corner, at)) continue;
            char text[16];
            std::snprintf(text, sizeof text, "x%.0f", static_cast<double>(cell.value));
            draw->AddText(ImVec2(at.x + 2, at.y - 14), IM_COL32(255, 90, 90, static_cast<int>(255 * alpha)),
                          text);
        }
    }
    draw->PopClipRect();
}

} // namespace ks::editor::ui
