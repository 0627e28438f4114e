// The dojo's graph editor: channels, plot and mouse (dojo_curve_view.h); the toolbar is in
// dojo_graph_toolbar.cpp.
#include "ui/dojo_curve_view.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
constexpr float kLeftMargin = 46.0f, kBottomMargin = 18.0f, kTopMargin = 8.0f, kRightMargin = 10.0f;
constexpr float kHandle = 5.5f; // half size of a key's diamond
constexpr float kPick = 8.0f;   // how near (pixels) a click must be to pick a key or a handle
const ImU32 kAxisColours[3] = {IM_COL32(235, 90, 90, 255), IM_COL32(120, 215, 90, 255),
                               IM_COL32(90, 140, 245, 255)};
const ImU32 kPositionColours[3] = {IM_COL32(255, 170, 160, 255), IM_COL32(190, 245, 160, 255),
                                   IM_COL32(160, 200, 255, 255)};
const ImU32 kSelected = IM_COL32(255, 225, 90, 255), kHandleColour = IM_COL32(240, 240, 250, 255);
const ImU32 kPlayhead = IM_COL32(255, 150, 40, 210); // orange: apart from the x axis' red

ImU32 channel_colour(CurveChannel c) {
    return is_position(c) ? kPositionColours[component(c)] : kAxisColours[component(c)];
}

// A grid step of 1, 2 or 5 times a power of ten giving about `lines` lines over `span`.
double nice_step(double span, int lines) {
    const double raw = std::max(span, 1e-9) / lines;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double n = raw / magnitude;
    return (n < 1.5 ? 1.0 : n < 3.0 ? 2.0 : n < 7.0 ? 5.0 : 10.0) * magnitude;
}

// A segment's value span for handles: its rise, or a quarter of the view on a flat segment.
double span_of(double v0, double v1, const GraphRange& range) {
    return std::abs(v1 - v0) > 1e-9 ? v1 - v0 : (range.v1 - range.v0) * 0.25;
}

ImVec2 im(Vec2 v) {
    return ImVec2(v.x, v.y);
}

float distance(Vec2 a, Vec2 b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

void diamond(ImDrawList* draw, ImVec2 c, float r, ImU32 colour, bool filled) {
    const ImVec2 d[4] = {ImVec2(c.x, c.y - r), ImVec2(c.x + r, c.y), ImVec2(c.x, c.y + r),
                         ImVec2(c.x - r, c.y)};
    if (filled)
        draw->AddQuadFilled(d[0], d[1], d[2], d[3], colour);
    else
        draw->AddQuad(d[0], d[1], d[2], d[3], colour, 1.6f);
}
} // namespace

float DojoCurveView::Plot::x(double t) const {
    return lo.x + static_cast<float>((t - range.t0) / (range.t1 - range.t0)) * (hi.x - lo.x);
}
float DojoCurveView::Plot::y(double v) const {
    return hi.y - static_cast<float>((v - range.v0) / (range.v1 - range.v0)) * (hi.y - lo.y);
}
double DojoCurveView::Plot::time_at(float sx) const {
    return range.t0 + (sx - lo.x) / (hi.x - lo.x) * (range.t1 - range.t0);
}
double DojoCurveView::Plot::value_at(float sy) const {
    return range.v0 + (hi.y - sy) / (hi.y - lo.y) * (range.v1 - range.v0);
}

void DojoCurveView::show(int node, CurveChannel channel) {
    solo_node_ = node;
    solo_channel_ = channel;
    chosen_for_ = -1;
}

// Samples the shown channels again when the file, clip, channels or width changed; false when they cannot
// be drawn (error_ says why).
bool DojoCurveView::refresh(const DojoContext& dojo, int samples) {
    Stamp stamp{dojo.edits.revision(), dojo.playback.clip(), samples, channels_};
    if (stamp == stamp_) return error_.empty();
    stamp_ = std::move(stamp);
    auto curves = clip_curves(dojo.edits.file(), dojo.clip_index(), channels_, samples);
    if (!curves) {
        error_ =
            curves.error().message + (curves.error().hint.empty() ? "" : " (" + curves.error().hint + ")");
        curves_.clear();
        points_.clear();
        return false;
    }
    error_.clear();
    curves_ = std::move(*curves);
    points_ = graph_points(channels_, curves_);
    selection_.keep_shown(points_);
    return true;
}

const GraphPoint* DojoCurveView::point(const GraphKey& key) const {
    for (const GraphPoint& p : points_)
        if (p.key == key) return &p;
    return nullptr;
}

// Node rows, each with its rotation and position axes as toggles; a node's name toggles its rotation.
void DojoCurveView::channel_list(const DojoContext& dojo, float height) {
    const anim::AnimationFile& file = dojo.edits.file();
    const anim::ClipDef* def = dojo.shown_def();
    // Sized by the font: names up to 8 characters wide (longer ones clipped, the tooltip names them), then
    // six axis toggles.
    const float button = ImGui::GetTextLineHeight() + 2.0f, name = ImGui::CalcTextSize("forearm_").x;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = name + 6 * (button + 1.0f) + 4.0f + style.ItemSpacing.x + style.WindowPadding.x * 2 +
                        style.ScrollbarSize;
    ImGui::BeginChild("channels", ImVec2(width, height), true);
    for (std::size_t i = 0; i < file.rig.size(); ++i) {
        const std::string& node = file.rig[i].name;
        bool keyed = false;
        for (const auto& phase : def->phases)
            for (const auto& target : phase.targets) keyed = keyed || target.node == node;
        ImGui::PushID(static_cast<int>(i));
        if (!keyed) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        auto shown = [&](CurveChannel c) {
            return std::find(channels_.begin(), channels_.end(), NodeChannel{node, c}) != channels_.end();
        };
        auto toggle = [&](CurveChannel c, bool on) {
            std::erase(channels_, NodeChannel{node, c});
            if (on) channels_.push_back({node, c});
            fit_pending_ = true;
        };
        const bool any = shown(CurveChannel::RotX) || shown(CurveChannel::RotY) || shown(CurveChannel::RotZ);
        if (ImGui::Selectable(node.c_str(), any, 0, ImVec2(name, 0)))
            for (int c = 0; c < 3; ++c) toggle(static_cast<CurveChannel>(c), !any);
        if (!keyed) ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s%s: click to show or hide its rotation", node.c_str(),
                              keyed ? "" : " (not keyed in this clip)");
        for (int c = 0; c < 6; ++c) {
            const auto channel = static_cast<CurveChannel>(c);
            ImGui::SameLine(0, c == 3 ? 5.0f : 1.0f);
            const bool on = shown(channel);
            ImVec4 colour = ImGui::ColorConvertU32ToFloat4(channel_colour(channel));
            colour.w = on ? 0.9f : 0.15f;
            ImGui::PushStyleColor(ImGuiCol_Button, colour);
            ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(colour.x, colour.y, colour.z, 0.6f));
            ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(0, 0));
            ImGui::PushID(c);
            if (ImGui::Button(c % 3 == 0 ? "x" : c % 3 == 1 ? "y" : "z", ImVec2(button, button)))
                toggle(channel, !on);
            ImGui::PopID();
            ImGui::PopStyleVar();
            ImGui::PopStyleColor(2);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%s %s %s", node.c_str(), c < 3 ? "rotation (degrees)" : "position offset",
                                  curve_channel_name(channel));
        }
        ImGui::PopID();
    }
    ImGui::EndChild();
}

void DojoCurveView::draw(const DojoContext& dojo) {
    const anim::ClipDef* def = dojo.shown_def();
    const anim::AnimationFile& file = dojo.edits.file();
    if (!def || file.rig.empty()) return;
    if (chosen_for_ != dojo.playback.clip()) { // a new clip: its first keyed node's rotation, or the view's
        chosen_for_ = dojo.playback.clip();
        channels_.clear();
        selection_.clear();
        fit_pending_ = true;
        std::string node;
        if (solo_node_ >= 0 && static_cast<std::size_t>(solo_node_) < file.rig.size())
            channels_.push_back({file.rig[static_cast<std::size_t>(solo_node_)].name, solo_channel_});
        for (const auto& phase : def->phases)
            for (const auto& target : phase.targets)
                if (node.empty() && channels_.empty()) node = target.node;
        if (!node.empty())
            for (int c = 0; c < 3; ++c) channels_.push_back({node, static_cast<CurveChannel>(c)});
    }
    toolbar(dojo);
    const float height = std::max(90.0f, ImGui::GetContentRegionAvail().y);
    if (show_list_.value_or(ImGui::GetContentRegionAvail().x >= 560.0f)) {
        channel_list(dojo, height);
        ImGui::SameLine();
    }
    const ImVec2 p = ImGui::GetCursorScreenPos();
    plot(dojo, Vec2(p.x, p.y), Vec2(std::max(80.0f, ImGui::GetContentRegionAvail().x), height));
}

void DojoCurveView::plot(const DojoContext& dojo, Vec2 origin, Vec2 size) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p = im(origin), end(origin.x + size.x, origin.y + size.y);
    draw->AddRectFilled(p, end, IM_COL32(20, 22, 28, 255), 4.0f);
    Plot plot{Vec2(p.x + kLeftMargin, p.y + kTopMargin), Vec2(end.x - kRightMargin, end.y - kBottomMargin),
              range_};
    ImGui::SetCursorScreenPos(p);
    ImGui::InvisibleButton("plot", im(size),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle |
                               ImGuiButtonFlags_MouseButtonRight);
    if (!refresh(dojo, std::clamp(static_cast<int>((plot.hi.x - plot.lo.x) / 3.0f), 16, 400))) {
        draw->AddText(ImVec2(plot.lo.x, plot.lo.y + 10), IM_COL32(255, 110, 90, 255), error_.c_str());
        return;
    }
    if (channels_.empty())
        draw->AddText(ImVec2(plot.lo.x, plot.lo.y + 10), IM_COL32(150, 155, 170, 255),
                      "No channels shown: pick a node's axes in the list");
    const bool rotation = std::any_of(channels_.begin(), channels_.end(),
                                      [](const NodeChannel& c) { return !is_position(c.channel); });
    if (pending_key_ && !channels_.empty()) { // on the channel that changes most into that key
        std::size_t best = 0;
        double most = -1;
        for (std::size_t c = 0; c < curves_.size(); ++c) {
            const auto& keys = curves_[c].keys;
            if (*pending_key_ >= keys.size()) continue;
            const double from = *pending_key_ == 0 ? curves_[c].start_value : keys[*pending_key_ - 1].value;
            if (std::abs(keys[*pending_key_].value - from) > most)
                most = std::abs(keys[*pending_key_].value - from), best = c;
        }
        selection_.click({channels_[best], *pending_key_}, false);
        selection_.keep_shown(points_);
        pending_key_.reset();
    }
    if (fit_pending_ && drag_.gesture == Gesture::None) {
        range_ = fit_graph(curves_, rotation ? 20.0 : 0.2);
        fit_pending_ = false;
        double t0 = 0, v0 = 0, t1 = 0, v1 = 0; // and the tangent handles shown
        anim::Ease ease;
        if (handle_segment(t0, v0, t1, v1, ease))
            for (const EaseHandle& h : ease_handles(ease)) {
                const double v = v0 + h.y * span_of(v0, v1, range_), pad = (range_.v1 - range_.v0) * 0.06;
                range_.v0 = std::min(range_.v0, v - pad), range_.v1 = std::max(range_.v1, v + pad);
            }
    }
    plot.range = range_;
    mouse(dojo, plot);
    plot.range = range_;
    draw->PushClipRect(p, end, true);
    // Value lines with labels; time lines (seconds or frames) with labels under the plot.
    const ImU32 label = IM_COL32(130, 136, 150, 255);
    const double vstep = nice_step(range_.v1 - range_.v0, 5);
    for (double line = std::ceil(range_.v0 / vstep) * vstep; line <= range_.v1; line += vstep) {
        const double v = std::abs(line) < vstep * 1e-6 ? 0.0 : line;
        const float y = plot.y(v);
        draw->AddLine(ImVec2(plot.lo.x, y), ImVec2(plot.hi.x, y),
                      v == 0.0 ? IM_COL32(95, 100, 115, 255) : IM_COL32(45, 49, 58, 255));
        char text[24];
        std::snprintf(text, sizeof(text), rotation ? "%.0f" : "%.2f", v);
        const ImVec2 ts = ImGui::CalcTextSize(text);
        draw->AddText(ImVec2(plot.lo.x - ts.x - 5, y - ts.y * 0.5f), label, text);
    }
    const TimeUnits units = dojo.time_units();
    const double tstep = units.frames
                             ? std::max(1.0, nice_step(units.shown(range_.t1 - range_.t0), 6)) / units.fps
                             : nice_step(range_.t1 - range_.t0, 6);
    for (double t = std::ceil(range_.t0 / tstep) * tstep; t <= range_.t1; t += tstep) {
        const float x = plot.x(t);
        draw->AddLine(ImVec2(x, plot.lo.y), ImVec2(x, plot.hi.y), IM_COL32(38, 41, 50, 255));
        const std::string text = units.text(std::abs(t) < tstep * 1e-6 ? 0.0 : t);
        draw->AddText(ImVec2(x - ImGui::CalcTextSize(text.c_str()).x * 0.5f, plot.hi.y + 2), label,
                      text.c_str());
    }
    const anim::ClipDef* def = dojo.shown_def();
    const float clip_end = plot.x(def ? def->duration() : 0.0);
    draw->AddLine(ImVec2(clip_end, plot.lo.y), ImVec2(clip_end, plot.hi.y), IM_COL32(90, 95, 110, 255), 1.5f);
    // The curves, each in its axis colour (positions lighter, dashed by skipping every other piece).
    std::vector<ImVec2> line;
    for (std::size_t c = 0; c < curves_.size(); ++c) {
        line.clear();
        for (const CurvePoint& point : curves_[c].points)
            line.push_back(ImVec2(plot.x(point.time), plot.y(point.value)));
        const ImU32 colour = channel_colour(channels_[c].channel);
        if (!is_position(channels_[c].channel))
            draw->AddPolyline(line.data(), static_cast<int>(line.size()), colour, 0, 2.0f);
        else
            for (std::size_t i = 0; i + 1 < line.size(); i += 2)
                draw->AddLine(line[i], line[i + 1], colour, 2.0f);
    }
    draw_handles(draw, plot);
    draw_scale_box(draw, plot);
    // The keys: filled where the node's key sets the channel, hollow where it does not (moving one keys it).
    for (const GraphPoint& point : points_) {
        const ImVec2 c(plot.x(point.time), plot.y(point.value));
        handles_.push_back(Vec2(c.x, c.y));
        const bool selected = selection_.contains(point.key);
        const ImU32 colour = selected      ? kSelected
                             : point.keyed ? channel_colour(point.key.channel.channel)
                                           : IM_COL32(150, 155, 170, 255);
        if (selected) diamond(draw, c, kHandle + 2.0f, IM_COL32(20, 22, 28, 255), true);
        diamond(draw, c, kHandle + (selected ? 1.0f : 0.0f), colour, point.keyed || selected);
    }
    if (drag_.gesture == Gesture::Box) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        draw->AddRectFilled(im(drag_.start), m, IM_COL32(255, 225, 90, 30));
        draw->AddRect(im(drag_.start), m, IM_COL32(255, 225, 90, 200));
    }
    const float playhead = plot.x(dojo.clip_time());
    draw->AddLine(ImVec2(playhead, plot.lo.y), ImVec2(playhead, plot.hi.y), kPlayhead, 1.5f);
    draw->PopClipRect();
}

// The tangent handles of the single selected key's segment: Bezier control points joined to the segment's
// ends, or a power curve's point.
bool DojoCurveView::handle_segment(double& t0, double& v0, double& t1, double& v1, anim::Ease& ease) const {
    if (selection_.keys().size() != 1) return false;
    const GraphKey& key = selection_.keys().front();
    for (std::size_t c = 0; c < channels_.size() && c < curves_.size(); ++c) {
        if (channels_[c] != key.channel || key.phase >= curves_[c].keys.size()) continue;
        const CurveKey& end = curves_[c].keys[key.phase];
        t1 = end.time, v1 = end.value, ease = end.ease;
        t0 = key.phase == 0 ? 0.0 : curves_[c].keys[key.phase - 1].time;
        v0 = key.phase == 0 ? curves_[c].start_value : curves_[c].keys[key.phase - 1].value;
        return !ease_handles(ease).empty() && t1 > t0;
    }
    return false;
}

void DojoCurveView::draw_handles(ImDrawList* draw, const Plot& plot) {
    double t0 = 0, v0 = 0, t1 = 0, v1 = 0;
    anim::Ease ease;
    if (!handle_segment(t0, v0, t1, v1, ease)) return;
    const double span = span_of(v0, v1, plot.range);
    const auto handles = ease_handles(ease);
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const ImVec2 h(plot.x(t0 + handles[i].u * (t1 - t0)), plot.y(v0 + handles[i].y * span));
        if (ease.family == anim::EaseFamily::CubicBezier) {
            const ImVec2 anchor = i == 0 ? ImVec2(plot.x(t0), plot.y(v0)) : ImVec2(plot.x(t1), plot.y(v1));
            draw->AddLine(anchor, h, IM_COL32(240, 240, 250, 160), 1.2f);
        }
        draw->AddCircleFilled(h, 4.5f, kHandleColour);
        draw->AddCircle(h, 6.0f, IM_COL32(20, 22, 28, 255), 0, 1.5f);
    }
}

// Wheel zoom around the mouse (Shift: values only, Ctrl: time only), F fits, A selects all.
void DojoCurveView::zoom_and_pan(const Plot& plot) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MouseWheel != 0.0f) {
        const double f = std::pow(0.85, static_cast<double>(io.MouseWheel));
        const double t = plot.time_at(io.MousePos.x), v = plot.value_at(io.MousePos.y);
        if (!io.KeyShift) range_.t0 = t + (range_.t0 - t) * f, range_.t1 = t + (range_.t1 - t) * f;
        if (!io.KeyCtrl) range_.v0 = v + (range_.v0 - v) * f, range_.v1 = v + (range_.v1 - v) * f;
    }
    if (!io.WantTextInput) {
        if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) fit_pending_ = true;
        if (ImGui::IsKeyPressed(GLFW_KEY_A, false)) selection_.all(points_);
    }
}

void DojoCurveView::mouse(const DojoContext& dojo, const Plot& plot) {
    const ImGuiIO& io = ImGui::GetIO();
    const Vec2 m(io.MousePos.x, io.MousePos.y);
    if (ImGui::IsItemHovered() && drag_.gesture == Gesture::None) zoom_and_pan(plot);
    if (ImGui::IsItemActivated()) {
        drag_.start = m;
        drag_.range = range_;
        drag_.lock = DragLock::Undecided;
        drag_.label.clear();
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
            press(dojo, plot, m);
        else
            drag_.gesture = Gesture::Pan;
    }
    if (ImGui::IsItemActive()) {
        switch (drag_.gesture) {
        case Gesture::Keys:
            drag_keys(dojo, plot, m);
            break;
        case Gesture::Handle:
            drag_handle(dojo, plot, m);
            break;
        case Gesture::Scale:
            drag_scale(dojo, m);
            break;
        case Gesture::Pan: {
            const double dt =
                (m.x - drag_.start.x) / (plot.hi.x - plot.lo.x) * (drag_.range.t1 - drag_.range.t0);
            const double dv =
                (m.y - drag_.start.y) / (plot.hi.y - plot.lo.y) * (drag_.range.v1 - drag_.range.v0);
            range_ = {drag_.range.t0 - dt, drag_.range.t1 - dt, drag_.range.v0 + dv, drag_.range.v1 + dv};
            break;
        }
        case Gesture::Box:
        case Gesture::None:
            break;
        }
    }
    if (ImGui::IsItemDeactivated()) {
        if (drag_.gesture == Gesture::Box)
            selection_.box(points_, plot.time_at(drag_.start.x), plot.value_at(drag_.start.y),
                           plot.time_at(m.x), plot.value_at(m.y), io.KeyShift);
        // A click (no drag) on one of several selected keys selects it alone.
        if (drag_.gesture == Gesture::Keys && drag_.lock == DragLock::Undecided && !io.KeyShift)
            selection_.click(drag_.pressed, false);
        drag_.gesture = Gesture::None;
        drag_.origin = {};
    }
}

// A press: with Alt, scale the selected keys; on a tangent handle, shape it; on a key, select it (Shift:
// toggle) and start moving the selection; elsewhere, a box.
void DojoCurveView::press(const DojoContext& dojo, const Plot& plot, Vec2 m) {
    const bool shift = ImGui::GetIO().KeyShift;
    if (ImGui::GetIO().KeyAlt)
        if (const auto box = selection_bounds(points_, selection_.keys())) { // Alt: scale the selection
            drag_.gesture = Gesture::Scale;
            drag_.bounds = *box;
            drag_.origin = dojo.edits.file();
            return;
        }
    double t0 = 0, v0 = 0, t1 = 0, v1 = 0;
    anim::Ease ease;
    if (!shift && handle_segment(t0, v0, t1, v1, ease)) {
        const double span = span_of(v0, v1, plot.range);
        const auto handles = ease_handles(ease);
        for (std::size_t i = 0; i < handles.size(); ++i) {
            const Vec2 h(plot.x(t0 + handles[i].u * (t1 - t0)), plot.y(v0 + handles[i].y * span));
            if (distance(h, m) > kPick) continue;
            drag_.gesture = Gesture::Handle;
            drag_.handle = i;
            drag_.origin = dojo.edits.file();
            return;
        }
    }
    const GraphPoint* nearest = nullptr;
    float best = kPick;
    for (const GraphPoint& point : points_) {
        const float d = distance(Vec2(plot.x(point.time), plot.y(point.value)), m);
        if (d <= best) best = d, nearest = &point;
    }
    if (!nearest) {
        drag_.gesture = Gesture::Box;
        return;
    }
    if (shift || !selection_.contains(nearest->key)) selection_.click(nearest->key, shift);
    dojo.selection.phase = static_cast<int>(nearest->key.phase);
    drag_.gesture = selection_.contains(nearest->key) ? Gesture::Keys : Gesture::None;
    drag_.pressed = nearest->key;
    drag_.origin = dojo.edits.file();
}

// One frame of moving the selected keys: the file as it was when the drag began, with the keys moved by
// the mouse's travel along the direction the drag started in (Ctrl: both); whole milliseconds (frames in
// frames mode) and tenths of a degree (thousandths of a unit).
void DojoCurveView::drag_keys(const DojoContext& dojo, const Plot& plot, Vec2 m) {
    const Vec2 d(m.x - drag_.start.x, m.y - drag_.start.y);
    if (drag_.lock == DragLock::Undecided) drag_.lock = decide_drag_lock(d.x, d.y, ImGui::GetIO().KeyCtrl);
    if (drag_.lock == DragLock::Undecided) return;
    GraphTransform how;
    if (drag_.lock != DragLock::ValueOnly)
        how.time_offset = std::round((plot.time_at(m.x) - plot.time_at(drag_.start.x)) * 1000.0) / 1000.0;
    if (drag_.lock != DragLock::TimeOnly) {
        const bool position = std::all_of(selection_.keys().begin(), selection_.keys().end(),
                                          [](const GraphKey& k) { return is_position(k.channel.channel); });
        const double resolution = position ? 1000.0 : 10.0;
        how.value_offset =
            std::round((plot.value_at(m.y) - plot.value_at(drag_.start.y)) * resolution) / resolution;
    }
    anim::AnimationFile edited = drag_.origin;
    auto moved = transform_graph_keys(edited, dojo.clip_index(), selection_.keys(), how, dojo.time_units());
    if (!moved) return dojo.edits.show_message(moved.error().message); // not logged frame after frame
    dojo.edits.show_message({});
    const GraphKey& first = selection_.keys().front();
    const std::string name = selection_.keys().size() == 1
                                 ? "drag key " + std::to_string(first.phase + 1) + " of " + first.channel.node
                                 : "move " + std::to_string(selection_.keys().size()) + " keys";
    dojo.edits.record_drag(drag_.origin, name);
    dojo.edits.replace(std::move(edited));
}

// One frame of scaling the selected keys (Alt+drag): from the file when the drag began, by the factor the
// mouse's travel gives along the drag's direction (Ctrl: both axes).
void DojoCurveView::drag_scale(const DojoContext& dojo, Vec2 m) {
    const Vec2 d(m.x - drag_.start.x, m.y - drag_.start.y);
    if (drag_.lock == DragLock::Undecided) drag_.lock = decide_drag_lock(d.x, d.y, ImGui::GetIO().KeyCtrl);
    if (drag_.lock == DragLock::Undecided) return;
    const GraphTransform how = scale_drag(drag_.bounds, drag_.lock, d.x, d.y);
    anim::AnimationFile edited = drag_.origin;
    auto scaled = transform_graph_keys(edited, dojo.clip_index(), selection_.keys(), how, dojo.time_units());
    if (!scaled) return dojo.edits.show_message(scaled.error().message); // not logged frame after frame
    char factors[48];
    std::snprintf(factors, sizeof(factors), "time x%g  value x%g", how.time_scale, how.value_scale);
    drag_.label = factors; // drawn by the box
    dojo.edits.show_message({});
    dojo.edits.record_drag(drag_.origin, "scale " + std::to_string(selection_.keys().size()) + " keys");
    dojo.edits.replace(std::move(edited));
}

// While Alt is held over the graph (or a scale drag runs): the selected keys' box and its centre, the pivot.
void DojoCurveView::draw_scale_box(ImDrawList* draw, const Plot& plot) const {
    const bool scaling = drag_.gesture == Gesture::Scale;
    if (!scaling && !(ImGui::GetIO().KeyAlt && ImGui::IsItemHovered())) return;
    const auto box =
        scaling ? std::optional<GraphRange>(drag_.bounds) : selection_bounds(points_, selection_.keys());
    if (!box) return;
    const ImU32 colour = IM_COL32(255, 225, 90, 150);
    const ImVec2 lo(plot.x(box->t0) - 6.0f, plot.y(box->v1) - 6.0f),
        hi(plot.x(box->t1) + 6.0f, plot.y(box->v0) + 6.0f);
    draw->AddRect(lo, hi, colour, 0.0f, 0, 1.0f);
    const ImVec2 pivot((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
    draw->AddLine(ImVec2(pivot.x - 6, pivot.y), ImVec2(pivot.x + 6, pivot.y), colour, 1.5f);
    draw->AddLine(ImVec2(pivot.x, pivot.y - 6), ImVec2(pivot.x, pivot.y + 6), colour, 1.5f);
    if (scaling && !drag_.label.empty())
        draw->AddText(ImVec2(lo.x, lo.y - ImGui::GetTextLineHeight() - 2.0f), IM_COL32(255, 225, 90, 255),
                      drag_.label.c_str());
}

// One frame of shaping the selected key's easing by a tangent handle (from the file when the drag began).
void DojoCurveView::drag_handle(const DojoContext& dojo, const Plot& plot, Vec2 m) {
    double t0 = 0, v0 = 0, t1 = 0, v1 = 0;
    anim::Ease ease;
    if (selection_.keys().size() != 1 || !handle_segment(t0, v0, t1, v1, ease)) return;
    const GraphKey& key = selection_.keys().front();
    // The easing as it was when the drag began: the segment's ends do not move while it is shaped.
    auto origin_curve = clip_curves(drag_.origin, dojo.clip_index(), std::span(&key.channel, 1), 2);
    if (!origin_curve || key.phase >= origin_curve->front().keys.size()) return;
    const auto shaped = drag_ease_handle(origin_curve->front().keys[key.phase].ease, drag_.handle,
                                         (plot.time_at(m.x) - t0) / (t1 - t0),
                                         (plot.value_at(m.y) - v0) / span_of(v0, v1, plot.range));
    if (!shaped) return;
    anim::AnimationFile edited = drag_.origin;
    auto set = set_segment_ease(edited, dojo.clip_index(), key.phase, key.channel.node, *shaped);
    if (!set) return dojo.edits.show_message(set.error().message);
    dojo.edits.show_message({});
    dojo.edits.record_drag(drag_.origin, "shape key " + std::to_string(key.phase + 1) + " of " +
                                             key.channel.node + "'s easing");
    dojo.edits.replace(std::move(edited));
}

} // namespace ks::editor::ui
