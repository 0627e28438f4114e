// The selected key's (phase's) editor (dojo_key_table.h).
#include "ui/dojo_key_table.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
// A dragged vector field: the components the drag changed, snapped to the field's grid (no float noise in
// the file); the others keep their exact values.
DVec3 dragged(const DVec3& before, const float (&v)[3], double steps) {
    DVec3 out = before;
    for (int i = 0; i < 3; ++i)
        if (v[i] != static_cast<float>(before[i])) out[i] = snap(static_cast<double>(v[i]), steps);
    return out;
}

// Where `node` is at the shown key now (rotation or position offset): a channel added to a key starts
// there, so nothing moves until it is edited.
DVec3 where(const DojoContext& dojo, const std::string& node, bool position) {
    const auto values = key_values(dojo.edits.file(), dojo.clip_index(), node, position);
    const auto key = static_cast<std::size_t>(dojo.selection.phase);
    return key < values.size() ? snap(values[key], kValueSteps) : DVec3(0.0);
}

// The easing's shape, 0..1 over 0..1, in a small box `size` wide and `height` high (one field's height: the
// key's fields stay on one row, leaving the table its rows at 1280x720).
void ease_thumbnail(const anim::Ease& ease, float size, float height) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = height / 1.5f, pad = h * 0.25f;
    draw->AddRectFilled(p, ImVec2(p.x + size, p.y + h + 2 * pad), IM_COL32(20, 22, 28, 255), 3.0f);
    draw->AddLine(ImVec2(p.x, p.y + pad), ImVec2(p.x + size, p.y + pad), IM_COL32(80, 80, 90, 255));
    draw->AddLine(ImVec2(p.x, p.y + pad + h), ImVec2(p.x + size, p.y + pad + h), IM_COL32(80, 80, 90, 255));
    ImVec2 points[64];
    for (int i = 0; i < 64; ++i) {
        const double t = i / 63.0;
        points[i] =
            ImVec2(p.x + static_cast<float>(t) * size, p.y + pad + h - static_cast<float>(ease(t)) * h);
    }
    draw->AddPolyline(points, 64, IM_COL32(120, 200, 255, 255), 0, 2.0f);
    ImGui::Dummy(ImVec2(size, h + 2 * pad));
}
} // namespace

bool DojoKeyTable::phase_buttons(const DojoContext& dojo) {
    int& selected = dojo.selection.phase;
    const auto c = dojo.clip_index(), p = static_cast<std::size_t>(selected);
    const std::size_t count = dojo.edits.file().clips[c].phases.size();
    const std::string key = "key " + std::to_string(p + 1);
    bool changed = false;
    const bool duplicate_clicked = ImGui::SmallButton("Duplicate key");
    dojo.mark(DojoSpot::DuplicateKey);
    if (duplicate_clicked)
        changed = dojo.edits.apply("duplicate " + key, [&](anim::AnimationFile& file) -> Result<void> {
            auto copy = duplicate_phase(file, c, p);
            if (!copy) return copy.error();
            selected = static_cast<int>(*copy);
            return {};
        });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Insert a copy of this key after it: absolute targets hold the pose (a pause), "
                          "relative ones repeat the motion");
    ImGui::SameLine();
    ImGui::BeginDisabled(count <= 1);
    if (ImGui::SmallButton("Remove key"))
        changed = dojo.edits.apply("remove " + key, [&](anim::AnimationFile& file) -> Result<void> {
            auto r = remove_phase(file, c, p);
            if (r) selected = std::max(0, selected - 1);
            return r;
        });
    ImGui::EndDisabled();
    for (int offset : {-1, +1}) {
        ImGui::SameLine();
        ImGui::BeginDisabled(offset < 0 ? p == 0 : p + 1 >= count);
        if (ImGui::SmallButton(offset < 0 ? "Earlier" : "Later"))
            changed = dojo.edits.apply("move " + key + (offset < 0 ? " earlier" : " later"),
                                       [&](anim::AnimationFile& file) -> Result<void> {
                                           auto moved = move_phase(file, c, p, offset);
                                           if (!moved) return moved.error();
                                           selected = static_cast<int>(*moved);
                                           return {};
                                       });
        ImGui::EndDisabled();
    }
    return changed;
}

void DojoKeyTable::draw(const DojoContext& dojo) {
    int& selected = dojo.selection.phase;
    const auto clip_index = dojo.clip_index();
    // The fields below change the key in place (begin_drag records the drag's one undo step first).
    anim::AnimationFile& file = dojo.edits.file_in_place();
    if (clip_index >= file.clips.size()) return;
    anim::ClipDef& def = file.clips[clip_index];
    if (def.phases.empty()) return;
    selected = std::clamp(selected, 0, static_cast<int>(def.phases.size()) - 1);
    for (int i = 0; i < static_cast<int>(def.phases.size()); ++i) {
        char label[32];
        std::snprintf(label, sizeof(label), "key %d", i + 1);
        if (i) ImGui::SameLine();
        if (ImGui::RadioButton(label, selected == i)) selected = i;
        dojo.named.here("key:" + std::to_string(i + 1));
    }
    // The key buttons on the keys' row when it has room (one row more for the table below).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float buttons = ImGui::CalcTextSize("Duplicate keyRemove keyEarlierLater").x +
                          style.FramePadding.x * 8 + style.ItemSpacing.x * 3;
    ImGui::SameLine(0, 16.0f);
    if (ImGui::GetContentRegionAvail().x < buttons) ImGui::NewLine();
    if (phase_buttons(dojo)) return; // the phases changed under this frame's references: draw them next frame
    anim::PhaseDef& phase = def.phases[static_cast<size_t>(selected)];
    bool edited = phase_timing(dojo, phase);
    std::string remove_node; // a key to remove, applied after the table (the rows reference the targets)
    edited |= target_rows(dojo, phase, remove_node);
    const auto phase_index = static_cast<std::size_t>(selected);
    if (edited) dojo.edits.changed();
    if (!remove_node.empty()) {
        dojo.edits.apply("remove key " + remove_node, [&](anim::AnimationFile& f) {
            return remove_node_key(f, clip_index, phase_index, remove_node);
        });
        return;
    }
    add_key_row(dojo);
}

// The selected key's duration and easing (with its curve); true when either changed.
bool DojoKeyTable::phase_timing(const DojoContext& dojo, anim::PhaseDef& phase) {
    bool edited = false;
    ImGui::BeginGroup();
    ImGui::SetNextItemWidth(120);
    if (const TimeUnits units = dojo.time_units(); units.frames) { // whole frames
        double frames = std::round(phase.duration * units.fps);
        const double most = 30.0 * units.fps, zero = 0.0;
        if (ImGui::DragScalar("duration", ImGuiDataType_Double, &frames, 0.2f, &zero, &most, "%.0f f",
                              ImGuiSliderFlags_AlwaysClamp))
            dojo.edits.begin_drag("key duration"), phase.duration = std::round(frames) / units.fps,
                                                   edited = true;
    } else {
        float duration = static_cast<float>(phase.duration);
        if (ImGui::DragFloat("duration", &duration, 0.005f, 0.0f, 30.0f, "%.3f s",
                             ImGuiSliderFlags_AlwaysClamp))
            dojo.edits.begin_drag("key duration"), phase.duration = snap(duration, kTimeSteps), edited = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Seconds to reach this key's targets; a key with no targets is a delay.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(150);
    const std::string current = anim::ease_name(phase.ease);
    if (ImGui::BeginCombo("easing", current.empty() ? "custom" : current.c_str())) {
        for (const auto& name : anim::known_ease_names()) {
            if (ImGui::Selectable(name.c_str(), name == current))
                if (auto e = anim::parse_ease_name(name))
                    dojo.edits.begin_drag("key easing"), phase.ease = *e, edited = true;
            dojo.named.here("combo:" + name);
        }
        ImGui::EndCombo();
    } else {
        dojo.named.here("easing");
    }
    ImGui::EndGroup();
    ImGui::SameLine();
    ease_thumbnail(phase.ease, 48.0f, ImGui::GetFrameHeight());

    return edited;
}

// One row per keyed node: rotation, position offset, mode and a remove button (`remove_node` names it).
bool DojoKeyTable::target_rows(const DojoContext& dojo, anim::PhaseDef& phase, std::string& remove_node) {
    bool edited = false;
    if (ImGui::BeginTable("targets", 5,
                          ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                              ImGuiTableFlags_SizingStretchProp,
                          ImVec2(0, std::max(ImGui::GetFrameHeightWithSpacing() * 3.0f,
                                             ImGui::GetContentRegionAvail().y -
                                                 ImGui::GetFrameHeightWithSpacing() - 4.0f)))) {
        ImGui::TableSetupColumn("node", ImGuiTableColumnFlags_WidthFixed, 90);
        ImGui::TableSetupColumn("rotation (deg, XYZ)");
        ImGui::TableSetupColumn("position offset");
        ImGui::TableSetupColumn("mode", ImGuiTableColumnFlags_WidthFixed, 60);
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 24);
        ImGui::TableHeadersRow();
        for (size_t t = 0; t < phase.targets.size(); ++t) {
            anim::TargetDef& target = phase.targets[t];
            ImGui::PushID(static_cast<int>(t));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            // The node posed in the preview is highlighted; clicking a name selects it there.
            if (ImGui::Selectable(target.node.c_str(), dojo.selection.node == target.node))
                dojo.selection.node = target.node;
            ImGui::TableNextColumn();
            auto& rot = target.rot ? target.rot : target.add_rot;
            if (rot) {
                float v[3] = {static_cast<float>(rot->x), static_cast<float>(rot->y),
                              static_cast<float>(rot->z)};
                ImGui::SetNextItemWidth(-1);
                if (ImGui::DragFloat3("##rot", v, 0.5f, -3600.0f, 3600.0f, "%.1f"))
                    dojo.edits.begin_drag("rotate " + target.node),
                        *rot = dragged(*rot, v, kDegreeFieldSteps), edited = true;
            } else if (ImGui::SmallButton("+ rot")) {
                const DVec3 here = where(dojo, target.node, false);
                dojo.edits.begin_drag("rotate " + target.node), target.rot = here, edited = true;
            }
            ImGui::TableNextColumn();
            auto& pos = target.pos ? target.pos : target.add_pos;
            if (pos) {
                float v[3] = {static_cast<float>(pos->x), static_cast<float>(pos->y),
                              static_cast<float>(pos->z)};
                ImGui::SetNextItemWidth(-1);
                if (ImGui::DragFloat3("##pos", v, 0.01f, -100.0f, 100.0f, "%.2f"))
                    dojo.edits.begin_drag("move " + target.node), *pos = dragged(*pos, v, kUnitFieldSteps),
                                                                  edited = true;
            } else if (ImGui::SmallButton("+ pos")) {
                const DVec3 here = where(dojo, target.node, true);
                dojo.edits.begin_drag("move " + target.node), target.pos = here, edited = true;
            }
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", target.add_rot || target.add_pos ? "relative" : "absolute");
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "absolute: the key holds these values; relative (the root's offsets, a looping "
                    "motion): added to where the node is when the key starts");
            ImGui::TableNextColumn();
            if (ImGui::SmallButton("x")) remove_node = target.node;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this node's key from this phase");
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    return edited;
}

// The node combo and "Add key" button; true when a key was added.
bool DojoKeyTable::add_key_row(const DojoContext& dojo) {
    bool edited = false;
    const auto clip_index = dojo.clip_index(), phase_index = static_cast<std::size_t>(dojo.selection.phase);
    const auto free_nodes = unkeyed_nodes(dojo.edits.file(), clip_index, phase_index);
    add_node_ = std::clamp(add_node_, 0, std::max(0, static_cast<int>(free_nodes.size()) - 1));
    ImGui::BeginDisabled(free_nodes.empty());
    ImGui::SetNextItemWidth(140);
    if (ImGui::BeginCombo("##add_node", free_nodes.empty()
                                            ? "(every node keyed)"
                                            : free_nodes[static_cast<size_t>(add_node_)].c_str())) {
        for (int i = 0; i < static_cast<int>(free_nodes.size()); ++i)
            if (ImGui::Selectable(free_nodes[static_cast<size_t>(i)].c_str(), i == add_node_)) add_node_ = i;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    const bool add_clicked = ImGui::Button("Add key");
    dojo.mark(DojoSpot::AddKey);
    if (add_clicked && !free_nodes.empty()) {
        const std::string node = free_nodes[static_cast<size_t>(add_node_)];
        edited = dojo.edits.apply("add key " + node, [&](anim::AnimationFile& file) {
            return add_node_key(file, clip_index, phase_index, node);
        });
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Key this node in this phase (holds its pose until you edit the key); Ctrl+Z undoes");
    ImGui::EndDisabled();
    return edited;
}

} // namespace ks::editor::ui
