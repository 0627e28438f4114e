#include "view/face_picking.h"

#include "brush/brush_query.h"
#include "level/entity_shapes.h"
#include "model/edit_faces.h"

namespace ks::editor {

std::optional<FacePick> pick_face(const Document& doc, const geometry::Ray& ray, const ShownFn& shown) {
    const PickHit hit = pick_entity(doc, ray, shown);
    if (hit.id <= 0) return std::nullopt;
    const level::Entity* e = doc.level.find(hit.id);
    if (!e || e->type() != level::EntityType::Brush) return std::nullopt;
    const auto world = level::world_brush(*e);
    if (!world) return std::nullopt;
    const auto entry = brush::ray_entry_face(*world, DVec3(ray.origin), DVec3(ray.direction));
    if (!entry) return std::nullopt;
    return FacePick{e->id, entry->face, static_cast<float>(entry->distance)};
}

Result<void> click_face(Editor& editor, const std::optional<FacePick>& picked) {
    if (!picked) {
        clear_face_selection(editor);
        return ok();
    }
    return select_face(editor, picked->entity, picked->face, SelectMode::Toggle);
}

bool begin_face_drag(FaceDrag& drag, Editor& editor, const geometry::Ray& ray, const ShownFn& shown,
                     FaceDragMode mode) {
    if (editor.doc().faces.empty()) return false;
    const auto picked = pick_face(editor.doc(), ray, shown);
    if (!picked) return false;
    const DVec3 point = DVec3(ray.origin) + DVec3(ray.direction) * double(picked->distance);
    return drag.begin(editor, picked->entity, picked->face, point, mode);
}

} // namespace ks::editor
