// The side and bottom panels: outliner, palette, inspector (with level settings), validation, history, log.
#include "ui/editor_app.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
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

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus;

void place_panel(float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
}

bool contains_text(const std::string& haystack, const char* needle) {
    if (!*needle) return true;
    std::string a = haystack, b = needle;
    for (auto& c : a) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (auto& c : b) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return a.find(b) != std::string::npos;
}

const char* type_label(level::EntityType t) {
    static std::string names[static_cast<size_t>(level::EntityType::Count)];
    auto& n = names[static_cast<size_t>(t)];
    if (n.empty()) n = std::string(level::type_name(t));
    return n.c_str();
}

ImVec4 type_colour(level::EntityType t) {
    switch (t) {
    case level::EntityType::Wall:
    case level::EntityType::Floor:
    case level::EntityType::Stair:
        return ImVec4(0.7f, 0.74f, 0.8f, 1);
    case level::EntityType::Door:
        return ImVec4(0.55f, 0.8f, 1.0f, 1);
    case level::EntityType::FloorLight:
    case level::EntityType::TopLight:
        return ImVec4(1.0f, 0.88f, 0.45f, 1);
    case level::EntityType::Robot:
        return ImVec4(1.0f, 0.5f, 0.45f, 1);
    case level::EntityType::Pickup:
        return ImVec4(0.5f, 1.0f, 0.6f, 1);
    case level::EntityType::GasCylinder:
        return ImVec4(1.0f, 0.65f, 0.3f, 1);
    case level::EntityType::ControlPanel:
        return ImVec4(0.8f, 0.6f, 1.0f, 1);
    case level::EntityType::Sound:
        return ImVec4(1.0f, 0.5f, 0.85f, 1);
    default:
        return ImVec4(1, 1, 1, 1);
    }
}
} // namespace

void EditorApp::palette_bar() {
    ImGui::TextDisabled("Place:");
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    bool first = true;
    for (auto type : level::all_types()) {
        const float w = ImGui::CalcTextSize(type_label(type)).x + ImGui::GetStyle().FramePadding.x * 2;
        if (!first) {
            ImGui::SameLine();
            if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w > right) ImGui::NewLine();
        }
        first = false;
        const bool active = placing_ && *placing_ == type;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
        ImGui::PushStyleColor(ImGuiCol_Text, type_colour(type));
        if (ImGui::SmallButton(type_label(type))) placing_ = type;
        ImGui::PopStyleColor(active ? 2 : 1);
        palette_rects_[static_cast<size_t>(type)] = {
            Vec2(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y),
            Vec2(ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y)};
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Click, then click in the viewport to place a %s on the surface under the cursor "
                "(snapped to the grid). Shift+click places several.",
                type_label(type));
    }
}

void EditorApp::viewport_toolbar() {
    for (GizmoMode m : {GizmoMode::Move, GizmoMode::Rotate, GizmoMode::Scale}) {
        if (ImGui::RadioButton(gizmo_mode_name(m), gizmo_.mode == m)) gizmo_.mode = m;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo mode (W / E / R)");
        ImGui::SameLine();
    }
    ImGui::TextDisabled("|");
    for (ViewMode v : {ViewMode::Perspective, ViewMode::Top, ViewMode::Front, ViewMode::Side}) {
        ImGui::SameLine();
        const bool active = view_.mode == v;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.26f, 0.45f, 0.75f, 1));
        if (ImGui::SmallButton(view_mode_name(v))) set_view(v);
        if (active) ImGui::PopStyleColor();
    }
    ImGui::SameLine();
    ImGui::TextDisabled("|");
    ImGui::SameLine();
    ImGui::Checkbox("Snap", &editor_.grid().snap);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::DragFloat("##grid", &editor_.grid().step, 0.05f, 0.05f, 16.0f, "%.2f u");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Grid step (origin snapping, nudge distance)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::DragFloat("##rot", &editor_.grid().rotation_step, 0.5f, 1.0f, 90.0f, "%.0f deg");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rotation snapping step");
}

void EditorApp::outliner_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Outliner", nullptr, kPanelFlags);
    if (!dojo_tab_) {
        palette_bar();
        ImGui::Separator();
    }
    ImGui::SetNextItemWidth(-1);
    const char* preview =
        type_filter_ < 0 ? "All types" : type_label(static_cast<level::EntityType>(type_filter_));
    if (ImGui::BeginCombo("##type", preview)) {
        if (ImGui::Selectable("All types", type_filter_ < 0)) type_filter_ = -1;
        for (auto t : level::all_types())
            if (ImGui::Selectable(type_label(t), type_filter_ == static_cast<int>(t)))
                type_filter_ = static_cast<int>(t);
        ImGui::EndCombo();
    }
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##search", "Search names...", search_, sizeof(search_));
    if (type_filter_ >= 0 && ImGui::Button("Select all of this type", ImVec2(-1, 0)))
        editor_.select_all_of_type(static_cast<level::EntityType>(type_filter_));

    // Issue count per entity, for the warning badges.
    const auto& issues = editor_.issues();
    ImGui::BeginChild("entities", ImVec2(0, 0), false);
    const Document& doc = editor_.doc();
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(4, 2));
    for (const auto& e : doc.level.entities) {
        if (type_filter_ >= 0 && static_cast<int>(e.type()) != type_filter_) continue;
        const std::string label = e.name.empty() ? std::string(level::type_name(e.type())) : e.name;
        if (!contains_text(label, search_) &&
            !contains_text(std::string(level::type_name(e.type())), search_))
            continue;
        ImGui::PushID(e.id);
        const bool hidden = doc.hidden.contains(e.id), locked = doc.locked.contains(e.id);
        ImGui::PushStyleColor(ImGuiCol_Text,
                              hidden ? ImVec4(0.45f, 0.45f, 0.5f, 1) : ImVec4(0.8f, 0.85f, 0.95f, 1));
        if (ImGui::SmallButton(hidden ? "-" : "o")) editor_.set_hidden(e.id, !hidden);
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(hidden ? "Hidden: click to show" : "Visible: click to hide");
        ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Text,
                              locked ? ImVec4(1.0f, 0.7f, 0.3f, 1) : ImVec4(0.45f, 0.45f, 0.5f, 1));
        if (ImGui::SmallButton(locked ? "L" : ".")) editor_.set_locked(e.id, !locked);
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(locked ? "Locked: click to unlock" : "Click to lock (no picking)");
        ImGui::SameLine();
        int errors = 0, warnings = 0;
        for (const auto& issue : issues)
            if (issue.entity_id == e.id) (issue.severity == IssueSeverity::Error ? errors : warnings)++;
        char row[160];
        std::snprintf(row, sizeof(row), "%-4d %s", e.id, label.c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, type_colour(e.type()));
        const float badge_w = (errors || warnings) ? 22.0f : 0.0f;
        if (ImGui::Selectable(row, doc.is_selected(e.id), ImGuiSelectableFlags_AllowDoubleClick,
                              ImVec2(ImGui::GetContentRegionAvail().x - badge_w, 0))) {
            const ImGuiIO& io = ImGui::GetIO();
            const SelectMode mode = io.KeyCtrl    ? SelectMode::Toggle
                                    : io.KeyShift ? SelectMode::Add
                                                  : SelectMode::Replace;
            report(editor_.select({e.id}, mode), "select");
            if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) focus_selection();
        }
        ImGui::PopStyleColor();
        if (!doc.selection.empty() && doc.selection.front() == e.id && outliner_scrolled_to_ != e.id) {
            ImGui::SetScrollHereY(0.5f); // picked in the viewport: bring its row into view
            outliner_scrolled_to_ = e.id;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s #%d", type_label(e.type()), e.id);
        if (errors || warnings) {
            ImGui::SameLine();
            ImGui::TextColored(errors ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(1, 0.8f, 0.3f, 1), "!%d",
                               errors + warnings);
            if (ImGui::IsItemHovered()) {
                std::string tip;
                for (const auto& issue : issues)
                    if (issue.entity_id == e.id) tip += issue.message + "\n";
                ImGui::SetTooltip("%s", tip.c_str());
            }
        }
        ImGui::PopID();
    }
    ImGui::PopStyleVar();
    ImGui::EndChild();
    ImGui::End();
}

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
    }
    if (mixed) ImGui::PopStyleColor();
    return changed;
}

void EditorApp::inspector_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Inspector", nullptr, kPanelFlags);
    const auto selected = editor_.selected_entities();
    if (selected.empty()) {
        ImGui::TextDisabled("Nothing selected: level settings");
        settings_section();
        ImGui::End();
        return;
    }
    const level::Entity& primary = *selected.front();
    if (selected.size() == 1)
        ImGui::TextColored(type_colour(primary.type()), "%s  #%d", type_label(primary.type()), primary.id);
    else
        ImGui::TextColored(ImVec4(0.9f, 0.9f, 1, 1), "%zu selected (common fields; grey = values differ)",
                           selected.size());
    ImGui::Separator();
    const auto fields = common_fields(selected);
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
            ImGui::TableNextColumn();
            ImGui::SetNextItemWidth(-1);
            FieldValue edited = *value;
            if (field_widget(field, edited, mixed)) {
                report(editor_.set_field(field.name, edited, "inspector:" + field.name), field.name.c_str());
                if (field.kind == FieldKind::Sound) editor_.end_merging(); // each name picked is its own step
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
    ImGui::End();
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
        report(editor_.set_player_start(start), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging();
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat("Start yaw", &start.yaw, 1.0f, -360.0f, 360.0f, "%.0f deg"))
        report(editor_.set_player_start(start), "player start");
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
}

void EditorApp::validation_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    const auto& issues = editor_.issues();
    const int errors = count_errors(issues);
    char title[96];
    std::snprintf(title, sizeof(title), "Validation: %d errors, %d warnings###Validation", errors,
                  static_cast<int>(issues.size()) - errors);
    ImGui::Begin(title, nullptr, kPanelFlags);
    if (issues.empty())
        ImGui::TextColored(ImVec4(0.4f, 1.0f, 0.5f, 1), "No problems: the level is ready to play.");
    for (size_t i = 0; i < issues.size(); ++i) {
        const Issue issue = issues[i]; // a copy: a fix changes the list
        ImGui::PushID(static_cast<int>(i));
        const bool error = issue.severity == IssueSeverity::Error;
        ImGui::TextColored(error ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(1, 0.8f, 0.3f, 1), "%s",
                           error ? "ERR " : "WARN");
        ImGui::SameLine();
        ImGui::PushTextWrapPos(w - (issue.fix.kind != QuickFix::Kind::None ? 110.0f : 12.0f));
        char line[512];
        std::snprintf(line, sizeof(line), "[%s] %s", rule_name(issue.rule), issue.message.c_str());
        if (ImGui::Selectable(line, false)) report(editor_.select_issue(issue), "select");
        ImGui::PopTextWrapPos();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Click to select the entity this is about");
        if (issue.fix.kind != QuickFix::Kind::None) {
            ImGui::SameLine(w - 104);
            if (ImGui::SmallButton(issue.fix.label.c_str())) {
                report(editor_.apply_quick_fix(issue), "quick fix");
                ImGui::PopID();
                break;
            }
        }
        ImGui::PopID();
    }
    ImGui::End();
}

void EditorApp::history_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("History", nullptr, kPanelFlags);
    const auto& history = editor_.history();
    const auto names = history.step_names();
    const int done = static_cast<int>(history.undo_count());
    int target = -1;
    if (ImGui::Selectable("(opened)", done == 0)) target = 0;
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
        ImGui::PushID(i);
        ImGui::PushStyleColor(ImGuiCol_Text,
                              i < done ? ImVec4(0.9f, 0.92f, 1, 1) : ImVec4(0.5f, 0.5f, 0.55f, 1));
        char label[160];
        std::snprintf(label, sizeof(label), "%3d  %s", i + 1, names[static_cast<size_t>(i)].c_str());
        if (ImGui::Selectable(label, i + 1 == done)) target = i + 1;
        ImGui::PopStyleColor();
        ImGui::PopID();
    }
    if (target >= 0) { // jump: undo or redo until `target` steps are done
        while (static_cast<int>(editor_.history().undo_count()) > target && editor_.undo()) {
        }
        while (static_cast<int>(editor_.history().undo_count()) < target && editor_.redo()) {
        }
    }
    ImGui::End();
}

void EditorApp::log_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Log", nullptr, kPanelFlags);
    if (ImGui::SmallButton("Clear")) log_.clear();
    ImGui::SameLine();
    ImGui::TextDisabled("editor messages, and the play-test's output");
    ImGui::BeginChild("lines");
    for (const auto& [line, error] : log_) {
        if (error)
            ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", line.c_str());
        else
            ImGui::TextUnformatted(line.c_str());
    }
    if (scroll_log_) ImGui::SetScrollHereY(1.0f), scroll_log_ = false;
    ImGui::EndChild();
    ImGui::End();
}

} // namespace ks::editor::ui
