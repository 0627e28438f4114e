// The inspector's group section: when the selection is one whole group, its name (editable) and member
// count; for a prefab instance its prefab, Apply to prefab, Revert all overrides and Unlink. The fields of a
// prefab member that the instance keeps as its own are marked in the field table (override_marker), with
// "Revert to prefab" in the field's context menu.
#include "model/edit_groups.h"
#include "model/edit_prefabs.h"
#include "ui/inspector_sections.h"
#include "ui/panel_style.h"
#include "ui/structure_actions.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

namespace {
const ImVec4 kOverride(1.0f, 0.75f, 0.25f, 1);

// The fields entity `id` overrides in `instance` (nullptr: not a live member).
const std::vector<std::string>* member_overrides(const level::Group& instance, int id) {
    const auto& members = instance.prefab.members;
    for (size_t i = 0; i < members.size() && i < instance.prefab.overrides.size(); ++i)
        if (members[i] == id) return &instance.prefab.overrides[i];
    return nullptr;
}

class GroupSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return !s.entities.empty(); }
    void draw(const PanelContext& ctx, InspectorSelection& s, FieldWidgets&) override {
        s.group_shown = draw_group(ctx);
    }

  private:
    static bool draw_group(const PanelContext& ctx);
};

// True when the selection is one whole group (or a prefab instance's member) and the section drew.
bool GroupSection::draw_group(const PanelContext& ctx) {
    Editor& editor = ctx.editor;
    const level::EditorData& data = editor.level().editor;
    const auto& selection = editor.doc().selection;
    // One whole group selected; or one entity of a prefab instance, shown with its instance's buttons.
    const level::Group* group = nullptr;
    bool whole = false;
    if (const std::vector<int> groups = selected_groups(editor); groups.size() == 1) {
        group = data.find_group(groups.front());
        whole = group && group_entities_deep(data, group->id).size() == selection.size();
    }
    if (!whole) {
        group = selection.size() == 1 && selection.front() > 0
                    ? data.find_group(prefab_instance_of(editor, selection.front()))
                    : nullptr;
        if (!group) return false;
    }
    const int id = group->id;
    if (whole) {
        ImGui::TextColored(group->has_prefab ? ImVec4(0.55f, 1.0f, 0.8f, 1) : ImVec4(0.6f, 0.8f, 1.0f, 1),
                           group->has_prefab ? "Prefab instance  #%d" : "Group  #%d", id);
        char name[128];
        std::snprintf(name, sizeof name, "%s", group->name.c_str());
        ImGui::SetNextItemWidth(-50);
        if (ImGui::InputText("name", name, sizeof name, ImGuiInputTextFlags_EnterReturnsTrue))
            ctx.report(rename_group(editor, id, name), "rename group");
        ctx.spots.here("group.name");
        ImGui::Text("%zu entities", group_entities_deep(data, id).size());
        if (!group->groups.empty()) {
            ImGui::SameLine();
            ImGui::TextDisabled("(%zu groups inside)", group->groups.size());
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("Enter")) ctx.report(enter_group(editor, id), "enter group");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Pick its members one by one (or double-click one in the viewport; Esc leaves)");
        ImGui::SameLine();
        if (ImGui::SmallButton("Ungroup")) ungroup_selection(editor, ctx.log);
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 1.0f, 0.8f, 1));
        ImGui::TextWrapped("Member of prefab instance %s  #%d", group->name.c_str(), id);
        ImGui::PopStyleColor();
    }
    if (group->has_prefab) {
        size_t overridden = 0;
        for (const auto& fields : group->prefab.overrides) overridden += fields.size();
        ImGui::Text("Prefab: %s", group->prefab.prefab.c_str());
        if (const PrefabEntry* entry = editor.prefabs().find(group->prefab.prefab); entry && entry->prefab)
            if (!entry->prefab->title.empty()) ImGui::TextDisabled("%s", entry->prefab->title.c_str());
        if (overridden > 0)
            ImGui::TextColored(kOverride, "* %zu overridden field%s", overridden, overridden == 1 ? "" : "s");
        else
            ImGui::TextDisabled("no overrides: it matches its prefab");
        if (ImGui::Button("Apply to prefab")) apply_to_prefab(editor, ctx.log, id);
        ctx.spots.here("group.apply");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Rewrite the prefab file from this instance; every instance follows");
        ImGui::SameLine();
        ImGui::BeginDisabled(overridden == 0);
        if (ImGui::Button("Revert all")) ctx.report(revert_prefab_overrides(editor, id), "revert");
        ImGui::EndDisabled();
        ctx.spots.here("group.revert");
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("Drop every override: the members follow the prefab again");
        ImGui::SameLine();
        if (ImGui::Button("Unlink")) ctx.report(unlink_prefab(editor, id), "unlink");
        ctx.spots.here("group.unlink");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Make it a plain group that no longer follows the prefab");
    }
    ImGui::Separator();
    return true;
}
} // namespace

std::unique_ptr<InspectorSection> make_group_section() {
    return std::make_unique<GroupSection>();
}

PrimaryOverrides primary_overrides(const Editor& editor) {
    PrimaryOverrides out;
    const auto& selection = editor.doc().selection;
    if (selection.empty() || selection.front() <= 0) return out;
    out.entity = selection.front();
    out.instance = prefab_instance_of(editor, out.entity);
    if (const level::Group* group = editor.level().editor.find_group(out.instance))
        out.fields = member_overrides(*group, out.entity);
    return out;
}

// After a field's name in the inspector table: a mark when the primary selected entity keeps this field as
// its own in its prefab instance, and the name's context menu to revert it.
void override_marker(const PanelContext& ctx, const PrimaryOverrides& primary, const std::string& field) {
    if (primary.instance == 0) return;
    const auto* fields = primary.fields;
    const bool overridden = fields && std::find(fields->begin(), fields->end(), field) != fields->end();
    if (ImGui::BeginPopupContextItem("field_menu")) {
        if (ImGui::MenuItem("Revert to prefab", nullptr, false, overridden))
            ctx.report(revert_prefab_overrides(ctx.editor, primary.instance, primary.entity, field),
                       "revert");
        ImGui::EndPopup();
    }
    if (!overridden) return;
    ImGui::SameLine(0, 3);
    ImGui::TextColored(kOverride, "*");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Overridden in this prefab instance (right-click the name: Revert to prefab)");
}

} // namespace ks::editor::ui
