// The dojo's curve view (dojo_curve_view.h).
#include "ui/dojo_curve_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
constexpr float kLeftMargin = 52.0f, kBottomMargin = 20.0f, kTopMargin = 18.0f, kRightMargin = 20.0f;
constexpr float kHandle = 6.0f; // half size of a key handle
const ImU32 kSegmentColours[2] = {IM_COL32(110, 190, 255, 255), IM_COL32(120, 235, 210, 255)};
const ImU32 kAxisColours[3] = {IM_COL32(235, 90, 90, 255), IM_COL32(120, 215, 90, 255),
                               IM_COL32(90, 140, 245, 255)};

// A grid step of 1, 2 or 5 times a power of ten giving about `lines` lines over `span`.
double nice_step(double span, int lines) {
    const double raw = span / lines;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double n = raw / magnitude;
    return (n < 1.5 ? 1.0 : n < 3.0 ? 2.0 : n < 7.0 ? 5.0 : 10.0) * magnitude;
}
} // namespace

// Samples the curve again when the file, clip, node, channel or width changed; false when it cannot be drawn
// (error_ says why).
bool DojoCurveView::refresh(const DojoContext& dojo, int samples) {
    const Stamp stamp{dojo.edits.revision(), dojo.playback.clip(), node_, samples, channel_};
    if (stamp == stamp_) return error_.empty();
    stamp_ = stamp;
    const anim::AnimationFile& file = dojo.edits.file();
    auto curve =
        clip_curve(file, dojo.clip_index(), file.rig[static_cast<size_t>(node_)].name, channel_, samples);
    if (!curve) {
        error_ = curve.error().message + (curve.error().hint.empty() ? "" : " (" + curve.error().hint + ")");
        return false;
    }
    error_.clear();
    curve_ = std::move(*curve);
    return true;
}

// Node (keyed nodes bright, the others dim) and channel.
void DojoCurveView::picker(const DojoContext& dojo) {
    const anim::ClipDef* def = dojo.shown_def();
    const anim::AnimationFile& file = dojo.edits.file();
    auto keyed = [&](const std::string& node) {
        for (const auto& phase : def->phases)
            for (const auto& target : phase.targets)
                if (target.node == node) return true;
        return false;
    };
    if (node_ < 0 || static_cast<size_t>(node_) >= file.rig.size()) { // the first keyed node
        node_ = 0;
        for (size_t i = 0; i < file.rig.size(); ++i)
            if (keyed(file.rig[i].name)) {
                node_ = static_cast<int>(i);
                break;
            }
    }
    ImGui::SetNextItemWidth(150);
    if (ImGui::BeginCombo("##node", file.rig[static_cast<size_t>(node_)].name.c_str())) {
        for (size_t i = 0; i < file.rig.size(); ++i) {
            const bool bright = keyed(file.rig[i].name);
            if (!bright)
                ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            if (ImGui::Selectable(file.rig[i].name.c_str(), static_cast<int>(i) == node_))
                node_ = static_cast<int>(i);
            if (!bright) ImGui::PopStyleColor();
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The node whose curve is shown (dim: not keyed in this clip)");
    // Two segmented controls, rotation x y z and position x y z, each axis in its usual colour.
    constexpr const char* kAxes[] = {"x", "y", "z"};
    for (int c = 0; c < 6; ++c) {
        if (c % 3 == 0) {
            ImGui::SameLine(0, 14.0f);
            ImGui::AlignTextToFramePadding();
            ImGui::TextDisabled(c == 0 ? "rotation" : "position");
        }
        ImGui::SameLine(0, c % 3 == 0 ? 6.0f : 2.0f);
        const bool on = static_cast<int>(channel_) == c;
        ImVec4 colour = ImGui::ColorConvertU32ToFloat4(kAxisColours[c % 3]);
        colour.w = on ? 0.85f : 0.18f;
        ImGui::PushStyleColor(ImGuiCol_Button, colour);
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered,
                              ImVec4(colour.x, colour.y, colour.z, on ? 0.95f : 0.4f));
        ImGui::PushID(c);
        if (ImGui::Button(kAxes[c % 3], ImVec2(ImGui::GetFrameHeight() * 1.1f, 0)))
            channel_ = static_cast<CurveChannel>(c);
        ImGui::PopID();
        ImGui::PopStyleColor(2);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s %s", c < 3 ? "rotation (degrees)" : "position offset from rest",
                              kAxes[c % 3]);
    }
}

namespace {
// The plot's rectangle on screen and the time and value ranges it shows.
struct Plot {
    ImVec2 lo, hi; // top-left, bottom-right of the plotting area
    double t0, t1, v0, v1;
    float x(double t) const { return lo.x + static_cast<float>((t - t0) / (t1 - t0)) * (hi.x - lo.x); }
    float y(double v) const { return hi.y - static_cast<float>((v - v0) / (v1 - v0)) * (hi.y - lo.y); }
    double time_at(float sx) const { return t0 + (sx - lo.x) / (hi.x - lo.x) * (t1 - t0); }
    double value_at(float sy) const { return v0 + (hi.y - sy) / (hi.y - lo.y) * (v1 - v0); }
};

// Value lines with their labels, and a faint line at each key's time with the time under the plot.
void draw_grid(ImDrawList* draw, const Plot& plot, const ClipCurve& curve, bool position) {
    const ImU32 label_colour = IM_COL32(130, 136, 150, 255);
    const double step = nice_step(plot.v1 - plot.v0, 5);
    for (double line = std::ceil(plot.v0 / step) * step; line <= plot.v1; line += step) {
        const double v = std::abs(line) < step * 1e-6 ? 0.0 : line; // no "-0"
        const float y = plot.y(v);
        draw->AddLine(ImVec2(plot.lo.x, y), ImVec2(plot.hi.x, y),
                      v == 0.0 ? IM_COL32(95, 100, 115, 255) : IM_COL32(45, 49, 58, 255));
        char label[24];
        std::snprintf(label, sizeof(label), position ? "%.2f" : "%.0f\xc2\xb0", v);
        const ImVec2 text = ImGui::CalcTextSize(label);
        draw->AddText(ImVec2(plot.lo.x - text.x - 6, y - text.y * 0.5f), label_colour, label);
    }
    draw->AddText(ImVec2(plot.lo.x - 4, plot.hi.y + 3), label_colour, "0s");
    for (const CurveKey& key : curve.keys) {
        const float x = plot.x(key.time);
        draw->AddLine(ImVec2(x, plot.lo.y), ImVec2(x, plot.hi.y), IM_COL32(60, 64, 76, 255));
        char label[16];
        std::snprintf(label, sizeof(label), "%.2fs", key.time);
        const ImVec2 text = ImGui::CalcTextSize(label);
        draw->AddText(ImVec2(std::min(x - text.x * 0.5f, plot.hi.x - text.x), plot.hi.y + 3), label_colour,
                      label);
    }
}

// The curve, one eased segment per key in alternating shades with the easing's name over wide segments, and
// the start value (the rest pose the dojo plays from) as a small dot.
void draw_segments(ImDrawList* draw, const Plot& plot, const ClipCurve& curve) {
    ImVec2 points[401];
    double from = 0.0;
    for (std::size_t k = 0; k < curve.keys.size(); ++k) {
        const CurveKey& key = curve.keys[k];
        int n = 0;
        for (const CurvePoint& point : curve.points)
            if (point.time >= from - 1e-9 && point.time <= key.time + 1e-9 && n < 401)
                points[n++] = ImVec2(plot.x(point.time), plot.y(point.value));
        const ImU32 colour = kSegmentColours[k % 2];
        if (n >= 2) draw->AddPolyline(points, n, colour, 0, 2.5f);
        const std::string ease = anim::ease_name(key.ease);
        const ImVec2 text = ImGui::CalcTextSize(ease.c_str());
        if (!ease.empty() && plot.x(key.time) - plot.x(from) > text.x + 8)
            draw->AddText(
                ImVec2((plot.x(from) + plot.x(key.time) - text.x) * 0.5f, plot.lo.y - kTopMargin + 2),
                (colour & 0x00ffffff) | 0xa0000000, ease.c_str());
        from = key.time;
    }
    draw->AddCircleFilled(ImVec2(plot.x(0.0), plot.y(curve.start_value)), 3.5f, IM_COL32(160, 165, 180, 255));
}

// A key's diamond: filled where the node's key sets the channel, hollow where it does not (yet).
void draw_handle(ImDrawList* draw, ImVec2 c, const CurveKey& key, bool selected, bool hot) {
    const ImU32 colour = selected    ? IM_COL32(255, 210, 80, 255)
                         : key.keyed ? IM_COL32(255, 160, 90, 255)
                                     : IM_COL32(150, 155, 170, 255);
    const float r = kHandle + (hot ? 1.5f : 0.0f);
    const ImVec2 d[4] = {ImVec2(c.x, c.y - r), ImVec2(c.x + r, c.y), ImVec2(c.x, c.y + r),
                         ImVec2(c.x - r, c.y)};
    if (key.keyed)
        draw->AddQuadFilled(d[0], d[1], d[2], d[3], colour);
    else
        draw->AddQuad(d[0], d[1], d[2], d[3], colour, 1.8f);
}
} // namespace

// The axes: the clip's time, and the values shown with a margin; kept while a key is dragged, so the plot
// does not rescale under the mouse.
void DojoCurveView::fit_axes() {
    if (drag_.active) return;
    double lo = curve_.start_value, hi = curve_.start_value;
    for (const auto& point : curve_.points) lo = std::min(lo, point.value), hi = std::max(hi, point.value);
    const double least = is_position(channel_) ? 0.2 : 20.0;
    if (hi - lo < least) lo -= (least - (hi - lo)) * 0.5, hi = lo + least;
    const double pad = (hi - lo) * 0.12;
    drag_.t0 = 0.0;
    drag_.t1 = std::max(curve_.duration, 0.01);
    drag_.v0 = lo - pad;
    drag_.v1 = hi + pad;
}

void DojoCurveView::draw(const DojoContext& dojo) {
    const anim::ClipDef* def = dojo.shown_def();
    const anim::AnimationFile& file = dojo.edits.file();
    if (!def || file.rig.empty()) return;
    picker(dojo);
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const ImVec2 size(ImGui::GetContentRegionAvail().x,
                      std::max(120.0f, ImGui::GetContentRegionAvail().y - 26.0f));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(p, ImVec2(p.x + size.x, p.y + size.y), IM_COL32(20, 22, 28, 255), 4.0f);
    const ImVec2 lo(p.x + kLeftMargin, p.y + kTopMargin);
    const ImVec2 hi(p.x + size.x - kRightMargin, p.y + size.y - kBottomMargin);
    if (!refresh(dojo, std::clamp(static_cast<int>((hi.x - lo.x) / 3.0f), 16, 400))) {
        ImGui::Dummy(size);
        draw->AddText(ImVec2(lo.x, lo.y + 10), IM_COL32(255, 110, 90, 255), error_.c_str());
        return;
    }
    fit_axes();
    const Plot plot{lo, hi, drag_.t0, drag_.t1, drag_.v0, drag_.v1};
    draw_grid(draw, plot, curve_, is_position(channel_));
    draw_segments(draw, plot, curve_);
    const std::string node = file.rig[static_cast<size_t>(node_)].name;
    for (std::size_t k = 0; k < curve_.keys.size(); ++k) {
        const CurveKey& key = curve_.keys[k];
        const ImVec2 c(plot.x(key.time), plot.y(key.value));
        ImGui::PushID(static_cast<int>(k));
        ImGui::SetCursorScreenPos(ImVec2(c.x - kHandle - 2, c.y - kHandle - 2));
        ImGui::InvisibleButton("key", ImVec2(2 * kHandle + 4, 2 * kHandle + 4));
        handles_.push_back(Vec2(c.x, c.y));
        const bool hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
        if (ImGui::IsItemActivated()) {
            drag_.active = true;
            drag_.key = k;
            drag_.time = key.time;
            drag_.value = key.value;
            drag_.target = key.keyed ? key.target_value : 0.0;
            drag_.keyed = key.keyed;
            drag_.origin = file;
            dojo.selection.phase = static_cast<int>(key.phase);
        }
        if (active && drag_.active && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
            const ImVec2 mouse = ImGui::GetIO().MousePos;
            drag(dojo, k, plot.time_at(mouse.x), plot.value_at(mouse.y), ImGui::GetIO().KeyShift);
        }
        if (ImGui::IsItemDeactivated()) drag_.active = false, drag_.origin = {};
        draw_handle(draw, c, key, static_cast<int>(key.phase) == dojo.selection.phase, hovered || active);
        if (hovered && !active)
            ImGui::SetTooltip(
                "key %zu of %s at %.3f s: %.2f%s\n%s", key.phase + 1, node.c_str(), key.time, key.value,
                is_position(channel_) ? "" : "\xc2\xb0",
                key.keyed ? (key.relative ? "relative key: drag to move" : "absolute key: drag to move")
                          : "not keyed here: drag up or down to key it");
        ImGui::PopID();
    }
    const float playhead = plot.x(dojo.clip_time());
    draw->AddLine(ImVec2(playhead, lo.y), ImVec2(playhead, hi.y), IM_COL32(255, 80, 80, 200), 1.5f);
    ImGui::SetCursorScreenPos(p);
    ImGui::Dummy(size);
    ImGui::TextDisabled("Drag keys in time and value (Shift: one direction). Hollow: %s not keyed there.",
                        node.c_str());
}

// One frame of a key drag: the file as it was when the drag began, with the key moved to (seconds, value).
// The first change records the drag's one undo step; a refused position keeps the last good one.
void DojoCurveView::drag(const DojoContext& dojo, std::size_t key, double seconds, double value, bool shift) {
    if (shift) { // one direction: the larger of the two moves on screen
        const double dt = std::abs(seconds - drag_.time) / (drag_.t1 - drag_.t0);
        const double dv = std::abs(value - drag_.value) / (drag_.v1 - drag_.v0);
        if (dt > dv)
            value = drag_.value;
        else
            seconds = drag_.time;
    }
    // Whole milliseconds and tenths of a degree (thousandths of a unit) read well in the file.
    seconds = std::round(seconds * 1000.0) / 1000.0;
    const double resolution = is_position(channel_) ? 1000.0 : 10.0;
    const double target = std::round((drag_.target + value - drag_.value) * resolution) / resolution;
    const auto clip = dojo.clip_index();
    const std::size_t phase = curve_.keys[key].phase;
    const std::string node = dojo.edits.file().rig[static_cast<size_t>(node_)].name;
    anim::AnimationFile edited = drag_.origin;
    Result<void> result = ok();
    if (std::abs(seconds - drag_.time) > 1e-4)
        result = move_key_time(edited, clip, phase, std::max(0.0, seconds));
    if (result && std::abs(value - drag_.value) > 1e-6) {
        if (!drag_.keyed) result = add_node_key(edited, clip, phase, node);
        if (result) result = set_key_value(edited, clip, phase, node, channel_, target);
    }
    if (!result) {
        dojo.edits.show_message(
            result.error().message); // while the drag stays refused, not logged each frame
        return;
    }
    dojo.edits.show_message({});
    dojo.edits.record_drag(drag_.origin, "drag key " + std::to_string(phase + 1) + " of " + node);
    dojo.edits.replace(std::move(edited));
}

} // namespace ks::editor::ui
