#include "model/edit_models.h"

#include "model/field_access.h"
#include "model/rotation.h"
#include "modelio/model_files.h"

#include <cmath>
#include <filesystem>

namespace ks::editor {

Result<int> place_model(Editor& editor, const std::string& file, Vec3 position, float yaw_degrees) {
    if (Result<void> name = modelio::check_model_name(file); !name)
        return Error("place model: " + name.error().message, Location{}, name.error().hint);
    if (!is_finite(position) || !std::isfinite(yaw_degrees))
        return Error("place model: position and yaw must be finite numbers");
    const Document& doc = editor.doc();
    level::Entity e;
    e.id = doc.level.next_id;
    e.name = std::filesystem::path(file).stem().string();
    e.rotation = {wrap_degrees(doc.grid.snap_angle(yaw_degrees)), 0, 0};
    e.props = level::default_props(level::EntityType::Model);
    e.as<level::ModelProps>().file = file;
    if (auto r = set_entity_field(e, "position", doc.grid.snap_point(position)); !r)
        return Error("place model: " + r.error().message, Location{}, r.error().hint);
    auto change = std::make_unique<LevelChange>();
    change->set_name("Place model " + e.name);
    change->insertions.push_back({doc.level.entities.size(), e});
    change->next_id = Change<int>{doc.level.next_id, doc.level.next_id + 1};
    editor.execute(std::move(change), {e.id});
    return e.id;
}

} // namespace ks::editor
