// The shown clip's events (named markers: muzzle flash, footstep, sound cue): a lane under the timeline
// with a flag at each event's time (drag to move, right-click for its menu, double-click the lane to add
// one there), the Events page listing them (time, name, sound, Audition, remove), and the Add event popup.
// Each change is one undo step through model/dojo_clips.h (a drag is one step).
#include "ui/dojo_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
const ImU32 kEventColour = IM_COL32(120, 220, 150, 255);
const ImU32 kSoundEventColour = IM_COL32(110, 200, 255, 255);
const ImU32 kSelectedColour = IM_COL32(255, 210, 80, 255);
constexpr const char* kCommonNames[] = {"muzzle_flash", "footstep", "sound_cue"};
} // namespace

void DojoPanel::open_add_event(double seconds) {
    open_add_event_ = true;
    add_event_time_ = std::round(seconds * 1000.0) / 1000.0; // whole milliseconds read well in the file
    event_name_[0] = '\0';
    event_sound_.clear();
}

bool DojoPanel::delete_selected() {
    const anim::ClipDef* def = shown_def();
    if (!def || selected_event_ < 0 || static_cast<size_t>(selected_event_) >= def->events.size())
        return false;
    const auto event = static_cast<std::size_t>(selected_event_);
    if (apply("remove event " + def->events[event].name,
              [&] { return remove_event(file_, static_cast<size_t>(clip_), event); }))
        selected_event_ = -1;
    return true;
}

void DojoPanel::event_lane(Vec2 origin, float width, float height, double length) {
    const anim::ClipDef* def = shown_def();
    if (!def || !(width >= 1.0f && height >= 1.0f)) return; // InvisibleButton asserts on a zero size
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p(origin.x, origin.y);
    draw->AddRectFilled(p, ImVec2(p.x + width, p.y + height), IM_COL32(22, 25, 31, 255), 4.0f);
    auto x_of = [&](double t) { return p.x + static_cast<float>(t / length) * width; };
    auto time_at = [&](float x) {
        return std::clamp(static_cast<double>((x - p.x) / width) * length, 0.0, length);
    };
    const auto clip = static_cast<std::size_t>(clip_);
    // The lane itself: double-click adds an event there, right-click offers to.
    ImGui::SetCursorScreenPos(p);
    ImGui::InvisibleButton("event lane", ImVec2(width, height));
    ImGui::SetItemAllowOverlap(); // the flags drawn over it take the mouse first
    const float mouse_x = ImGui::GetIO().MousePos.x;
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
        open_add_event(time_at(mouse_x));
    if (ImGui::BeginPopupContextItem("lane menu")) {
        const double t = time_at(ImGui::GetMousePosOnOpeningCurrentPopup().x);
        char label[48];
        std::snprintf(label, sizeof(label), "Add event at %.2f s...", t);
        if (ImGui::MenuItem(label)) open_add_event(t);
        ImGui::EndPopup();
    }
    if (def->events.empty()) {
        draw->AddText(ImVec2(p.x + 8, p.y + (height - ImGui::GetTextLineHeight()) * 0.5f),
                      IM_COL32(110, 115, 130, 255), "events: double-click to add");
        return;
    }
    for (std::size_t i = 0; i < def->events.size(); ++i) {
        const anim::ClipEvent& event = def->events[i];
        const float x = x_of(event.time);
        const bool selected = static_cast<int>(i) == selected_event_;
        const ImU32 colour = selected              ? kSelectedColour
                             : event.sound.empty() ? kEventColour
                                                   : kSoundEventColour;
        draw->AddLine(ImVec2(x, p.y + 1), ImVec2(x, p.y + height - 1), colour, 2.0f);
        draw->AddTriangleFilled(ImVec2(x, p.y + 2), ImVec2(x + 9, p.y + 6), ImVec2(x, p.y + 10), colour);
        const ImVec2 label = ImGui::CalcTextSize(event.name.c_str());
        const float text_x = std::min(x + 11, p.x + width - label.x - 2);
        draw->AddText(ImVec2(text_x, p.y + (height - label.y) * 0.5f), colour, event.name.c_str());
        ImGui::PushID(static_cast<int>(i));
        ImGui::SetCursorScreenPos(ImVec2(x - 5, p.y));
        ImGui::InvisibleButton("event", ImVec2(std::max(10.0f, text_x + label.x - x + 5), height));
        event_flags_.push_back(Vec2(x, p.y + height * 0.5f));
        if (ImGui::IsItemActivated()) {
            selected_event_ = static_cast<int>(i);
            event_drag_ = true;
            event_drag_moved_ = false;
        }
        if (ImGui::IsItemHovered() && !event_drag_)
            ImGui::SetTooltip("%s at %.3f s%s%s\ndrag to move, right-click for more", event.name.c_str(),
                              event.time, event.sound.empty() ? "" : ", sound ", event.sound.c_str());
        if (ImGui::BeginPopupContextItem("event menu")) {
            selected_event_ = static_cast<int>(i);
            ImGui::TextDisabled("%s", event.name.c_str());
            if (ImGui::MenuItem("Edit in the Events page")) page_ = DojoPage::Events, page_requested_ = true;
            if (ImGui::MenuItem("Move the playhead here")) playing_ = false, restart_at(event.time);
            if (ImGui::MenuItem("Delete", "Del")) delete_selected();
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }
    // The drag follows the mouse by the selected index, which move_event keeps up to date as the event
    // passes others (the buttons' ids follow the index, so ImGui's active item cannot be relied on).
    if (event_drag_) {
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            event_drag_ = false;
        } else if (selected_event_ >= 0 && static_cast<size_t>(selected_event_) < def->events.size() &&
                   ImGui::GetIO().MouseDelta.x != 0.0f) {
            const auto event = static_cast<size_t>(selected_event_);
            const anim::AnimationFile before = event_drag_moved_ ? anim::AnimationFile{} : file_;
            const std::string name = def->events[event].name;
            const double seconds = std::round(time_at(mouse_x) * 1000.0) / 1000.0;
            if (auto moved = move_event(file_, clip, event, seconds)) {
                if (!event_drag_moved_) history_.record(before, "move event " + name); // the drag's one step
                event_drag_moved_ = true;
                selected_event_ = static_cast<int>(*moved);
                after_edit();
            }
        }
    }
}

// The Events page: one row per event, and Add event at the playhead.
void DojoPanel::event_list() {
    const anim::ClipDef* def = shown_def();
    if (!def) return;
    const auto clip = static_cast<std::size_t>(clip_);
    char add_label[64];
    std::snprintf(add_label, sizeof(add_label), "Add event at the playhead (%.2f s)...", clip_time());
    if (ImGui::Button(add_label)) open_add_event(clip_time());
    mark(DojoSpot::AddEvent);
    ImGui::SameLine();
    ImGui::TextDisabled("or double-click the event lane");
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("events", 5, flags)) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("time", ImGuiTableColumnFlags_WidthFixed, 80);
    ImGui::TableSetupColumn("name");
    ImGui::TableSetupColumn("sound");
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, audition_ ? 76.0f : 1.0f);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 24);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < def->events.size(); ++i) {
        const anim::ClipEvent& event = def->events[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::TableNextRow();
        if (static_cast<int>(i) == selected_event_)
            ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(90, 75, 30, 120));
        ImGui::TableNextColumn();
        // The time is moved when the drag or typing ends: the list re-sorts, and a row must not change
        // under the mouse.
        double seconds = editing_event_ == static_cast<int>(i) ? editing_event_time_ : event.time;
        const double zero = 0.0, length = def->duration();
        ImGui::SetNextItemWidth(-1);
        if (ImGui::DragScalar("##time", ImGuiDataType_Double, &seconds, 0.005f, &zero, &length, "%.3f s",
                              ImGuiSliderFlags_AlwaysClamp))
            editing_event_ = static_cast<int>(i), editing_event_time_ = seconds;
        if (ImGui::IsItemActivated()) selected_event_ = static_cast<int>(i);
        if (ImGui::IsItemDeactivatedAfterEdit()) {
            editing_event_ = -1;
            apply("move event " + event.name, [&]() -> Result<void> {
                auto moved = move_event(file_, clip, i, seconds);
                if (!moved) return moved.error();
                selected_event_ = static_cast<int>(*moved);
                return ok();
            });
            ImGui::PopID();
            break; // the events were re-sorted: the rest is drawn next frame
        }
        ImGui::TableNextColumn();
        char name[64];
        std::snprintf(name, sizeof(name), "%s", event.name.c_str());
        ImGui::SetNextItemWidth(-1);
        if (ImGui::InputText("##name", name, sizeof(name), ImGuiInputTextFlags_EnterReturnsTrue) &&
            event.name != name) {
            const std::string renamed = name;
            apply("rename event " + renamed, [&] { return rename_event(file_, clip, i, renamed); });
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type a name and press Enter");
        ImGui::TableNextColumn();
        std::string sound = event.sound;
        ImGui::SetNextItemWidth(-1);
        if (sound_name_widget("sound", sound, sound_names_) && sound != event.sound)
            apply(sound.empty() ? "clear event sound" : "event sound " + sound,
                  [&] { return set_event_sound(file_, clip, i, sound); });
        ImGui::TableNextColumn();
        if (static_cast<size_t>(clip_) < file_.clips.size() && i < file_.clips[clip].events.size())
            audition_button(audition_, file_.clips[clip].events[i].sound, 1.0f);
        ImGui::TableNextColumn();
        const bool remove = ImGui::SmallButton("x");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this event (Del removes the selected one)");
        ImGui::PopID();
        if (remove) {
            selected_event_ = static_cast<int>(i);
            delete_selected();
            break;
        }
    }
    ImGui::EndTable();
}

// Add event: its time (the playhead, or where the lane was clicked), a name (common ones a click away) and
// an optional sound from assets/sounds.
void DojoPanel::add_event_popup() {
    if (open_add_event_) ImGui::OpenPopup("Add event");
    open_add_event_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Add event", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const anim::ClipDef* def = shown_def();
    const double length = def ? def->duration() : 0.0;
    ImGui::Text("In clip '%s' (%.2f s long)", def ? def->name.c_str() : "", length);
    const double zero = 0.0;
    ImGui::SetNextItemWidth(120);
    ImGui::DragScalar("time", ImGuiDataType_Double, &add_event_time_, 0.005f, &zero, &length, "%.3f s",
                      ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(220);
    const bool entered =
        ImGui::InputText("name", event_name_, sizeof(event_name_), ImGuiInputTextFlags_EnterReturnsTrue);
    for (const char* common : kCommonNames) {
        ImGui::SameLine();
        if (ImGui::SmallButton(common)) std::snprintf(event_name_, sizeof(event_name_), "%s", common);
    }
    ImGui::SetNextItemWidth(220);
    sound_name_widget("sound", event_sound_, sound_names_);
    ImGui::SameLine();
    ImGui::TextDisabled("sound (optional)");
    ImGui::Spacing();
    const bool named = event_name_[0] != '\0';
    ImGui::BeginDisabled(!named);
    const bool add = ImGui::Button("Add", ImVec2(110, 0)) || (entered && named);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0))) ImGui::CloseCurrentPopup();
    if (add && def) {
        ImGui::CloseCurrentPopup();
        const std::string name = event_name_;
        apply("add event " + name, [&]() -> Result<void> {
            auto index = add_event(file_, static_cast<size_t>(clip_), add_event_time_, name, event_sound_);
            if (!index) return index.error();
            selected_event_ = static_cast<int>(*index);
            return ok();
        });
    }
    ImGui::EndPopup();
}

} // namespace ks::editor::ui
