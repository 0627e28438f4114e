// The quick fixes (quick_fix.h): Editor::apply_quick_fix sends each kind to its own apply_fix, one undo
// step through the Editor's edits.
#include "model/editor.h"

#include "model/command.h"

namespace ks::editor {

template <>
Result<void> Editor::apply_fix(const Issue& issue, const std::string&, const std::monostate&) {
    return Error("this issue has no quick fix", Location{}, issue.message);
}

namespace {
// The issue's entity, checked before an edit: it may have gone, or been locked, since the check ran.
Result<const level::Entity*> fixable_entity(const Document& doc, const Issue& issue,
                                            const std::string& name) {
    const level::Entity* current = doc.level.find(issue.entity_id);
    if (!current) return Error(name + ": entity " + std::to_string(issue.entity_id) + " no longer exists");
    if (doc.locked.contains(issue.entity_id))
        return Error(name + ": entity " + std::to_string(issue.entity_id) + " is locked");
    return current;
}
} // namespace

template <>
Result<void> Editor::apply_fix(const Issue& issue, const std::string& name, const fixes::SetField& fix) {
    auto current = fixable_entity(doc_, issue, name);
    if (!current) return current.error();
    level::Entity after = **current;
    if (auto r = set_entity_field(after, fix.field, fix.value); !r) return r;
    auto change = std::make_unique<LevelChange>();
    change->set_name(name);
    change->updates.push_back({**current, std::move(after)});
    execute(std::move(change), {issue.entity_id});
    return ok();
}

template <>
Result<void> Editor::apply_fix(const Issue& issue, const std::string& name, const fixes::MoveEntity& fix) {
    return apply_fix(issue, name, fixes::SetField{"position", FieldValue(fix.position)});
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string& name, const fixes::MovePlayerStart& fix) {
    auto change = std::make_unique<LevelChange>();
    change->set_name(name);
    change->player_start =
        Change<level::PlayerStart>{doc_.level.player_start, {fix.position, doc_.level.player_start.yaw}};
    execute(std::move(change), doc_.selection);
    return ok();
}

template <>
Result<void> Editor::apply_fix(const Issue& issue, const std::string&, const fixes::DeleteEntity&) {
    return delete_entities({issue.entity_id});
}

template <>
Result<void> Editor::apply_fix(const Issue& issue, const std::string&, const fixes::MovePatrolPoint& fix) {
    return patrol_move(issue.entity_id, fix.index, fix.position);
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::SetSetting& fix) {
    return set_setting(fix.field, fix.value);
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::SetLink& fix) {
    return link_set(fix.owner, fix.index, fix.link);
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::RemoveLink& fix) {
    return link_remove(fix.owner, fix.index);
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::AddLink& fix) {
    auto added = link_add(fix.owner, fix.link);
    if (!added) return added.error();
    return ok();
}

namespace {
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
} // namespace

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::SetKillName& fix) {
    auto changed = edit_kill_list(doc_.level, fix.objective, fix.kill_index,
                                  [&](auto&, auto name) { *name = fix.name; });
    if (!changed) return changed.error();
    return objective_set(fix.objective, std::move(changed).value());
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::RemoveKillName& fix) {
    auto changed = edit_kill_list(doc_.level, fix.objective, fix.kill_index,
                                  [](auto& kill, auto name) { kill.erase(name); });
    if (!changed) return changed.error();
    return objective_set(fix.objective, std::move(changed).value());
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::AddShutdownObjective&) {
    return add_shutdown_objective();
}

template <>
Result<void> Editor::apply_fix(const Issue&, const std::string&, const fixes::UnlinkPrefab& fix) {
    return unlink_prefab(fix.group);
}

Result<void> Editor::apply_quick_fix(const Issue& issue) {
    const std::string name = "Quick fix: " + issue.fix.label;
    return std::visit([&](const auto& fix) { return apply_fix(issue, name, fix); }, issue.fix.action);
}

} // namespace ks::editor
