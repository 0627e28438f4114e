// The shown clip's events: the lane, the Events page and the Add event popup (dojo_events.h).
#include "ui/dojo_events.h"

#include "model/dojo_clips.h"

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

void DojoEvents::open_add(const DojoContext& dojo, double seconds) {
    open_add_ = true;
    add_time_ = dojo.event_time(seconds);
    name_[0] = '\0';
    sound_.clear();
}

bool DojoEvents::delete_selected(const DojoContext& dojo) {
    const anim::ClipDef* def = dojo.shown_def();
    int& selected = dojo.selection.event;
    if (!def || selected < 0 || static_cast<size_t>(selected) >= def->events.size()) return false;
    const auto event = static_cast<std::size_t>(selected);
    const auto clip = dojo.clip_index();
    if (dojo.edits.apply("remove event " + def->events[event].name,
                         [&](anim::AnimationFile& file) { return remove_event(file, clip, event); }))
        selected = -1;
    return true;
}

// One frame of a flag's drag: the selected event to `seconds`; the first move records the drag's one
// undo step. The selection follows the event as move_event re-sorts the list.
void DojoEvents::drag_selected(const DojoContext& dojo, double seconds) {
    const anim::ClipDef* def = dojo.shown_def();
    int& selected = dojo.selection.event;
    if (!def || selected < 0 || static_cast<size_t>(selected) >= def->events.size()) return;
    const auto event = static_cast<size_t>(selected);
    const anim::AnimationFile before = drag_moved_ ? anim::AnimationFile{} : dojo.edits.file();
    const std::string name = def->events[event].name;
    anim::AnimationFile& file = dojo.edits.file_in_place();
    if (auto moved = move_event(file, dojo.clip_index(), event, seconds)) {
        if (!drag_moved_) dojo.edits.record_drag(before, "move event " + name);
        drag_moved_ = true;
        selected = static_cast<int>(*moved);
        dojo.edits.changed();
    }
}

void DojoEvents::lane(const DojoContext& dojo, Vec2 origin, float width, float height, double length) {
    const anim::ClipDef* def = dojo.shown_def();
    if (!def || !(width >= 1.0f && height >= 1.0f)) return; // InvisibleButton asserts on a zero size
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p(origin.x, origin.y);
    draw->AddRectFilled(p, ImVec2(p.x + width, p.y + height), IM_COL32(22, 25, 31, 255), 4.0f);
    auto x_of = [&](double t) { return p.x + static_cast<float>(t / length) * width; };
    auto time_at = [&](float x) {
        return std::clamp(static_cast<double>((x - p.x) / width) * length, 0.0, length);
    };
    // The lane itself: double-click adds an event there, right-click offers to.
    ImGui::SetCursorScreenPos(p);
    ImGui::InvisibleButton("event lane", ImVec2(width, height));
    dojo.named.here("event_lane"); // its centre: a script double-clicks at a time's x on it
    ImGui::SetItemAllowOverlap();  // the flags drawn over it take the mouse first
    const float mouse_x = ImGui::GetIO().MousePos.x;
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
        open_add(dojo, time_at(mouse_x));
    if (ImGui::BeginPopupContextItem("lane menu")) {
        const double t = time_at(ImGui::GetMousePosOnOpeningCurrentPopup().x);
        char label[48];
        std::snprintf(label, sizeof(label), "Add event at %.2f s...", t);
        if (ImGui::MenuItem(label)) open_add(dojo, t);
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
        const bool selected = static_cast<int>(i) == dojo.selection.event;
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
        flags_.push_back(Vec2(x, p.y + height * 0.5f));
        if (ImGui::IsItemActivated()) {
            dojo.selection.event = static_cast<int>(i);
            drag_ = true;
            drag_moved_ = false;
        }
        if (ImGui::IsItemHovered() && !drag_)
            ImGui::SetTooltip("%s at %.3f s%s%s\ndrag to move, right-click for more", event.name.c_str(),
                              event.time, event.sound.empty() ? "" : ", sound ", event.sound.c_str());
        if (ImGui::BeginPopupContextItem("event menu")) {
            dojo.selection.event = static_cast<int>(i);
            ImGui::TextDisabled("%s", event.name.c_str());
            if (ImGui::MenuItem("Edit in the Events page")) dojo.selection.request_page(DojoPage::Events);
            if (ImGui::MenuItem("Move the playhead here"))
                dojo.playback.set_playing(false), dojo.playback.restart_at(event.time);
            if (ImGui::MenuItem("Delete", "Del")) delete_selected(dojo);
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }
    // The drag follows the mouse by the selected index, which move_event keeps up to date as the event
    // passes others (the buttons' ids follow the index, so ImGui's active item cannot be relied on).
    if (drag_) {
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left))
            drag_ = false;
        else if (ImGui::GetIO().MouseDelta.x != 0.0f)
            drag_selected(dojo, dojo.event_time(time_at(mouse_x)));
    }
}

// The Events page: one row per event, and Add event at the playhead.
void DojoEvents::list(const DojoContext& dojo) {
    const anim::ClipDef* def = dojo.shown_def();
    if (!def) return;
    const auto clip = dojo.clip_index();
    char add_label[64];
    std::snprintf(add_label, sizeof(add_label), "Add event at the playhead (%.2f s)...", dojo.clip_time());
    if (ImGui::Button(add_label)) open_add(dojo, dojo.clip_time());
    dojo.mark(DojoSpot::AddEvent);
    ImGui::SameLine();
    ImGui::TextDisabled("or double-click the event lane");
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("events", 5, flags)) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("time", ImGuiTableColumnFlags_WidthFixed, 80);
    ImGui::TableSetupColumn("name");
    ImGui::TableSetupColumn("sound");
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, dojo.audition ? 76.0f : 1.0f);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 24);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < def->events.size(); ++i) {
        const anim::ClipEvent& event = def->events[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::TableNextRow();
        if (static_cast<int>(i) == dojo.selection.event)
            ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(90, 75, 30, 120));
        ImGui::TableNextColumn();
        // The time is moved when the drag or typing ends: the list re-sorts, and a row must not change
        // under the mouse.
        double seconds = editing_ == static_cast<int>(i) ? editing_time_ : event.time;
        const double zero = 0.0, length = def->duration();
        ImGui::SetNextItemWidth(-1);
        if (ImGui::DragScalar("##time", ImGuiDataType_Double, &seconds, 0.005f, &zero, &length, "%.3f s",
                              ImGuiSliderFlags_AlwaysClamp))
            editing_ = static_cast<int>(i), editing_time_ = seconds;
        if (ImGui::IsItemActivated()) dojo.selection.event = static_cast<int>(i);
        if (ImGui::IsItemDeactivatedAfterEdit()) {
            editing_ = -1;
            dojo.edits.apply("move event " + event.name, [&](anim::AnimationFile& file) -> Result<void> {
                auto moved = move_event(file, clip, i, dojo.event_time(seconds));
                if (!moved) return moved.error();
                dojo.selection.event = static_cast<int>(*moved);
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
            dojo.edits.apply("rename event " + renamed,
                             [&](anim::AnimationFile& file) { return rename_event(file, clip, i, renamed); });
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type a name and press Enter");
        ImGui::TableNextColumn();
        std::string sound = event.sound;
        ImGui::SetNextItemWidth(-1);
        if (sound_name_widget("sound", sound, sound_names_) && sound != event.sound)
            dojo.edits.apply(
                sound.empty() ? "clear event sound" : "event sound " + sound,
                [&](anim::AnimationFile& file) { return set_event_sound(file, clip, i, sound); });
        ImGui::TableNextColumn();
        if (const auto& clips = dojo.edits.file().clips; clip < clips.size() && i < clips[clip].events.size())
            audition_button(dojo.audition, clips[clip].events[i].sound, 1.0f);
        ImGui::TableNextColumn();
        const bool remove = ImGui::SmallButton("x");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this event (Del removes the selected one)");
        ImGui::PopID();
        if (remove) {
            dojo.selection.event = static_cast<int>(i);
            delete_selected(dojo);
            break;
        }
    }
    ImGui::EndTable();
}

// Add event: its time (the playhead, or where the lane was clicked), a name (common ones a click away) and
// an optional sound from assets/sounds.
void DojoEvents::popup(const DojoContext& dojo) {
    if (open_add_) ImGui::OpenPopup("Add event");
    open_add_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Add event", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const anim::ClipDef* def = dojo.shown_def();
    const double length = def ? def->duration() : 0.0;
    ImGui::Text("In clip '%s' (%.2f s long)", def ? def->name.c_str() : "", length);
    const double zero = 0.0;
    ImGui::SetNextItemWidth(120);
    ImGui::DragScalar("time", ImGuiDataType_Double, &add_time_, 0.005f, &zero, &length, "%.3f s",
                      ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(220);
    const bool entered = ImGui::InputText("name", name_, sizeof(name_), ImGuiInputTextFlags_EnterReturnsTrue);
    for (const char* common : kCommonNames) {
        ImGui::SameLine();
        if (ImGui::SmallButton(common)) std::snprintf(name_, sizeof(name_), "%s", common);
        dojo.named.here(std::string("event.name:") + common);
    }
    ImGui::SetNextItemWidth(220);
    sound_name_widget("sound", sound_, sound_names_, &dojo.named);
    ImGui::SameLine();
    ImGui::TextDisabled("sound (optional)");
    ImGui::Spacing();
    const bool named = name_[0] != '\0';
    ImGui::BeginDisabled(!named);
    const bool add_clicked = ImGui::Button("Add", ImVec2(110, 0));
    dojo.named.here("event.add");
    const bool add = add_clicked || (entered && named);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0))) ImGui::CloseCurrentPopup();
    if (add && def) {
        ImGui::CloseCurrentPopup();
        const std::string name = name_;
        dojo.edits.apply("add event " + name, [&](anim::AnimationFile& file) -> Result<void> {
            auto index = add_event(file, dojo.clip_index(), dojo.event_time(add_time_), name, sound_);
            if (!index) return index.error();
            dojo.selection.event = static_cast<int>(*index);
            return ok();
        });
    }
    ImGui::EndPopup();
}

} // namespace ks::editor::ui
