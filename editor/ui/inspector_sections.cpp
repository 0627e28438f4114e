// The inspector's Properties tab, section by section: the player start alone; the level settings when
// nothing is selected; the group or prefab instance (group_inspector.cpp); the selection's title and field
// the actions; the field table (common fields of several); a robot's patrol; a sound's Audition; the level
// settings folded below. A new section is a class here (or in its own file) and one line in
// make_inspector_sections().
#include "ui/inspector_sections.h"
#include "level/entity_shapes.h"
#include "model/edit_entities.h"
#include "model/edit_patrols.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
const ImVec4 kStartTitleText(0.45f, 1.0f, 0.55f, 1.0f); // the player start's green (viewport_lines.cpp)

// The level's name, player start, settings fields, ambient Audition and on_start links.
void level_settings(const PanelContext& ctx, FieldWidgets& widgets) {
    Editor& editor = ctx.editor;
    char name[128];
    std::snprintf(name, sizeof(name), "%s", editor.level().name.c_str());
    ImGui::SetNextItemWidth(-90);
    if (ImGui::InputText("Level name", name, sizeof(name), ImGuiInputTextFlags_EnterReturnsTrue))
        ctx.report(rename_level(editor, name), "rename");
    level::PlayerStart start = editor.level().player_start;
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat3("Start", &start.position.x, 0.1f))
        ctx.report(set_player_start(editor, start, "settings:player_start"), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat("Start yaw", &start.yaw, 1.0f, -360.0f, 360.0f, "%.0f deg"))
        ctx.report(set_player_start(editor, start, "settings:player_start"), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
    if (ImGui::Button("Player start at camera")) {
        const geometry::Camera& camera = ctx.window.viewport_camera().camera;
        level::PlayerStart at = start;
        at.position = camera.position - Vec3(0, 3, 0);
        at.yaw = std::remainder(degrees(camera.yaw), 360.0f);
        ctx.report(set_player_start(editor, at), "player start");
    }
    ImGui::Separator();
    for (const auto& field : describe_settings_fields()) {
        auto value = get_settings_field(editor.level().settings, field.name);
        if (!value) continue;
        ImGui::PushID(field.name.c_str());
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(field.name.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", field.tooltip.c_str());
        ImGui::SameLine(150);
        ImGui::SetNextItemWidth(-1);
        FieldValue edited = *value;
        if (widgets.edit(ctx, field, edited, false)) {
            ctx.report(set_setting(editor, field.name, edited, "settings:" + field.name), field.name.c_str());
            if (field.kind == FieldKind::Sound || widgets.typed_commit())
                editor.end_merging(); // each name picked, each number typed, is its own step
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
        ImGui::PopID();
    }
    audition_button(ctx.audition, editor.level().settings.ambient_sound.value, 1.0f);
    ImGui::Separator();
    ImGui::TextDisabled("When the level starts (on_start):");
    ImGui::PushID("level_links");
    ctx.window.link_list(LinkOwner::level(), "level_link");
    ImGui::PopID();
}

// The player start alone: its position and yaw, placed at the camera, focused.
class PlayerStartSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return s.entities.empty() && s.player_start; }
    void draw(const PanelContext& ctx, InspectorSelection&, FieldWidgets&) override {
        Editor& editor = ctx.editor;
        ImGui::TextColored(kStartTitleText, "Player start");
        ImGui::Separator();
        level::PlayerStart start = editor.level().player_start;
        ImGui::SetNextItemWidth(-90);
        if (ImGui::DragFloat3("position", &start.position.x, 0.1f, 0.0f, 0.0f, "%g"))
            ctx.report(set_player_start(editor, start, "inspector:player_start"), "player start");
        if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
        ImGui::SetNextItemWidth(-90);
        if (ImGui::DragFloat("yaw", &start.yaw, 1.0f, -180.0f, 180.0f, "%.0f deg"))
            ctx.report(set_player_start(editor, start, "inspector:player_start"), "player start");
        if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped(
            "The player's feet and facing (yaw 0 faces -z). In the viewport: W moves it, E turns it "
            "(the y ring), F focuses on it; F5 play-tests from it.");
        ImGui::PopStyleColor();
        if (ImGui::Button("Player start at camera")) {
            const geometry::Camera& camera = ctx.window.viewport_camera().camera;
            level::PlayerStart at = start;
            at.position = camera.position - Vec3(0, level::kPlayerHeight, 0);
            at.yaw = std::remainder(degrees(camera.yaw), 360.0f);
            ctx.report(set_player_start(editor, at), "player start");
        }
        ImGui::SameLine();
        if (ImGui::Button("Focus")) ctx.window.focus_selection();
    }
};

// Nothing selected: the level's settings.
class LevelSettingsSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return s.entities.empty() && !s.player_start; }
    void draw(const PanelContext& ctx, InspectorSelection&, FieldWidgets& widgets) override {
        ImGui::TextDisabled("Nothing selected: level settings");
        level_settings(ctx, widgets);
    }
};

// The selection's type and id, or how many are selected.
class SelectionTitleSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return !s.entities.empty(); }
    void draw(const PanelContext&, InspectorSelection& s, FieldWidgets&) override {
        const level::Entity& primary = s.primary();
        if (s.group_shown) // one whole group: the fields below are its first member's
            ImGui::TextColored(type_colour(primary.type()), "%s  #%d%s", type_label(primary.type()),
                               primary.id, s.entities.size() > 1 ? "  (common fields)" : "");
        else if (s.entities.size() == 1)
            ImGui::TextColored(type_colour(primary.type()), "%s  #%d", type_label(primary.type()),
                               primary.id);
        else
            ImGui::TextColored(ImVec4(0.9f, 0.9f, 1, 1), "%zu selected (common fields; grey = values differ)",
                               s.entities.size());
        ImGui::Separator();
    }
};

// The fields the selected entities share: name, value (grey where they differ), revert to default.
class FieldTableSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return !s.entities.empty(); }
    void draw(const PanelContext& ctx, InspectorSelection& s, FieldWidgets& widgets) override {
        Editor& editor = ctx.editor;
        const level::Entity& primary = s.primary();
        const auto fields = common_fields(s.entities);
        const PrimaryOverrides overrides = primary_overrides(editor);
        // The name column is as wide as this type's longest field name (capped), the values get the rest.
        float name_w = 0;
        for (const auto& field : fields) name_w = std::max(name_w, ImGui::CalcTextSize(field.name.c_str()).x);
        name_w = std::min(name_w + ImGui::GetStyle().CellPadding.x * 2 + 4, s.width * 0.42f);
        if (!ImGui::BeginTable("fields", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg))
            return;
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, name_w);
        ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("reset", ImGuiTableColumnFlags_WidthFixed, 22.0f);
        for (const auto& field : fields) {
            auto value = get_entity_field(primary, field.name);
            if (!value) continue;
            bool mixed = false;
            for (const level::Entity* e : s.entities) {
                auto other = get_entity_field(*e, field.name);
                if (other && *other != *value) mixed = true;
            }
            ImGui::PushID(field.name.c_str());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted(field.name.c_str());
            if (ImGui::IsItemHovered()) tooltip(field);
            override_marker(ctx, overrides, field.name);
            ImGui::TableNextColumn();
            ImGui::SetNextItemWidth(-1);
            FieldValue edited = *value;
            if (widgets.edit(ctx, field, edited, mixed)) {
                ctx.report(set_field(editor, field.name, edited, "inspector:" + field.name),
                           field.name.c_str());
                if (field.kind == FieldKind::Sound || field.kind == FieldKind::Texture ||
                    widgets.typed_commit())
                    editor.end_merging(); // each name picked, each number typed, is its own step
            }
            if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging(); // one drag = one step
            ImGui::TableNextColumn();
            auto def = default_entity_field(primary, field.name);
            const bool is_default = def && *def == *value && !mixed;
            if (!is_default) {
                if (ImGui::SmallButton("R")) ctx.report(revert_field(editor, field.name), "revert");
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("Revert to default: %s", def ? format_field_value(*def).c_str() : "?");
            }
            ImGui::PopID();
        }
        ImGui::EndTable();
    }

  private:
    static void tooltip(const FieldDescriptor& field) {
        std::string tip = field.tooltip;
        if (field.kind == FieldKind::Float || field.kind == FieldKind::Int || field.kind == FieldKind::Vec2 ||
            field.kind == FieldKind::Vec3) {
            char range[96];
            std::snprintf(range, sizeof(range), "\nrange %g .. %g %s", field.min, field.max,
                          field.unit.c_str());
            tip += range;
        }
        ImGui::SetTooltip("%s", tip.c_str());
    }
};

// A robot's patrol: mode, wait and one row per point (x, y, z; add after; remove). Every change is an
// Editor patrol edit, so each is one undo step (a dragged number merges into one).
class PatrolSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override {
        return s.entities.size() == 1 && s.primary().try_as<level::RobotProps>();
    }
    void draw(const PanelContext& ctx, InspectorSelection& s, FieldWidgets&) override {
        Editor& editor = ctx.editor;
        const level::Entity& robot = s.primary();
        const level::Patrol& patrol = robot.as<level::RobotProps>().patrol;
        const int id = robot.id;
        if (!ImGui::CollapsingHeader("Patrol", ImGuiTreeNodeFlags_DefaultOpen)) return;
        if (!patrol.active()) {
            ImGui::TextDisabled("No patrol: the robot wanders");
            if (ImGui::Button("Add patrol point here"))
                ctx.report(patrol_add(editor, id, robot.position), "patrol");
            ctx.spots.here("patrol.add_here");
            return;
        }
        int mode = patrol.ping_pong() ? 1 : 0;
        // Mode and wait share a row, so a robot's route fits under its fields.
        const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
        ImGui::SetNextItemWidth(half - ImGui::CalcTextSize("mode").x - ImGui::GetStyle().ItemInnerSpacing.x);
        if (ImGui::Combo("mode", &mode, "loop\0ping_pong\0"))
            ctx.report(patrol_set_mode(editor, id, mode == 1 ? "ping_pong" : "loop"), "patrol mode");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(half - ImGui::CalcTextSize("wait (s)").x -
                                ImGui::GetStyle().ItemInnerSpacing.x);
        float wait = patrol.wait;
        if (ImGui::DragFloat("wait (s)", &wait, 0.05f, 0.0f, static_cast<float>(level::kMaxPatrolWait),
                             "%.2f"))
            ctx.report(patrol_set_wait(editor, id, wait, "inspector:patrol.wait"), "patrol wait");
        if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
        for (int i = 0; i < static_cast<int>(patrol.points.size()); ++i)
            if (!point_row(ctx, robot, i)) break; // the list changed under the loop
    }

  private:
    // False when the point list changed.
    static bool point_row(const PanelContext& ctx, const level::Entity& robot, int i) {
        Editor& editor = ctx.editor;
        const level::Patrol& patrol = robot.as<level::RobotProps>().patrol;
        const int id = robot.id;
        ImGui::PushID(i);
        Vec3 point = patrol.points[static_cast<size_t>(i)];
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 70.0f);
        char label[16];
        std::snprintf(label, sizeof label, "%d", i);
        if (ImGui::DragFloat3(label, &point.x, 0.1f, 0.0f, 0.0f, "%.2f"))
            ctx.report(patrol_move(editor, id, i, point, "inspector:patrol." + std::to_string(i)),
                       "patrol point");
        if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
        ImGui::SameLine();
        if (ImGui::SmallButton("+")) {
            // A new point halfway to the next one (or a step on from the last), where it is easy to drag.
            const size_t next = static_cast<size_t>(i) + 1;
            const Vec3 at = next < patrol.points.size()
                                ? (patrol.points[static_cast<size_t>(i)] + patrol.points[next]) * 0.5f
                                : patrol.points[static_cast<size_t>(i)] + Vec3(2, 0, 0);
            ctx.report(patrol_add(editor, id, at, i), "patrol add");
            ImGui::PopID();
            return false;
        }
        ctx.spots.here("patrol" + std::to_string(i) + ".add");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add a point after this one");
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) {
            ctx.report(patrol_remove(editor, id, i), "patrol remove");
            ImGui::PopID();
            return false;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this point");
        ImGui::PopID();
        return true;
    }
};

// One sound emitter: Audition plays its sound at its volume.
class SoundAuditionSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override {
        return s.entities.size() == 1 && s.primary().try_as<level::SoundProps>();
    }
    void draw(const PanelContext& ctx, InspectorSelection& s, FieldWidgets&) override {
        const auto& sound = s.primary().as<level::SoundProps>();
        audition_button(ctx.audition, sound.sound.value, sound.volume);
    }
};

// Duplicate, Delete, Focus: one row under the title, so a long field table never pushes them out of a
// 1280 x 720 window.
class SelectionActionsSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return !s.entities.empty(); }
    void draw(const PanelContext& ctx, InspectorSelection&, FieldWidgets&) override {
        if (ImGui::SmallButton("Duplicate")) ctx.report(duplicate(ctx.editor), "duplicate");
        ctx.spots.here("inspector.duplicate");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("A copy one grid step along x, selected (Ctrl+D)");
        ImGui::SameLine();
        if (ImGui::SmallButton("Delete")) ctx.report(delete_selection(ctx.editor), "delete");
        ctx.spots.here("inspector.delete");
        ImGui::SameLine();
        if (ImGui::SmallButton("Focus")) ctx.window.focus_selection();
        ImGui::Separator();
    }
};

// Under a selection: the level settings, folded.
class FoldedLevelSettingsSection final : public InspectorSection {
  public:
    bool applies(const InspectorSelection& s) const override { return !s.entities.empty(); }
    void draw(const PanelContext& ctx, InspectorSelection&, FieldWidgets& widgets) override {
        if (ImGui::CollapsingHeader("Level settings")) level_settings(ctx, widgets);
    }
};

template <class Section>
void add(std::vector<std::unique_ptr<InspectorSection>>& sections) {
    sections.push_back(std::make_unique<Section>());
}
} // namespace

std::vector<std::unique_ptr<InspectorSection>> make_inspector_sections() {
    std::vector<std::unique_ptr<InspectorSection>> sections;
    sections.push_back(make_face_section()); // first: shown above whatever else applies
    add<PlayerStartSection>(sections);
    add<LevelSettingsSection>(sections);
    sections.push_back(make_group_section());
    add<SelectionTitleSection>(sections);
    add<SelectionActionsSection>(sections); // above the fields: on screen however many fields follow
    add<FieldTableSection>(sections);
    add<PatrolSection>(sections);
    add<SoundAuditionSection>(sections);
    add<FoldedLevelSettingsSection>(sections);
    return sections;
}

} // namespace ks::editor::ui
