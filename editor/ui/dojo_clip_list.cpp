// The dojo's clip management: the clip list (name, length, loop mode, events, a lock on the clips the game
// needs), New (empty, or from the pose shown), Duplicate, Rename, Delete and the loop mode of the shown
// clip. Each is one undo step through model/dojo_clips.h; a refusal (a required clip, a taken name) shows
// the model's message under the list.
#include "ui/dojo_panel.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

namespace {

// A small padlock in the text colour, `size` pixels high, at the cursor (a Dummy reserves its place).
void draw_lock(float size) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const ImU32 colour = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const float w = size * 0.62f, body = size * 0.52f, x = p.x + 1.0f, y = p.y + size * 0.12f;
    draw->AddRectFilled(ImVec2(x, y + size - body), ImVec2(x + w, y + size), colour, 1.5f);
    draw->PathArcTo(ImVec2(x + w * 0.5f, y + size - body), w * 0.32f, 3.14159f, 6.28318f, 8);
    draw->PathStroke(colour, 0, 1.6f);
    ImGui::Dummy(ImVec2(w + 2.0f, size));
}
} // namespace

void DojoPanel::clip_toolbar() {
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("Clips in %s", clip_file_.filename().string().c_str());
    const auto clip = static_cast<std::size_t>(clip_);
    const std::string protection = clip_protection(file_, clip);
    const float buttons = ImGui::CalcTextSize("New clip...Duplicate Rename...Delete").x +
                          ImGui::GetStyle().FramePadding.x * 8 + ImGui::GetStyle().ItemSpacing.x * 3;
    ImGui::SameLine(std::max(ImGui::GetCursorPosX(), ImGui::GetContentRegionMax().x - buttons));
    if (ImGui::Button("New clip...")) open_clip_dialog(kNewEmpty);
    mark(DojoSpot::NewClip);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add a clip: empty, or holding the pose shown now");
    ImGui::SameLine();
    if (ImGui::Button("Duplicate"))
        apply("duplicate clip", [&]() -> Result<void> {
            auto copy = duplicate_clip(file_, clip);
            if (!copy) return copy.error();
            clip_ = static_cast<int>(*copy);
            return ok();
        });
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Insert a copy of this clip after it");
    ImGui::SameLine();
    ImGui::BeginDisabled(!protection.empty());
    if (ImGui::Button("Rename...")) open_clip_dialog(kRename);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", protection.empty() ? "Rename this clip (blend pairs and 'next' follow it)"
                                                   : ("Required: " + protection).c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(!protection.empty());
    if (ImGui::Button("Delete")) apply("delete clip", [&] { return delete_clip(file_, clip); });
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", protection.empty() ? "Delete this clip and its blend pairs (Ctrl+Z undoes)"
                                                   : ("Required: " + protection).c_str());
}

void DojoPanel::clip_list() {
    // In a short window the list gives way (it scrolls) so that the pages under it stay on screen.
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const float fits = (ImGui::GetContentRegionAvail().y * 0.35f - 8.0f) / line - 1.0f;
    const float rows = std::clamp(fits, 1.0f, std::min<float>(4.5f, static_cast<float>(file_.clips.size())));
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_BordersOuter | ImGuiTableFlags_SizingStretchProp;
    const float height = line * (rows + 1.0f) + 8.0f;
    if (ImGui::BeginTable("clip list", 4, flags, ImVec2(0, height))) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("clip", ImGuiTableColumnFlags_WidthStretch, 3.0f);
        ImGui::TableSetupColumn("length", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        ImGui::TableSetupColumn("loop", ImGuiTableColumnFlags_WidthStretch, 1.6f);
        ImGui::TableSetupColumn("events", ImGuiTableColumnFlags_WidthStretch, 0.9f);
        ImGui::TableHeadersRow();
        for (int i = 0; i < static_cast<int>(file_.clips.size()); ++i) {
            const anim::ClipDef& def = file_.clips[static_cast<size_t>(i)];
            ImGui::PushID(i);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const bool selected = i == clip_ && !transition_mode_;
            if (ImGui::Selectable(def.name.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns) &&
                i < static_cast<int>(clips_.clips.size()))
                show_clip(i);
            if (selected && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
            const std::string protection = clip_protection(file_, static_cast<std::size_t>(i));
            if (!protection.empty()) {
                ImGui::SameLine(ImGui::GetColumnWidth() - ImGui::GetTextLineHeight() * 0.7f);
                draw_lock(ImGui::GetTextLineHeight());
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("Required: %s", protection.c_str());
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.2f s", def.duration());
            ImGui::TableNextColumn();
            if (def.loop == anim::LoopMode::Next)
                ImGui::Text("next: %s", def.next.c_str());
            else
                ImGui::TextUnformatted(loop_mode_name(def.loop));
            ImGui::TableNextColumn();
            if (def.events.empty())
                ImGui::TextDisabled("-");
            else
                ImGui::Text("%zu", def.events.size());
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    if (!message_.empty()) ImGui::TextColored(kErrorColour, "%s", message_.c_str());
}

// once / loop / ping-pong / next (with the clip played after) for the shown clip.
void DojoPanel::loop_row() {
    const anim::ClipDef* def = shown_def();
    if (!def) return;
    const auto clip = static_cast<std::size_t>(clip_);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Loop");
    constexpr anim::LoopMode kModes[] = {anim::LoopMode::Once, anim::LoopMode::Loop, anim::LoopMode::PingPong,
                                         anim::LoopMode::Next};
    constexpr const char* kLabels[] = {"once", "loop", "ping-pong", "next"};
    constexpr const char* kTips[] = {
        "Play once and hold the last pose", "Repeat; each pass starts where the last ended",
        "Forward, then backward to the start, forever", "Play once, then the clip chosen beside"};
    for (int m = 0; m < 4; ++m) {
        ImGui::SameLine();
        if (ImGui::RadioButton(kLabels[m], def->loop == kModes[m]) && def->loop != kModes[m]) {
            std::string next;
            if (kModes[m] == anim::LoopMode::Next) // the first other clip until one is chosen
                for (const auto& other : file_.clips)
                    if (other.name != def->name) {
                        next = other.name;
                        break;
                    }
            apply(std::string("loop mode ") + kLabels[m],
                  [&, mode = kModes[m]] { return set_loop_mode(file_, clip, mode, next); });
            return; // `def` may have moved
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kTips[m]);
    }
    if (def->loop != anim::LoopMode::Next) return;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x));
    if (!ImGui::BeginCombo("##next", def->next.c_str())) return;
    std::string chosen;
    for (const auto& other : file_.clips)
        if (ImGui::Selectable(other.name.c_str(), other.name == def->next)) chosen = other.name;
    ImGui::EndCombo();
    if (!chosen.empty() && chosen != def->next)
        apply("next clip " + chosen,
              [&] { return set_loop_mode(file_, clip, anim::LoopMode::Next, chosen); });
}

void DojoPanel::open_clip_dialog(int kind) {
    clip_dialog_ = kind;
    open_dialog_ = true;
    const anim::ClipDef* def = shown_def();
    std::snprintf(clip_name_, sizeof(clip_name_), "%s",
                  kind == kRename && def ? def->name.c_str() : "new_clip");
}

// The New clip / Rename clip dialog: the name (checked as it is typed) and, for a new clip, what it starts
// with.
void DojoPanel::clip_dialog() {
    const char* title = clip_dialog_ == kRename ? "Rename clip" : "New clip";
    if (open_dialog_) ImGui::OpenPopup(title);
    open_dialog_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const anim::ClipDef* def = shown_def();
    const bool rename = clip_dialog_ == kRename;
    ImGui::TextUnformatted(rename && def ? ("Rename '" + def->name + "' to:").c_str() : "Name:");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(300);
    const bool entered =
        ImGui::InputText("##clip name", clip_name_, sizeof(clip_name_),
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    mark(DojoSpot::ClipNameField);
    const std::string name = clip_name_;
    const bool unchanged = rename && def && name == def->name;
    const auto check = unchanged ? Result<void>(ok()) : check_new_clip_name(file_, name);
    if (check)
        ImGui::TextDisabled("letters, digits, _ and -");
    else
        ImGui::TextColored(kErrorColour, "%s", check.error().message.c_str());
    if (!rename) {
        ImGui::Spacing();
        if (ImGui::RadioButton("Empty: the rest nodes ease home", clip_dialog_ == kNewEmpty))
            clip_dialog_ = kNewEmpty;
        char label[128];
        std::snprintf(label, sizeof(label), "Holding the pose shown: '%s' at %.2f s",
                      def ? def->name.c_str() : "", time_);
        if (ImGui::RadioButton(label, clip_dialog_ == kNewFromPose)) clip_dialog_ = kNewFromPose;
    }
    ImGui::Spacing();
    ImGui::BeginDisabled(!check);
    const bool confirmed = ImGui::Button(rename ? "Rename" : "Create", ImVec2(110, 0)) || (entered && check);
    mark(DojoSpot::ClipDialogOk);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    if (confirmed && check) {
        ImGui::CloseCurrentPopup();
        if (rename && !unchanged) {
            apply("rename clip to " + name,
                  [&] { return rename_clip(file_, static_cast<size_t>(clip_), name); });
        } else if (!rename) {
            std::vector<NodePoseValue> pose;
            if (clip_dialog_ == kNewFromPose && player_)
                for (auto& value : pose_values(rig_, player_->pose()))
                    if (std::any_of(file_.rig.begin(), file_.rig.end(),
                                    [&](const anim::RigNodeDef& n) { return n.name == value.node; }))
                        pose.push_back(std::move(value));
            std::size_t made = 0;
            if (apply("new clip " + name, [&]() -> Result<void> {
                    auto index = new_clip(file_, name, pose);
                    if (!index) return index.error();
                    made = *index;
                    return ok();
                }))
                show_clip(static_cast<int>(made));
        }
    }
    ImGui::EndPopup();
}

} // namespace ks::editor::ui
