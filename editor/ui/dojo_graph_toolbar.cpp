// The graph editor's toolbar (dojo_curve_view.h): the channel list's toggle, fit, seconds or frames (the
// clip's stored frame rate), the selected keys' numeric entry (time and value; offsets and scale for
// several) and easing (presets, a custom curve's numbers).
#include "jsonio/number_text.h"
#include "ui/dojo_curve_view.h"

#include <imgui.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>

namespace ks::editor::ui {

namespace {
std::optional<double> parse_number(const char* text) {
    std::string_view s(text);
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || error != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

void copy_text(char* out, std::size_t size, const std::string& text) {
    std::snprintf(out, size, "%s", text.c_str());
}

// A short text field applied on Enter; true then.
bool field(const char* label, char* text, std::size_t size, float width, const char* tip) {
    ImGui::SetNextItemWidth(width);
    const bool entered = ImGui::InputText(label, text, size, ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    return entered;
}
} // namespace

void DojoCurveView::edit(const DojoContext& dojo, const std::string& name, const GraphTransform& how) {
    const auto keys = selection_.keys();
    const auto clip = dojo.clip_index();
    const TimeUnits units = dojo.time_units();
    dojo.edits.apply(
        name, [&](anim::AnimationFile& file) { return transform_graph_keys(file, clip, keys, how, units); });
}

void DojoCurveView::toolbar(const DojoContext& dojo) {
    const bool list = show_list_.value_or(ImGui::GetContentRegionAvail().x >= 560.0f);
    if (ImGui::SmallButton(list ? "<<" : ">>")) show_list_ = !list;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(list ? "Hide the channel list" : "Show the channel list");
    ImGui::SameLine();
    if (ImGui::SmallButton("Fit")) fit_pending_ = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show every key of the shown channels (F over the graph)");
    ImGui::SameLine();
    if (ImGui::SmallButton("All")) selection_.all(points_);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Select every shown key (A over the graph)");
    ImGui::SameLine();
    frame_rate(dojo);
    ImGui::SameLine();
    ease_menu(dojo);
    key_fields(dojo);
}

// Seconds or frames: the clip stores its frame rate (saved with it, so frames mode survives save and load);
// each change is one undo step.
void DojoCurveView::frame_rate(const DojoContext& dojo) {
    const TimeUnits units = dojo.time_units();
    const auto clip = dojo.clip_index();
    const anim::ClipDef* def = dojo.shown_def();
    auto set = [&](std::optional<double> fps) {
        char name[48];
        std::snprintf(name, sizeof(name), fps ? "frames at %g fps" : "times in seconds", fps.value_or(0.0));
        dojo.edits.apply(name,
                         [&](anim::AnimationFile& file) { return set_clip_frame_rate(file, clip, fps); });
    };
    if (ImGui::SmallButton(units.frames ? "frames" : "seconds"))
        set(units.frames ? std::nullopt
                         : std::optional<double>(def ? clip_frame_rate(*def) : kDefaultFrameRate));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Times in seconds or frames. In frames the clip keeps its frame rate (saved with it) and "
            "moved keys and events land on whole frames");
    if (!units.frames) return;
    ImGui::SameLine();
    char rate[48];
    std::snprintf(rate, sizeof(rate), "%g fps", units.fps);
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("120 fps").x + ImGui::GetFrameHeight() * 1.5f);
    if (ImGui::BeginCombo("##fps", rate)) {
        for (const double fps : kFrameRates) {
            std::snprintf(rate, sizeof(rate), "%g fps", fps);
            if (ImGui::Selectable(rate, fps == units.fps) && fps != units.fps) set(fps);
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The clip's frame rate (keys stay where they are; one between frames shows a fraction)");
}

// The selected keys' numbers: one key's time and value; several keys' offsets and scale around their centre.
void DojoCurveView::key_fields(const DojoContext& dojo) {
    const auto& keys = selection_.keys();
    if (keys.empty()) {
        ImGui::TextDisabled("Click a key (Shift: add), drag a box, A: all. Drag moves (Ctrl: free), Alt+drag "
                            "scales, wheel zooms.");
        return;
    }
    const TimeUnits units = dojo.time_units();
    double t0 = 1e300, t1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const GraphKey& key : keys)
        if (const GraphPoint* p = point(key))
            t0 = std::min(t0, p->time), t1 = std::max(t1, p->time), v0 = std::min(v0, p->value),
            v1 = std::max(v1, p->value);
    if (t0 > t1) return;
    if (fields_for_ != keys || stamp_.revision != fields_revision_) { // what the fields show changed
        fields_for_ = keys;
        fields_revision_ = stamp_.revision;
        const bool one = keys.size() == 1;
        copy_text(time_text_, sizeof(time_text_), one ? units.text(t0) : "0");
        copy_text(value_text_, sizeof(value_text_),
                  one ? jsonio::shortest_text(std::round(v0 * 1e5) / 1e5) : "0");
        copy_text(time_scale_, sizeof(time_scale_), "1");
        copy_text(value_scale_, sizeof(value_scale_), "1");
    }
    const std::string what = keys.size() == 1 ? "key " + std::to_string(keys[0].phase + 1) + " of " +
                                                    keys[0].channel.node + " " +
                                                    curve_channel_name(keys[0].channel.channel)
                                              : std::to_string(keys.size()) + " keys";
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(what.c_str());
    ImGui::SameLine();
    const bool one = keys.size() == 1;
    if (field(one ? "time" : "+time", time_text_, sizeof(time_text_), 70.0f,
              one ? "The key's time (seconds, or frames with f: 12f); Enter sets it"
                  : "Move the keys' times by this much (Enter)")) {
        if (auto t = parse_time_text(time_text_, units)) {
            GraphTransform how;
            how.time_offset = one ? *t - t0 : *t;
            edit(dojo, one ? "set key time" : "move " + std::to_string(keys.size()) + " keys", how);
        }
    }
    ImGui::SameLine();
    if (field(one ? "value" : "+value", value_text_, sizeof(value_text_), 70.0f,
              one ? "The key's value (degrees, or the offset from rest); Enter sets it"
                  : "Add this to every selected key's value (Enter)")) {
        if (auto v = parse_number(value_text_)) {
            GraphTransform how;
            how.value_offset = one ? *v - v0 : *v;
            edit(dojo, one ? "set key value" : "offset " + std::to_string(keys.size()) + " keys", how);
        }
    }
    if (one) return;
    ImGui::SameLine();
    const bool scale_time =
        field("x time", time_scale_, sizeof(time_scale_), 44.0f,
              "Scale the keys' times around their centre (Enter; or Alt+drag sideways on the graph)");
    ImGui::SameLine();
    const bool scale_value =
        field("x value", value_scale_, sizeof(value_scale_), 44.0f,
              "Scale the keys' values around their centre (Enter; or Alt+drag up or down on the graph)");
    if (scale_time || scale_value) {
        const auto ts = parse_number(time_scale_), vs = parse_number(value_scale_);
        if (ts && vs) {
            GraphTransform how;
            how.pivot_time = (t0 + t1) * 0.5;
            how.pivot_value = (v0 + v1) * 0.5;
            how.time_scale = *ts;
            how.value_scale = *vs;
            edit(dojo, "scale " + std::to_string(keys.size()) + " keys", how);
        }
    }
}

// The selected keys' easing: presets for each selected key's segment (its node's), and a custom curve's
// numbers for one key.
void DojoCurveView::ease_menu(const DojoContext& dojo) {
    const auto& keys = selection_.keys();
    ImGui::BeginDisabled(keys.empty());
    if (ImGui::SmallButton("Ease...")) ImGui::OpenPopup("ease presets");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("The easing into the selected keys (each key's node, that segment): a preset, or a "
                          "Bezier or power curve with handles to drag");
    const auto clip = dojo.clip_index();
    if (ImGui::BeginPopup("ease presets")) {
        for (const EasePreset& preset : ease_presets())
            if (ImGui::Selectable(preset.label.c_str())) {
                std::map<std::pair<std::size_t, std::string>, bool> segments; // node x key, each once
                for (const GraphKey& key : keys) segments[{key.phase, key.channel.node}] = true;
                dojo.edits.apply("ease " + preset.label, [&](anim::AnimationFile& file) -> Result<void> {
                    for (const auto& [segment, unused] : segments)
                        if (auto set =
                                set_segment_ease(file, clip, segment.first, segment.second, preset.ease);
                            !set)
                            return set;
                    return ok();
                });
            }
        ImGui::EndPopup();
    }
    double t0 = 0, v0 = 0, t1 = 0, v1 = 0;
    anim::Ease ease;
    if (keys.size() != 1 || !handle_segment(t0, v0, t1, v1, ease)) {
        if (keys.size() == 1)
            if (const GraphPoint* p = point(keys[0]))
                for (std::size_t c = 0; c < channels_.size(); ++c)
                    if (channels_[c] == p->key.channel && p->key.phase < curves_[c].keys.size()) {
                        ImGui::SameLine();
                        const std::string name = anim::ease_name(curves_[c].keys[p->key.phase].ease);
                        ImGui::TextDisabled("%s", name.c_str());
                    }
        return;
    }
    const GraphKey key = keys[0];
    auto apply = [&](const anim::Ease& shaped) {
        dojo.edits.apply("set key " + std::to_string(key.phase + 1) + " of " + key.channel.node + "'s easing",
                         [&](anim::AnimationFile& file) {
                             return set_segment_ease(file, clip, key.phase, key.channel.node, shaped);
                         });
    };
    ImGui::SameLine();
    if (ease.family == anim::EaseFamily::CubicBezier) {
        float p[4] = {ease.params[0], ease.params[1], ease.params[2], ease.params[3]};
        ImGui::SetNextItemWidth(190.0f);
        if (ImGui::InputFloat4("bezier", p, "%.3g", ImGuiInputTextFlags_EnterReturnsTrue))
            apply(anim::Ease::bezier(p[0], p[1], p[2], p[3]));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("x1 y1 x2 y2: the handles (x in [0, 1]); Enter sets them");
    } else {
        float power = ease.params[0];
        ImGui::SetNextItemWidth(60.0f);
        if (ImGui::InputFloat("power", &power, 0, 0, "%.3g", ImGuiInputTextFlags_EnterReturnsTrue))
            apply(anim::Ease::power(power, ease.mode));
        ImGui::SameLine();
        constexpr const char* kModes[] = {"In", "Out", "InOut"};
        int mode = static_cast<int>(ease.mode);
        ImGui::SetNextItemWidth(70.0f);
        if (ImGui::Combo("##mode", &mode, kModes, 3))
            apply(anim::Ease::power(ease.params[0], static_cast<anim::EaseMode>(mode)));
    }
}

} // namespace ks::editor::ui
