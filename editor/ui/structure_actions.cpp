// Group and prefab actions for the window's keys, menus and panels (structure_actions.h).
#include "ui/structure_actions.h"
#include "model/edit_groups.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"

namespace ks::editor::ui {

std::string group_label(const level::Group& group) {
    std::string label = group.name.empty() ? "group " + std::to_string(group.id) : group.name;
    if (group.has_prefab) label += "  [" + group.prefab.prefab + "]";
    return label;
}

void group_selection(Editor& editor, EditorLog& log) {
    if (editor.doc().selection.empty()) return;
    auto group = group_selection(editor);
    if (!group) {
        log.line("group: " + group.error().str(), true);
        return;
    }
    if (const level::Group* g = editor.level().editor.find_group(*group))
        log.line("grouped " + std::to_string(group_entities_deep(editor.level().editor, *group).size()) +
                 " entities as " + g->name);
}

void ungroup_selection(Editor& editor, EditorLog& log) {
    if (selected_groups(editor).empty()) {
        log.line("ungroup: the selection holds no whole group", true);
        return;
    }
    log.report(ungroup_selection(editor), "ungroup");
}

void leave_group(Editor& editor, EditorLog& log) {
    const int left = editor.open_group();
    exit_group(editor);
    select_group(editor, log, left);
}

void select_group(Editor& editor, EditorLog& log, int group_id, SelectMode mode) {
    const level::EditorData& data = editor.level().editor;
    if (!data.find_group(group_id)) return;
    const int parent = parent_group_of_group(data, group_id);
    if (parent != editor.open_group()) {
        if (parent == 0)
            while (editor.open_group() != 0) exit_group(editor);
        else
            log.report(enter_group(editor, parent), "enter group");
    }
    const std::vector<int> members = group_entities_deep(data, group_id);
    if (members.empty()) return;
    log.report(select_picked(editor, members.front(), mode), "select");
}

bool double_click_enter(Editor& editor, EditorLog& log, int entity_id) {
    if (entity_id <= 0) return false;
    const int unit = pick_unit(editor.level().editor, editor.open_group(), entity_id);
    if (unit == 0) return false;
    if (auto r = enter_group(editor, unit); !r) {
        log.report(r, "enter group");
        return false;
    }
    log.report(select_picked(editor, entity_id), "select");
    return true;
}

void apply_to_prefab(Editor& editor, EditorLog& log, int instance) {
    auto applied = apply_instance_to_prefab(editor, instance);
    if (applied)
        log.line("applied to " + applied->string());
    else
        log.line("apply to prefab: " + applied.error().str(), true);
}

} // namespace ks::editor::ui
