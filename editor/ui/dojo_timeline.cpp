// The dojo's transport and timeline (dojo_timeline.h).
#include "ui/dojo_timeline.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

void DojoTimeline::transport(const DojoContext& dojo) {
    DojoPlayback& playback = dojo.playback;
    if (ImGui::Button(playback.playing() ? "Pause" : "Play")) playback.set_playing(!playback.playing());
    ImGui::SameLine();
    if (ImGui::Button("Stop")) playback.set_playing(false), playback.restart_at(0.0);
    ImGui::SameLine();
    if (ImGui::Button("Step")) playback.set_playing(false), playback.restart_at(playback.time() + 1.0 / 30.0);
    ImGui::SameLine();
    bool loop = playback.loop();
    if (ImGui::Checkbox("Loop", &loop)) playback.set_loop(loop);
    ImGui::SameLine();
    if (dojo.audition) {
        ImGui::Checkbox("Sounds", &event_sounds_);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play the events' sounds as the playhead passes them");
        ImGui::SameLine();
    }
    ImGui::SetNextItemWidth(80);
    float speed = playback.speed();
    if (ImGui::DragFloat("speed", &speed, 0.01f, 0.05f, 4.0f, "%.2fx")) playback.set_speed(speed);
    ImGui::SameLine();
    const anim::Player* player = playback.player();
    ImGui::Text("t = %s%s", dojo.time_units().text(playback.time()).c_str(),
                player && player->blending() ? "  (blending)" : "");
}

void DojoTimeline::timeline(const DojoContext& dojo, float width, const DojoEventLane& lane_of) {
    DojoPlayback& playback = dojo.playback;
    const anim::AnimationFile& file = dojo.edits.file();
    const DojoPlayPlan& plan = playback.plan();
    // InvisibleButton refuses (asserts on) a zero size: a window too small for a timeline shows none.
    if (playback.clips().clips.empty() || !(width >= 1.0f)) return;
    const double length = std::max(0.01, playback.timeline_length());
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = 34.0f;
    ImGui::InvisibleButton("timeline", ImVec2(width, h));
    if (ImGui::IsItemActive()) { // scrub: onto a key marker within 6 pixels, else whole frames in frames mode
        const float u = std::clamp((ImGui::GetIO().MousePos.x - p.x) / width, 0.0f, 1.0f);
        playback.set_playing(false);
        const anim::ClipDef* def = dojo.shown_def();
        const double t = u * length;
        playback.restart_at(def && !plan.transition && t <= def->duration() + 1e-9
                                ? scrub_time(*def, dojo.time_units(), t, 6.0 * length / width)
                                : t);
    }
    draw->AddRectFilled(p, ImVec2(p.x + width, p.y + h), IM_COL32(28, 31, 38, 255), 4.0f);
    for (int s = 0; s <= static_cast<int>(length * 10); ++s) { // ticks every 0.1 s, labels every second
        const float x = p.x + static_cast<float>(s / 10.0 / length) * width;
        const bool second = s % 10 == 0;
        draw->AddLine(ImVec2(x, p.y + h - (second ? 12 : 6)), ImVec2(x, p.y + h),
                      IM_COL32(110, 115, 130, 255));
        if (second) {
            char t[16];
            std::snprintf(t, sizeof(t), "%ds", s / 10);
            draw->AddText(ImVec2(x + 2, p.y + h - 26), IM_COL32(150, 155, 170, 255), t);
        }
    }
    // Key markers: the end of every phase (where its targets are reached).
    // The file's clips can outnumber the compiled ones while the file has issues: index with care.
    auto markers = [&](int clip, double offset, ImU32 colour) {
        if (clip < 0 || static_cast<size_t>(clip) >= file.clips.size()) return;
        const anim::ClipDef& def = file.clips[static_cast<size_t>(clip)];
        double t = 0;
        for (size_t i = 0; i < def.phases.size(); ++i) {
            t += def.phases[i].duration;
            const float x = p.x + static_cast<float>((offset + t) / length) * width;
            if (x > p.x + width + 1) break;
            const bool sel = !plan.transition && static_cast<int>(i) == dojo.selection.phase;
            if (!plan.transition) dojo.named.set("marker:" + std::to_string(i + 1), Vec2(x, p.y + 9));
            draw->AddQuadFilled(ImVec2(x, p.y + 3), ImVec2(x + 5, p.y + 9), ImVec2(x, p.y + 15),
                                ImVec2(x - 5, p.y + 9), sel ? IM_COL32(255, 210, 80, 255) : colour);
        }
    };
    if (plan.transition) {
        markers(plan.from, 0.0, IM_COL32(150, 200, 255, 255));
        markers(plan.to, plan.switch_at, IM_COL32(255, 150, 120, 255));
        const float xs = p.x + static_cast<float>(plan.switch_at / length) * width;
        const float xb = p.x + static_cast<float>((plan.switch_at + plan.blend) / length) * width;
        draw->AddRectFilled(ImVec2(xs, p.y), ImVec2(xb, p.y + h), IM_COL32(255, 200, 80, 50));
    } else {
        markers(plan.clip, 0.0, IM_COL32(150, 200, 255, 255));
    }
    // The playhead: a looping clip's pass, a ping-pong's way back, the transition test's own time.
    const double shown = plan.transition ? std::fmod(playback.time(), length + 1e-9) : dojo.clip_time();
    const float x = p.x + static_cast<float>(shown / length) * width;
    const float lane = ImGui::GetFrameHeight() * 0.8f;
    if (!plan.transition && lane_of) lane_of(Vec2(p.x, p.y + h + 2), width, lane, length);
    draw->AddLine(ImVec2(x, p.y), ImVec2(x, p.y + h + (plan.transition ? 0 : lane + 2)),
                  IM_COL32(255, 80, 80, 255), 2.0f);
    ImGui::SetCursorScreenPos(ImVec2(p.x, p.y + h + 2));
    ImGui::Dummy(ImVec2(width, lane));
}

} // namespace ks::editor::ui
