// The quick fixes (quick_fix.h): apply_quick_fix sends each kind to its own apply_fix overload, one undo
// step through the editor's operations.
#include "model/quick_fix.h"

#include "model/command.h"
#include "model/edit_entities.h"
#include "model/edit_logic.h"
#include "model/edit_patrols.h"
#include "model/edit_prefabs.h"
#include "model/editor.h"

namespace ks::editor {
namespace {

Result<void> apply_fix(Editor&, const Issue& issue, const std::string&, const std::monostate&) {
    return Error("this issue has no quick fix", Location{}, issue.message);
}

// The issue's entity, checked before an edit: it may have gone, or been locked, since the check ran.
Result<const level::Entity*> fixable_entity(const Document& doc, const Issue& issue,
                                            const std::string& name) {
    const level::Entity* current = doc.level.find(issue.entity_id);
    if (!current) return Error(name + ": entity " + std::to_string(issue.entity_id) + " no longer exists");
    if (doc.locked.contains(issue.entity_id))
        return Error(name + ": entity " + std::to_string(issue.entity_id) + " is locked");
    return current;
}

Result<void> apply_fix(Editor& editor, const Issue& issue, const std::string& name,
                       const fixes::SetField& fix) {
    const Document& doc = editor.doc();
    auto current = fixable_entity(doc, issue, name);
    if (!current) return current.error();
    level::Entity after = **current;
    if (auto r = set_entity_field(after, fix.field, fix.value); !r) return r;
    auto change = std::make_unique<LevelChange>();
    change->set_name(name);
    change->updates.push_back({**current, std::move(after)});
    editor.execute(std::move(change), {issue.entity_id});
    return ok();
}

Result<void> apply_fix(Editor& editor, const Issue& issue, const std::string& name,
                       const fixes::MoveEntity& fix) {
    return apply_fix(editor, issue, name, fixes::SetField{"position", FieldValue(fix.position)});
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string& name,
                       const fixes::MovePlayerStart& fix) {
    const Document& doc = editor.doc();
    auto change = std::make_unique<LevelChange>();
    change->set_name(name);
    change->player_start =
        Change<level::PlayerStart>{doc.level.player_start, {fix.position, doc.level.player_start.yaw}};
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<void> apply_fix(Editor& editor, const Issue& issue, const std::string&, const fixes::DeleteEntity&) {
    return delete_entities(editor, {issue.entity_id});
}

Result<void> apply_fix(Editor& editor, const Issue& issue, const std::string&,
                       const fixes::MovePatrolPoint& fix) {
    return patrol_move(editor, issue.entity_id, fix.index, fix.position);
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::SetSetting& fix) {
    return set_setting(editor, fix.field, fix.value);
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::SetLink& fix) {
    return link_set(editor, fix.owner, fix.index, fix.link);
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::RemoveLink& fix) {
    return link_remove(editor, fix.owner, fix.index);
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::AddLink& fix) {
    auto added = link_add(editor, fix.owner, fix.link);
    if (!added) return added.error();
    return ok();
}

// Objective `objective` with its kill list edited by `edit` at name `kill_index` (both checked).
template <class Edit>
Result<level::Objective> edit_kill_list(const level::Level& level, int objective, int kill_index, Edit edit) {
    if (auto r = check_index(objective, level.objectives.size(), "objective", "the level"); !r)
        return r.error();
    level::Objective changed = level.objectives[static_cast<size_t>(objective)];
    if (auto r = check_index(kill_index, changed.kill.size(), "kill-list name",
                             "objective " + in_quotes(changed.id));
        !r)
        return r.error();
    edit(changed.kill, changed.kill.begin() + kill_index);
    return changed;
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::SetKillName& fix) {
    const Document& doc = editor.doc();
    auto changed =
        edit_kill_list(doc.level, fix.objective, fix.kill_index, [&](auto&, auto name) { *name = fix.name; });
    if (!changed) return changed.error();
    return objective_set(editor, fix.objective, std::move(changed).value());
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::RemoveKillName& fix) {
    const Document& doc = editor.doc();
    auto changed = edit_kill_list(doc.level, fix.objective, fix.kill_index,
                                  [](auto& kill, auto name) { kill.erase(name); });
    if (!changed) return changed.error();
    return objective_set(editor, fix.objective, std::move(changed).value());
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::AddShutdownObjective&) {
    return add_shutdown_objective(editor);
}

Result<void> apply_fix(Editor& editor, const Issue&, const std::string&, const fixes::UnlinkPrefab& fix) {
    return unlink_prefab(editor, fix.group);
}

} // namespace

Result<void> apply_quick_fix(Editor& editor, const Issue& issue) {
    const std::string name = "Quick fix: " + issue.fix.label;
    return std::visit([&](const auto& fix) { return apply_fix(editor, issue, name, fix); }, issue.fix.action);
}

} // namespace ks::editor
