// Robot patrol edits: edit_patrols.h. Each builds one LevelChange updating the robot and executes it
// through the Editor.
#include "model/edit_patrols.h"

#include "model/patrol_edit.h"

namespace ks::editor {
namespace {

Result<void> edit_patrol(Editor& editor, int id, std::string name,
                         const std::function<Result<void>(level::Patrol&)>& edit,
                         std::string merge_key = {}) {
    const Document& doc = editor.doc();
    const level::Entity* current = doc.level.find(id);
    if (!current) return Error(name + ": no entity with id " + std::to_string(id));
    if (!current->try_as<level::RobotProps>())
        return Error(name + ": entity " + std::to_string(id) + " is a " +
                         std::string(level::type_name(current->type())) + ", not a robot",
                     Location{}, "patrols belong to robots");
    if (doc.locked.contains(id))
        return Error(name + ": robot " + std::to_string(id) + " is locked", Location{}, "unlock it first");
    level::Entity after = *current;
    if (auto r = edit(after.as<level::RobotProps>().patrol); !r) {
        Error e = r.error();
        e.message = name + ": robot " + std::to_string(id) + ": " + e.message;
        return e;
    }
    if (after == *current) return ok(); // nothing changed: no history step
    auto change = std::make_unique<LevelChange>();
    change->set_name(std::move(name));
    change->merge_key = std::move(merge_key);
    change->updates.push_back({*current, std::move(after)});
    editor.execute(std::move(change), doc.selection);
    return ok();
}
} // namespace

Result<void> patrol_add(Editor& editor, int id, Vec3 point, std::optional<int> after) {
    return edit_patrol(editor, id, "Add patrol point",
                       [&](level::Patrol& patrol) { return add_patrol_point(patrol, point, after); });
}

Result<void> patrol_move(Editor& editor, int id, int index, Vec3 point, std::string merge_key) {
    return edit_patrol(
        editor, id, "Move patrol point",
        [&](level::Patrol& patrol) { return move_patrol_point(patrol, index, point); }, std::move(merge_key));
}

Result<void> patrol_remove(Editor& editor, int id, int index) {
    return edit_patrol(editor, id, "Remove patrol point",
                       [&](level::Patrol& patrol) { return remove_patrol_point(patrol, index); });
}

Result<void> patrol_set_mode(Editor& editor, int id, std::string_view mode) {
    return edit_patrol(editor, id, "Set patrol mode",
                       [&](level::Patrol& patrol) { return set_patrol_mode(patrol, mode); });
}

Result<void> patrol_set_wait(Editor& editor, int id, float seconds, std::string merge_key) {
    return edit_patrol(
        editor, id, "Set patrol wait",
        [&](level::Patrol& patrol) { return set_patrol_wait(patrol, seconds); }, std::move(merge_key));
}

} // namespace ks::editor
