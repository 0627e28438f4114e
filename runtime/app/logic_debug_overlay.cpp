#include "logic_debug_overlay.h"

#include "core/log.h"
#include "shell/app_shell.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::runtime {
namespace {

constexpr ImU32 kEventColour = IM_COL32(255, 196, 60, 255);
constexpr ImU32 kActionColour = IM_COL32(80, 220, 255, 255);

ImU32 faded(ImU32 colour, float alpha) {
    const auto a = static_cast<ImU32>(std::clamp(alpha, 0.0f, 1.0f) * 255.0f);
    return (colour & ~IM_COL32_A_MASK) | (a << IM_COL32_A_SHIFT);
}

// The segment a..b on screen, clipped to the part in front of the camera; false when none is.
bool project_segment(const Mat4& view_projection, Vec3 a, Vec3 b, float width, float height, ImVec2& sa,
                     ImVec2& sb) {
    constexpr float kNear = 0.05f;
    Vec4 ca = view_projection * Vec4(a, 1.0f), cb = view_projection * Vec4(b, 1.0f);
    if (ca.w < kNear && cb.w < kNear) return false;
    if (ca.w < kNear) ca = ca + (cb - ca) * ((kNear - ca.w) / (cb.w - ca.w));
    if (cb.w < kNear) cb = cb + (ca - cb) * ((kNear - cb.w) / (ca.w - cb.w));
    auto screen = [&](const Vec4& c) {
        return ImVec2((c.x / c.w * 0.5f + 0.5f) * width, (0.5f - c.y / c.w * 0.5f) * height);
    };
    sa = screen(ca);
    sb = screen(cb);
    return true;
}

} // namespace

void LogicDebugOverlay::configure(std::filesystem::path trace, std::optional<LogicBreak> break_point) {
    trace_path_ = std::move(trace);
    debugger_.set_break(break_point);
}

void LogicDebugOverlay::start(const level::Level& level, const game::Game& game) {
    debugger_.reset(level, game.settings().step);
    trace_.reset();
    if (trace_path_.empty()) return;
    auto opened = game::LogicTraceWriter::open(trace_path_, level, game.settings().step);
    if (!opened) {
        log::error(opened.error().str());
        return;
    }
    trace_.emplace(std::move(*opened));
}

void LogicDebugOverlay::after_step(const game::Game& game) {
    debugger_.after_step(game);
    if (!trace_) return;
    if (auto written = trace_->write(game); !written) {
        log::error(written.error().str());
        trace_.reset(); // said once; the game goes on
    }
}

bool LogicDebugOverlay::handle_keys(InputState& keys, bool& visible) {
    const bool toggled = keys.take_press(GLFW_KEY_F3);
    if (toggled) visible = !visible;
    if (!visible) {
        if (debugger_.halted()) debugger_.resume(); // hidden, it never holds the game
        return toggled;
    }
    if (keys.take_press(GLFW_KEY_F6)) debugger_.halted() ? debugger_.resume() : debugger_.halt();
    if (keys.take_press(GLFW_KEY_F7)) debugger_.step_once();
    if (keys.take_press(GLFW_KEY_F8)) {
        const auto& entries = debugger_.entries();
        const auto newest = std::find_if(entries.rbegin(), entries.rend(),
                                         [](const LogicLogEntry& e) { return !e.record.is_action; });
        if (debugger_.break_point() || newest == entries.rend())
            debugger_.set_break(std::nullopt);
        else
            debugger_.set_break(LogicBreak::at(newest->record));
    }
    return toggled;
}

void LogicDebugOverlay::draw(ImDrawList* draw, const game::Game& game, const geometry::Camera& camera,
                             const shell::Fonts& fonts, float width, float height) {
    draw_lines(draw, game, camera, width, height);
    draw_panel(game, fonts, width, height);
}

void LogicDebugOverlay::draw_lines(ImDrawList* draw, const game::Game& game, const geometry::Camera& camera,
                                   float width, float height) const {
    const Mat4 view_projection = camera.view_projection();
    for (const LogicLogEntry& e : debugger_.entries()) {
        const std::int64_t age = game.steps() - e.record.step;
        if (age < 0 || age > LogicDebugger::kLineSteps) continue;
        const float alpha = 1.0f - static_cast<float>(age) / static_cast<float>(LogicDebugger::kLineSteps);
        const Vec3 from = debugger_.place(e.record.source, game);
        const std::string_view what =
            e.record.is_action ? level::action_name(e.record.action) : level::event_name(e.record.event);
        const Vec3 to = e.record.is_action ? debugger_.place(e.record.target, game) : from;
        ImVec2 a, b;
        if (!project_segment(view_projection, from, to, width, height, a, b)) continue;
        const ImU32 colour = faded(e.record.is_action ? kActionColour : kEventColour, alpha);
        if (e.record.is_action) {
            draw->AddLine(a, b, colour, 3.0f);
            draw->AddCircleFilled(b, 6.0f, colour);
            draw->AddText(ImVec2((a.x + b.x) * 0.5f + 6.0f, (a.y + b.y) * 0.5f), colour, what.data(),
                          what.data() + what.size());
        } else {
            draw->AddCircle(a, 10.0f, colour, 0, 3.0f);
            draw->AddText(ImVec2(a.x + 14.0f, a.y - 8.0f), colour, what.data(), what.data() + what.size());
        }
    }
}

void LogicDebugOverlay::draw_panel(const game::Game& game, const shell::Fonts& fonts, float width,
                                   float height) {
    // Bottom left: clear of the HUD's bars (top left), the objectives (top right), the message and the rifle.
    ImGui::SetNextWindowPos(ImVec2(12.0f, height * 0.57f));
    ImGui::SetNextWindowSize(ImVec2(width * 0.46f, height * 0.41f));
    ImGui::SetNextWindowBgAlpha(0.72f);
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (fonts.mono) ImGui::PushFont(fonts.mono);
    ImGui::Begin("Logic debugger (F3)", nullptr, kFlags);
    char state[160];
    if (debugger_.halted())
        std::snprintf(state, sizeof state, "HALTED at step %lld  -  F7 one step, F6 resume",
                      static_cast<long long>(game.steps()));
    else
        std::snprintf(state, sizeof state, "running, step %lld  -  F6 halt",
                      static_cast<long long>(game.steps()));
    ImGui::TextColored(debugger_.halted() ? ImVec4(1.0f, 0.45f, 0.35f, 1.0f) : ImVec4(0.6f, 0.9f, 0.6f, 1.0f),
                       "%s", state);
    const auto& b = debugger_.break_point();
    ImGui::Text("break: %s  -  F8 %s", b ? b->text().c_str() : "none",
                b ? "clears it" : "at the newest event; halted: click a row");
    if (debugger_.halted()) {
        if (ImGui::SmallButton("Step")) debugger_.step_once();
        ImGui::SameLine();
        if (ImGui::SmallButton("Resume")) debugger_.resume();
        ImGui::SameLine();
        if (b && ImGui::SmallButton("Clear break")) debugger_.set_break(std::nullopt);
    }
    ImGui::Separator();
    ImGui::BeginChild("records");
    const auto& hit = debugger_.hit();
    int row = 0;
    for (const LogicLogEntry& e : debugger_.entries()) {
        const bool at_hit = hit && hit->record.step == e.record.step && hit->line == e.line;
        ImGui::PushID(row++);
        ImGui::PushStyleColor(ImGuiCol_Text, at_hit               ? IM_COL32(255, 110, 90, 255)
                                             : e.record.is_action ? kActionColour
                                                                  : kEventColour);
        if (ImGui::Selectable(e.line.c_str(), at_hit) && debugger_.halted())
            debugger_.set_break(LogicBreak::at(e.record));
        ImGui::PopStyleColor();
        ImGui::PopID();
    }
    if (!debugger_.halted()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::End();
    if (fonts.mono) ImGui::PopFont();
}

} // namespace ks::runtime
