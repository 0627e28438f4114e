// The viewport's place tool (place_tool.h): the preview boxes where a click would place, and the click.
#include "ui/place_tool.h"
#include "model/edit_entities.h"
#include "model/edit_prefabs.h"
#include "view/model_drop.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace ks::editor::ui {

std::string PlaceTool::label() const {
    if (!model_.empty()) return "model " + model_;
    return type_ ? std::string(level::type_name(*type_)) : "prefab " + prefab_;
}

std::string PlaceTool::hint() const {
    return "Click to place " + label() + "  (Shift: several, Esc: stop)";
}

void PlaceTool::input(const ToolInput& in) {
    if (!in.hovered || !ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    const geometry::Ray ray = in.view.ray(in.mouse);
    const Vec3 at = place_point(in.editor.doc(), ray, in.shown, in.view.pivot);
    if (!model_.empty()) {
        auto placed = place_model_at(in.editor, model_, ray, in.shown, in.view.pivot);
        if (!placed) in.log.line("place model: " + placed.error().str(), true);
    } else if (type_) {
        auto placed = place(in.editor, *type_, placement_for(in.editor.doc(), *type_, at));
        if (!placed) in.log.line("place: " + placed.error().str(), true);
    } else {
        auto placed = place_prefab(in.editor, prefab_, at, 0.0f);
        if (!placed) in.log.line("place prefab: " + placed.error().str(), true);
    }
    if (!ImGui::GetIO().KeyShift) disarm(); // Shift keeps placing
}

// Where a click would place, in every view (the 4-up view's panes too): the entity's box, or each of the
// prefab's entities where it would land. A level ray that meets nothing falls back to the drawn view's pivot.
void PlaceTool::draw_lines(render::DebugDraw& debug, const ToolView& view) const {
    if (!drop_file_.empty() && drop_ray_) { // a thumbnail dragged over a view: where letting go places it
        level::Entity preview;
        preview.position = model_drop_point(view.editor.doc(), *drop_ray_, view.shown, view.view.pivot);
        preview.props = level::default_props(level::EntityType::Model);
        preview.as<level::ModelProps>().file = drop_file_;
        draw_obb(debug, entity_obb(preview), Vec4(0.4f, 1.0f, 0.5f, 0.9f));
        return;
    }
    if (!armed() || !view.mouse_ray) return;
    const Vec3 p = place_point(view.editor.doc(), *view.mouse_ray, view.shown, view.view.pivot);
    if (type_ || !model_.empty()) { // a model's box is its file's (the marker cube while it cannot be read)
        const level::EntityType type = type_ ? *type_ : level::EntityType::Model;
        level::Entity preview;
        preview.position = placement_for(view.editor.doc(), type, p);
        preview.props = level::default_props(type);
        if (!model_.empty()) preview.as<level::ModelProps>().file = model_;
        draw_obb(debug, entity_obb(preview), Vec4(0.4f, 1.0f, 0.5f, 0.9f));
    } else if (const PrefabEntry* entry = view.editor.prefabs().find(prefab_); entry && entry->prefab) {
        for (const level::Entity& local : entry->prefab->entities) {
            level::Entity at = local;
            at.position += p;
            draw_obb(debug, entity_obb(at), Vec4(0.4f, 1.0f, 0.5f, 0.75f));
        }
    }
}

void PlaceTool::status(nlohmann::json& s) const {
    s["placing"] = type_ ? std::string(level::type_name(*type_)) : std::string();
    s["placing_prefab"] = prefab_;
    s["placing_model"] = model_;
    s["dropping_model"] = drop_file_;
}

} // namespace ks::editor::ui
