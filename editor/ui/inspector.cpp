// The inspector: the selected entities' fields (common fields of several), a robot's patrol, and the level
// settings when nothing is selected.
#include "ui/editor_app.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace ks::editor::ui {

namespace {
using Report = std::function<void(const Result<void>&, const char*)>;

// A robot's patrol: mode, wait and one row per point (x, y, z; add after; remove). Every change is an
// Editor patrol edit, so each is one undo step (a dragged number merges into one).
void patrol_section(Editor& editor, const level::Entity& robot, const Report& report) {
    const level::Patrol& patrol = robot.as<level::RobotProps>().patrol;
    const int id = robot.id;
    if (!ImGui::CollapsingHeader("Patrol", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!patrol.active()) {
        ImGui::TextDisabled("No patrol: the robot wanders");
        if (ImGui::Button("Add patrol point here")) report(editor.patrol_add(id, robot.position), "patrol");
        return;
    }
    int mode = patrol.ping_pong() ? 1 : 0;
    if (ImGui::Combo("mode", &mode, "loop\0ping_pong\0"))
        report(editor.patrol_set_mode(id, mode == 1 ? "ping_pong" : "loop"), "patrol mode");
    float wait = patrol.wait;
    if (ImGui::DragFloat("wait (s)", &wait, 0.05f, 0.0f, static_cast<float>(level::kMaxPatrolWait), "%.2f"))
        report(editor.patrol_set_wait(id, wait, "inspector:patrol.wait"), "patrol wait");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
    for (int i = 0; i < static_cast<int>(patrol.points.size()); ++i) {
        ImGui::PushID(i);
        Vec3 point = patrol.points[static_cast<size_t>(i)];
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 70.0f);
        char label[16];
        std::snprintf(label, sizeof label, "%d", i);
        if (ImGui::DragFloat3(label, &point.x, 0.1f, 0.0f, 0.0f, "%.2f"))
            report(editor.patrol_move(id, i, point, "inspector:patrol." + std::to_string(i)), "patrol point");
        if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
        ImGui::SameLine();
        if (ImGui::SmallButton("+")) {
            // A new point halfway to the next one (or a step on from the last), where it is easy to drag.
            const size_t next = static_cast<size_t>(i) + 1;
            const Vec3 at = next < patrol.points.size()
                                ? (patrol.points[static_cast<size_t>(i)] + patrol.points[next]) * 0.5f
                                : patrol.points[static_cast<size_t>(i)] + Vec3(2, 0, 0);
            report(editor.patrol_add(id, at, i), "patrol add");
            ImGui::PopID();
            break; // the list changed under the loop
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add a point after this one");
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) {
            report(editor.patrol_remove(id, i), "patrol remove");
            ImGui::PopID();
            break; // the list changed under the loop
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this point");
        ImGui::PopID();
    }
}
} // namespace

bool EditorApp::field_widget(const FieldDescriptor& field, FieldValue& value, bool mixed) {
    const char* id = "##value";
    bool changed = false;
    if (mixed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 0.6f, 0.65f, 1));
    const float lo = static_cast<float>(field.min), hi = static_cast<float>(field.max);
    const float speed = std::clamp((hi - lo) / 400.0f, 0.01f, 0.25f);
    switch (field.kind) {
    case FieldKind::Float: {
        float v = static_cast<float>(std::get<double>(value));
        // A slider's range spanning decades (a radius) is logarithmic, so small values stay reachable.
        if (field.slider)
            changed = ImGui::SliderFloat(id, &v, lo, hi, "%.2f",
                                         ImGuiSliderFlags_AlwaysClamp |
                                             (lo > 0 && hi >= lo * 100 ? ImGuiSliderFlags_Logarithmic : 0));
        else
            changed = ImGui::DragFloat(id, &v, speed, lo, hi, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = static_cast<double>(v);
        break;
    }
    case FieldKind::Int: {
        int v = static_cast<int>(std::get<double>(value));
        changed = ImGui::DragInt(id, &v, 0.2f, static_cast<int>(field.min), static_cast<int>(field.max), "%d",
                                 ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = static_cast<double>(v);
        break;
    }
    case FieldKind::Bool: {
        bool v = std::get<bool>(value);
        changed = ImGui::Checkbox(id, &v);
        if (changed) value = v;
        break;
    }
    case FieldKind::String: {
        char buffer[256];
        std::snprintf(buffer, sizeof(buffer), "%s", std::get<std::string>(value).c_str());
        changed = ImGui::InputText(id, buffer, sizeof(buffer), ImGuiInputTextFlags_EnterReturnsTrue);
        if (changed) value = std::string(buffer);
        break;
    }
    case FieldKind::Vec2: {
        Vec2 v = std::get<Vec2>(value);
        // %g: "55" and "-90" instead of "55.00" and "-90.00", so three components fit a narrow inspector.
        changed = ImGui::DragFloat2(id, &v.x, speed, lo, hi, "%g", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = v;
        break;
    }
    case FieldKind::Vec3: {
        Vec3 v = std::get<Vec3>(value);
        changed = ImGui::DragFloat3(id, &v.x, speed, lo, hi, "%g", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = v;
        break;
    }
    case FieldKind::Color: {
        level::Color c = std::get<level::Color>(value);
        float rgb[3] = {c.r, c.g, c.b};
        changed = ImGui::ColorEdit3(id, rgb, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_DisplayHex);
        if (changed) value = level::Color{rgb[0], rgb[1], rgb[2]};
        break;
    }
    case FieldKind::Choice: {
        const std::string current = std::get<std::string>(value);
        if (ImGui::BeginCombo(id, current.c_str())) {
            for (const auto& option : field.options)
                if (ImGui::Selectable(option.c_str(), option == current)) value = option, changed = true;
            ImGui::EndCombo();
        }
        break;
    }
    case FieldKind::Sound: {
        std::string name = std::get<std::string>(value);
        changed = sound_name_widget(id, name, sound_names_);
        if (changed) value = name;
        break;
    }
    case FieldKind::Texture:
        changed = texture_field_widget(value);
        break;
    }
    if (mixed) ImGui::PopStyleColor();
    return changed;
}

std::optional<InspectorTab> parse_inspector_tab(std::string_view name) {
    if (name == "properties") return InspectorTab::Properties;
    if (name == "links") return InspectorTab::Links;
    if (name == "objectives") return InspectorTab::Objectives;
    return std::nullopt;
}

void EditorApp::inspector_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Inspector", nullptr, kPanelFlags);
    if (ImGui::BeginTabBar("inspector_tabs")) {
        auto flags = [this](InspectorTab tab) {
            return select_tab_ == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
        };
        const bool properties = ImGui::BeginTabItem("Properties", nullptr, flags(InspectorTab::Properties));
        spots_.here("tab.properties");
        if (properties) {
            shown_tab_ = InspectorTab::Properties;
            selection_inspector(w);
            ImGui::EndTabItem();
        }
        const auto selected = editor_.selected_entities();
        char links_title[48];
        std::snprintf(links_title, sizeof links_title, "Links (%zu)###links",
                      selected.size() == 1 ? selected.front()->links.size() : editor_.level().links.size());
        const bool links = ImGui::BeginTabItem(links_title, nullptr, flags(InspectorTab::Links));
        spots_.here("tab.links");
        if (links) {
            shown_tab_ = InspectorTab::Links;
            links_tab();
            ImGui::EndTabItem();
        }
        char objectives_title[48];
        std::snprintf(objectives_title, sizeof objectives_title, "Objectives (%zu)###objectives",
                      editor_.level().objectives.size());
        const bool objectives =
            ImGui::BeginTabItem(objectives_title, nullptr, flags(InspectorTab::Objectives));
        spots_.here("tab.objectives");
        if (objectives) {
            shown_tab_ = InspectorTab::Objectives;
            objectives_tab();
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
        select_tab_.reset();
    }
    ImGui::End();
}

void EditorApp::selection_inspector(float w) {
    const auto selected = editor_.selected_entities();
    if (selected.empty() && editor_.doc().player_start_selected()) {
        player_start_section();
        return;
    }
    if (selected.empty()) {
        ImGui::TextDisabled("Nothing selected: level settings");
        settings_section();
        return;
    }
    const level::Entity& primary = *selected.front();
    if (group_section()) // one whole group: its name and prefab; the fields below are its first member's
        ImGui::TextColored(type_colour(primary.type()), "%s  #%d%s", type_label(primary.type()), primary.id,
                           selected.size() > 1 ? "  (common fields)" : "");
    else if (selected.size() == 1)
        ImGui::TextColored(type_colour(primary.type()), "%s  #%d", type_label(primary.type()), primary.id);
    else
        ImGui::TextColored(ImVec4(0.9f, 0.9f, 1, 1), "%zu selected (common fields; grey = values differ)",
                           selected.size());
    ImGui::Separator();
    const auto fields = common_fields(selected);
    const PrimaryOverrides overrides = primary_overrides();
    // The name column is as wide as this type's longest field name (capped), the values get the rest.
    float name_w = 0;
    for (const auto& field : fields) name_w = std::max(name_w, ImGui::CalcTextSize(field.name.c_str()).x);
    name_w = std::min(name_w + ImGui::GetStyle().CellPadding.x * 2 + 4, w * 0.42f);
    if (ImGui::BeginTable("fields", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, name_w);
        ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("reset", ImGuiTableColumnFlags_WidthFixed, 22.0f);
        for (const auto& field : fields) {
            auto value = get_entity_field(primary, field.name);
            if (!value) continue;
            bool mixed = false;
            for (const level::Entity* e : selected) {
                auto other = get_entity_field(*e, field.name);
                if (other && *other != *value) mixed = true;
            }
            ImGui::PushID(field.name.c_str());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted(field.name.c_str());
            if (ImGui::IsItemHovered()) {
                std::string tip = field.tooltip;
                if (field.kind == FieldKind::Float || field.kind == FieldKind::Int ||
                    field.kind == FieldKind::Vec2 || field.kind == FieldKind::Vec3) {
                    char range[96];
                    std::snprintf(range, sizeof(range), "\nrange %g .. %g %s", field.min, field.max,
                                  field.unit.c_str());
                    tip += range;
                }
                ImGui::SetTooltip("%s", tip.c_str());
            }
            override_marker(overrides, field.name);
            ImGui::TableNextColumn();
            ImGui::SetNextItemWidth(-1);
            FieldValue edited = *value;
            if (field_widget(field, edited, mixed)) {
                report(editor_.set_field(field.name, edited, "inspector:" + field.name), field.name.c_str());
                if (field.kind == FieldKind::Sound || field.kind == FieldKind::Texture)
                    editor_.end_merging(); // each name picked is its own step
            }
            if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging(); // one drag = one step
            ImGui::TableNextColumn();
            auto def = default_entity_field(primary, field.name);
            const bool is_default = def && *def == *value && !mixed;
            if (!is_default) {
                if (ImGui::SmallButton("R")) report(editor_.revert_field(field.name), "revert");
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("Revert to default: %s", def ? format_field_value(*def).c_str() : "?");
            }
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    if (selected.size() == 1 && primary.try_as<level::RobotProps>())
        patrol_section(editor_, primary,
                       [this](const Result<void>& r, const char* what) { report(r, what); });
    if (const auto* sound = primary.try_as<level::SoundProps>(); sound && selected.size() == 1)
        audition_button(options_.audition, sound->sound.value, sound->volume);
    ImGui::Spacing();
    if (ImGui::Button("Duplicate")) report(editor_.duplicate(), "duplicate");
    ImGui::SameLine();
    if (ImGui::Button("Delete")) report(editor_.delete_selection(), "delete");
    ImGui::SameLine();
    if (ImGui::Button("Focus")) focus_selection();
    if (ImGui::CollapsingHeader("Level settings")) settings_section();
}

// The Links tab: the selected entity's links (what its events set off) and the links that act on it; with
// nothing selected, the level's own (on_start).
void EditorApp::links_tab() {
    const auto selected = editor_.selected_entities();
    if (selected.size() > 1) {
        ImGui::TextWrapped("%zu selected: select one entity to wire its links.", selected.size());
        return;
    }
    if (selected.empty()) {
        ImGui::TextWrapped("Nothing selected: the level's own links, set off when it starts (on_start). "
                           "Select an entity to wire its events.");
        ImGui::PushID("level_links");
        link_list(LinkOwner::level(), "level_link");
        ImGui::PopID();
        return;
    }
    const level::Entity& entity = *selected.front();
    ImGui::TextColored(type_colour(entity.type()), "%s", entity_title(entity).c_str());
    if (!level::entity_events(entity.type()).empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("Each link: on the event, do the action to the target (after the delay; once: "
                           "the first time only).");
        ImGui::PopStyleColor();
    }
    ImGui::PushID("links");
    link_list(LinkOwner::entity(entity.id), "link");
    ImGui::PopID();
    const auto incoming = incoming_links(editor_.level(), entity.id);
    ImGui::Spacing();
    if (incoming.empty()) {
        ImGui::TextDisabled(entity.name.empty() ? "No links act on it (it has no name to be targeted by)"
                                                : "No links act on it");
        return;
    }
    ImGui::TextDisabled("Acted on by:");
    for (size_t i = 0; i < incoming.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string row = incoming[i].source + ": " + incoming[i].label;
        if (ImGui::Selectable(row.c_str(), false) && incoming[i].source_entity != 0)
            report(editor_.select({incoming[i].source_entity}), "select");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(incoming[i].source_entity != 0 ? "Click to select the source"
                                                             : "In the Objectives tab or the level settings");
        ImGui::PopID();
    }
}

void EditorApp::settings_section() {
    char name[128];
    std::snprintf(name, sizeof(name), "%s", editor_.level().name.c_str());
    ImGui::SetNextItemWidth(-90);
    if (ImGui::InputText("Level name", name, sizeof(name), ImGuiInputTextFlags_EnterReturnsTrue))
        report(editor_.rename_level(name), "rename");
    level::PlayerStart start = editor_.level().player_start;
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat3("Start", &start.position.x, 0.1f))
        report(editor_.set_player_start(start, "settings:player_start"), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging();
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat("Start yaw", &start.yaw, 1.0f, -360.0f, 360.0f, "%.0f deg"))
        report(editor_.set_player_start(start, "settings:player_start"), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging();
    if (ImGui::Button("Player start at camera")) {
        level::PlayerStart at = start;
        at.position = view_.camera.position - Vec3(0, 3, 0);
        at.yaw = std::remainder(degrees(view_.camera.yaw), 360.0f);
        report(editor_.set_player_start(at), "player start");
    }
    ImGui::Separator();
    for (const auto& field : describe_settings_fields()) {
        auto value = get_settings_field(editor_.level().settings, field.name);
        if (!value) continue;
        ImGui::PushID(field.name.c_str());
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(field.name.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", field.tooltip.c_str());
        ImGui::SameLine(150);
        ImGui::SetNextItemWidth(-1);
        FieldValue edited = *value;
        if (field_widget(field, edited, false)) {
            report(editor_.set_setting(field.name, edited, "settings:" + field.name), field.name.c_str());
            if (field.kind == FieldKind::Sound) editor_.end_merging(); // each name picked is its own step
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging();
        ImGui::PopID();
    }
    audition_button(options_.audition, editor_.level().settings.ambient_sound.value, 1.0f);
    ImGui::Separator();
    ImGui::TextDisabled("When the level starts (on_start):");
    ImGui::PushID("level_links");
    link_list(LinkOwner::level(), "level_link");
    ImGui::PopID();
}

} // namespace ks::editor::ui
