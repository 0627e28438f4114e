// The dojo's clip management (dojo_clip_list.h).
#include "ui/dojo_clip_list.h"

#include "model/dojo_clips.h"
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

bool DojoClipList::folded() const {
    return folded_.value_or(ImGui::GetContentRegionAvail().y < ImGui::GetTextLineHeightWithSpacing() * 18.0f);
}

void DojoClipList::toolbar(const DojoContext& dojo) {
    const bool folded = folded_now_ = this->folded();
    if (ImGui::ArrowButton("##fold", folded ? ImGuiDir_Right : ImGuiDir_Down)) folded_ = !folded;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(folded ? "Show the clip list"
                                 : "Fold the clip list to one row (room for the pages)");
    ImGui::SameLine();
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("Clips in %s", dojo.clip_file.filename().string().c_str());
    const auto clip = dojo.clip_index();
    const std::string protection = clip_protection(dojo.edits.file(), clip);
    const float buttons = ImGui::CalcTextSize("New clip...Duplicate Rename...Delete").x +
                          ImGui::GetStyle().FramePadding.x * 8 + ImGui::GetStyle().ItemSpacing.x * 3;
    ImGui::SameLine(std::max(ImGui::GetCursorPosX(), ImGui::GetContentRegionMax().x - buttons));
    if (ImGui::Button("New clip...")) open_dialog(dojo, kNewEmpty);
    dojo.mark(DojoSpot::NewClip);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add a clip: empty, or holding the pose shown now");
    ImGui::SameLine();
    if (ImGui::Button("Duplicate"))
        dojo.edits.apply("duplicate clip", [&](anim::AnimationFile& file) -> Result<void> {
            auto copy = duplicate_clip(file, clip);
            if (!copy) return copy.error();
            dojo.playback.choose_clip(static_cast<int>(*copy)); // shown once the edit compiles
            return ok();
        });
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Insert a copy of this clip after it");
    ImGui::SameLine();
    ImGui::BeginDisabled(!protection.empty());
    if (ImGui::Button("Rename...")) open_dialog(dojo, kRename);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", protection.empty() ? "Rename this clip (blend pairs and 'next' follow it)"
                                                   : ("Required: " + protection).c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(!protection.empty());
    if (ImGui::Button("Delete"))
        dojo.edits.apply("delete clip", [&](anim::AnimationFile& file) { return delete_clip(file, clip); });
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", protection.empty() ? "Delete this clip and its blend pairs (Ctrl+Z undoes)"
                                                   : ("Required: " + protection).c_str());
}

void DojoClipList::list(const DojoContext& dojo) {
    const anim::AnimationFile& file = dojo.edits.file();
    if (folded_now_) { // one row: the shown clip, picked from a combo
        const anim::ClipDef* shown = dojo.shown_def();
        ImGui::SetNextItemWidth(220.0f);
        if (ImGui::BeginCombo("clip", shown ? shown->name.c_str() : "")) {
            for (int i = 0; i < static_cast<int>(file.clips.size()); ++i)
                if (ImGui::Selectable(file.clips[static_cast<size_t>(i)].name.c_str(),
                                      i == dojo.playback.clip()) &&
                    i < static_cast<int>(dojo.playback.clips().clips.size()))
                    dojo.show_clip(i);
            ImGui::EndCombo();
        }
        return;
    }
    // Three tenths of the column (at most every clip); it scrolls beyond, so that the pages
    // under it keep room for their own rows.
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const float fits = (ImGui::GetContentRegionAvail().y * 0.3f - 8.0f) / line - 1.0f;
    const float clips = static_cast<float>(file.clips.size());
    const float rows = std::clamp(rows_ > 0 ? rows_ : fits, 1.0f, std::max(1.0f, clips));
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
        for (int i = 0; i < static_cast<int>(file.clips.size()); ++i) {
            const anim::ClipDef& def = file.clips[static_cast<size_t>(i)];
            ImGui::PushID(i);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const bool selected = i == dojo.playback.clip() && !dojo.playback.transition();
            if (ImGui::Selectable(def.name.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns) &&
                i < static_cast<int>(dojo.playback.clips().clips.size()))
                dojo.show_clip(i);
            if (selected && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
            const std::string protection = clip_protection(file, static_cast<std::size_t>(i));
            if (!protection.empty()) {
                ImGui::SameLine(ImGui::GetColumnWidth() - ImGui::GetTextLineHeight() * 0.7f);
                draw_lock(ImGui::GetTextLineHeight());
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("Required: %s", protection.c_str());
            }
            ImGui::TableNextColumn();
            const TimeUnits units = clip_time_units(def);
            ImGui::TextUnformatted(units.text(def.duration()).c_str());
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
    if (const std::string& message = dojo.edits.message(); !message.empty())
        ImGui::TextColored(kErrorColour, "%s", message.c_str());
    // The splitter under the list: dragged, it gives the list more or fewer rows (the pages the rest).
    ImGui::InvisibleButton("##list_split", ImVec2(std::max(1.0f, ImGui::GetContentRegionAvail().x), 6.0f));
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeNS);
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        ImGui::GetWindowDrawList()->AddLine(ImVec2(a.x, (a.y + b.y) * 0.5f), ImVec2(b.x, (a.y + b.y) * 0.5f),
                                            ImGui::GetColorU32(ImGuiCol_SeparatorHovered), 2.0f);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drag: more or fewer clip rows");
    if (ImGui::IsItemActive())
        rows_ = std::clamp(rows + ImGui::GetIO().MouseDelta.y / line, 1.0f, std::max(1.0f, clips));
}

// once / loop / ping-pong / next (with the clip played after) for the shown clip.
void DojoClipList::loop_row(const DojoContext& dojo) {
    const anim::ClipDef* def = dojo.shown_def();
    if (!def) return;
    const anim::AnimationFile& file = dojo.edits.file();
    const auto clip = dojo.clip_index();
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
                for (const auto& other : file.clips)
                    if (other.name != def->name) {
                        next = other.name;
                        break;
                    }
            dojo.edits.apply(
                std::string("loop mode ") + kLabels[m],
                [&, mode = kModes[m]](anim::AnimationFile& f) { return set_loop_mode(f, clip, mode, next); });
            return; // `def` may have moved
        }
        dojo.named.here(std::string("loop:") + kLabels[m]);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kTips[m]);
    }
    if (def->loop != anim::LoopMode::Next) return;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x));
    if (!ImGui::BeginCombo("##next", def->next.c_str())) return;
    std::string chosen;
    for (const auto& other : file.clips)
        if (ImGui::Selectable(other.name.c_str(), other.name == def->next)) chosen = other.name;
    ImGui::EndCombo();
    if (!chosen.empty() && chosen != def->next)
        dojo.edits.apply("next clip " + chosen, [&](anim::AnimationFile& f) {
            return set_loop_mode(f, clip, anim::LoopMode::Next, chosen);
        });
}

void DojoClipList::open_dialog(const DojoContext& dojo, Dialog kind) {
    dialog_ = kind;
    open_dialog_ = true;
    const anim::ClipDef* def = dojo.shown_def();
    std::snprintf(name_, sizeof(name_), "%s", kind == kRename && def ? def->name.c_str() : "new_clip");
}

// The New clip / Rename clip dialog: the name (checked as it is typed) and, for a new clip, what it starts
// with.
void DojoClipList::dialog(const DojoContext& dojo) {
    const char* title = dialog_ == kRename ? "Rename clip" : "New clip";
    if (open_dialog_) ImGui::OpenPopup(title);
    open_dialog_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const anim::ClipDef* def = dojo.shown_def();
    const bool rename = dialog_ == kRename;
    ImGui::TextUnformatted(rename && def ? ("Rename '" + def->name + "' to:").c_str() : "Name:");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(300);
    const bool entered =
        ImGui::InputText("##clip name", name_, sizeof(name_),
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    dojo.mark(DojoSpot::ClipNameField);
    const std::string name = name_;
    const bool unchanged = rename && def && name == def->name;
    const auto check = unchanged ? Result<void>(ok()) : check_new_clip_name(dojo.edits.file(), name);
    if (check)
        ImGui::TextDisabled("letters, digits, _ and -");
    else
        ImGui::TextColored(kErrorColour, "%s", check.error().message.c_str());
    if (!rename) {
        ImGui::Spacing();
        if (ImGui::RadioButton("Empty: the rest nodes ease home", dialog_ == kNewEmpty)) dialog_ = kNewEmpty;
        char label[128];
        std::snprintf(label, sizeof(label), "Holding the pose shown: '%s' at %.2f s",
                      def ? def->name.c_str() : "", dojo.playback.time());
        if (ImGui::RadioButton(label, dialog_ == kNewFromPose)) dialog_ = kNewFromPose;
    }
    ImGui::Spacing();
    ImGui::BeginDisabled(!check);
    const bool confirmed = ImGui::Button(rename ? "Rename" : "Create", ImVec2(110, 0)) || (entered && check);
    dojo.mark(DojoSpot::ClipDialogOk);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    if (confirmed && check) {
        ImGui::CloseCurrentPopup();
        if (rename && !unchanged) {
            const auto clip = dojo.clip_index();
            dojo.edits.apply("rename clip to " + name,
                             [&](anim::AnimationFile& file) { return rename_clip(file, clip, name); });
        } else if (!rename) {
            create_clip(dojo, name);
        }
    }
    ImGui::EndPopup();
}

// A new clip, empty or holding the pose shown (the nodes the file's rig names), shown once made.
void DojoClipList::create_clip(const DojoContext& dojo, const std::string& name) {
    const anim::AnimationFile& file = dojo.edits.file();
    std::vector<NodePoseValue> pose;
    if (dialog_ == kNewFromPose && dojo.playback.player())
        for (auto& value : pose_values(dojo.playback.rig(), dojo.playback.player()->pose()))
            if (std::any_of(file.rig.begin(), file.rig.end(),
                            [&](const anim::RigNodeDef& n) { return n.name == value.node; }))
                pose.push_back(std::move(value));
    std::size_t made = 0;
    if (dojo.edits.apply("new clip " + name, [&](anim::AnimationFile& edited) -> Result<void> {
            auto index = new_clip(edited, name, pose);
            if (!index) return index.error();
            made = *index;
            return ok();
        }))
        dojo.show_clip(static_cast<int>(made));
}

} // namespace ks::editor::ui
