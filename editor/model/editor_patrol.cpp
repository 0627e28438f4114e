// Editor: robot patrol edits. Each builds one LevelChange updating the robot and executes it through History.
#include "model/editor.h"
#include "model/patrol_edit.h"

namespace ks::editor {

Result<void> Editor::edit_patrol(int id, std::string name,
                                 const std::function<Result<void>(level::Patrol&)>& edit,
                                 std::string merge_key) {
    const level::Entity* current = doc_.level.find(id);
    if (!current) return Error(name + ": no entity with id " + std::to_string(id));
    if (!current->try_as<level::RobotProps>())
        return Error(name + ": entity " + std::to_string(id) + " is a " +
                         std::string(level::type_name(current->type())) + ", not a robot",
                     Location{}, "patrols belong to robots");
    if (doc_.locked.contains(id))
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
    execute(std::move(change), doc_.selection);
    return ok();
}

Result<void> Editor::patrol_add(int id, Vec3 point, std::optional<int> after) {
    return edit_patrol(id, "Add patrol point",
                       [&](level::Patrol& patrol) { return add_patrol_point(patrol, point, after); });
}

Result<void> Editor::patrol_move(int id, int index, Vec3 point, std::string merge_key) {
    return edit_patrol(
        id, "Move patrol point",
        [&](level::Patrol& patrol) { return move_patrol_point(patrol, index, point); }, std::move(merge_key));
}

Result<void> Editor::patrol_remove(int id, int index) {
    return edit_patrol(id, "Remove patrol point",
                       [&](level::Patrol& patrol) { return remove_patrol_point(patrol, index); });
}

Result<void> Editor::patrol_set_mode(int id, std::string_view mode) {
    return edit_patrol(id, "Set patrol mode",
                       [&](level::Patrol& patrol) { return set_patrol_mode(patrol, mode); });
}

Result<void> Editor::patrol_set_wait(int id, float seconds, std::string merge_key) {
    return edit_patrol(
        id, "Set patrol wait", [&](level::Patrol& patrol) { return set_patrol_wait(patrol, seconds); },
        std::move(merge_key));
}

} // namespace ks::editor
