// The script language's group, layer and prefab steps (script_structure.h) run on the Editor, and their
// expectations checked. Every edit is the Editor's own, so a line is one undo step like the panel's.
#include "model/edit_groups.h"
#include "model/edit_layers.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"
#include "model/script_command.h"

#include "jsonio/suggest.h"

#include <algorithm>

namespace ks::editor {
namespace fs = std::filesystem;

namespace {

template <class T>
Result<void> structure_done(const Result<T>& r) {
    if (!r) return r.error();
    return ok();
}

// A layer by name, or by index from 0.
Result<int> layer_index(const Editor& editor, const std::string& word) {
    const auto& layers = editor.level().editor.layers;
    std::vector<std::string> names;
    for (size_t i = 0; i < layers.size(); ++i) {
        if (layers[i].name == word) return static_cast<int>(i);
        names.push_back(layers[i].name);
    }
    int index = -1;
    if (script_tokens::to_int(word, index) && index >= 0 && index < static_cast<int>(layers.size()))
        return index;
    const std::string near = jsonio::closest_match(word, names);
    return Error(
        "no layer '" + word + "'", Location{},
        (near.empty() ? std::string() : "did you mean '" + near + "'? ") +
            (names.empty() ? "the level has no layers: layer add NAME" : "layers: " + jsonio::join(names)));
}

// Runs `edit(index)` on the layer `word` names.
template <class Edit>
Result<void> on_layer(const Editor& editor, const std::string& word, Edit edit) {
    auto index = layer_index(editor, word);
    if (!index) return index.error();
    return edit(*index);
}

Result<const level::Group*> find_group(const Editor& editor, int id) {
    if (const level::Group* g = editor.level().editor.find_group(id)) return g;
    std::string ids;
    for (const level::Group& g : editor.level().editor.groups)
        ids += (ids.empty() ? "" : ", ") + std::to_string(g.id);
    return Error("no group " + std::to_string(id), Location{},
                 ids.empty() ? "the level has no groups" : "groups: " + ids);
}

// Counts the expectation (a failing line ends the script, so only passing ones are ever reported).
Result<void> expect_count(ScriptContext& c, const std::string& what, int expected, size_t actual) {
    ++c.report.expectations_checked;
    if (static_cast<size_t>(expected) == actual) return ok();
    return Error("expected " + what + " " + std::to_string(expected) + ", found " + std::to_string(actual));
}

} // namespace

Result<void> StructureStep::run(ScriptContext& c) const {
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

namespace steps {

Result<void> Group::run(ScriptContext& c) const {
    return structure_done(group_selection(c.editor, name));
}
Result<void> Ungroup::run(ScriptContext& c) const {
    return ungroup_selection(c.editor);
}
Result<void> Enter::run(ScriptContext& c) const {
    return enter_group(c.editor, group);
}
Result<void> Exit::run(ScriptContext& c) const {
    exit_group(c.editor);
    return ok();
}
Result<void> Pick::run(ScriptContext& c) const {
    return select_picked(c.editor, entity_id, mode);
}

Result<void> LayerAdd::run(ScriptContext& c) const {
    return structure_done(layer_add(c.editor, name));
}
Result<void> LayerRename::run(ScriptContext& c) const {
    return on_layer(c.editor, layer, [&](int i) { return layer_rename(c.editor, i, name); });
}
Result<void> LayerRemove::run(ScriptContext& c) const {
    return on_layer(c.editor, layer, [&](int i) { return layer_remove(c.editor, i); });
}
Result<void> LayerVisible::run(ScriptContext& c) const {
    return on_layer(c.editor, layer, [&](int i) { return layer_set_visible(c.editor, i, visible); });
}
Result<void> LayerLocked::run(ScriptContext& c) const {
    return on_layer(c.editor, layer, [&](int i) { return layer_set_locked(c.editor, i, locked); });
}
Result<void> LayerActive::run(ScriptContext& c) const {
    return on_layer(c.editor, layer, [&](int i) { return layer_set_active(c.editor, i); });
}
Result<void> LayerMove::run(ScriptContext& c) const {
    return on_layer(c.editor, layer, [&](int i) { return move_selection_to_layer(c.editor, i); });
}

Result<void> PrefabFolder::run(ScriptContext& c) const {
    const fs::path folder(path);
    c.editor.prefabs().set_folders({folder.is_absolute() ? folder : c.base_dir / folder});
    return ok();
}
Result<void> PrefabSave::run(ScriptContext& c) const {
    auto r = save_prefab(c.editor, name, title, replace);
    if (!r) return r.error();
    c.report.saved.push_back(*r);
    return ok();
}
Result<void> PrefabPlace::run(ScriptContext& c) const {
    return structure_done(place_prefab(c.editor, name, position, yaw));
}
Result<void> PrefabApply::run(ScriptContext& c) const {
    auto r = apply_instance_to_prefab(c.editor, group);
    if (!r) return r.error();
    c.report.saved.push_back(*r);
    return ok();
}
Result<void> PrefabUpdate::run(ScriptContext& c) const {
    return structure_done(update_prefab_instances(c.editor));
}
Result<void> PrefabRevert::run(ScriptContext& c) const {
    return revert_prefab_overrides(c.editor, group, entity_id, field);
}
Result<void> PrefabUnlink::run(ScriptContext& c) const {
    return unlink_prefab(c.editor, group);
}

Result<void> ExpectGroups::run(ScriptContext& c) const {
    return expect_count(c, "groups", count, c.editor.level().editor.groups.size());
}
Result<void> ExpectLayers::run(ScriptContext& c) const {
    return expect_count(c, "layers", count, c.editor.level().editor.layers.size());
}
Result<void> ExpectGroup::run(ScriptContext& c) const {
    if (auto g = find_group(c.editor, group); !g) return g.error();
    return expect_count(c, "group " + std::to_string(group) + " entities", count,
                        group_entities_deep(c.editor.level().editor, group).size());
}
Result<void> ExpectOpenGroup::run(ScriptContext& c) const {
    return expect_count(c, "the entered group", group, static_cast<size_t>(c.editor.open_group()));
}
Result<void> ExpectHidden::run(ScriptContext& c) const {
    ++c.report.expectations_checked;
    const bool is_hidden = c.editor.doc().hidden.contains(entity_id);
    if (is_hidden == hidden) return ok();
    return Error("expected entity " + std::to_string(entity_id) + " to be " +
                 (is_hidden ? "shown" : "hidden") + ", it is " + (is_hidden ? "hidden" : "shown"));
}

Result<void> ExpectLayer::run(ScriptContext& c) const {
    auto index = layer_index(c.editor, layer);
    if (!index) return index.error();
    const level::Level& level = c.editor.level();
    size_t entities = 0;
    for (const level::Entity& e : level.entities) entities += layer_of(level.editor, e.id) == *index;
    if (auto r = expect_count(c, "layer " + layer + " entities", count, entities); !r) return r;
    const level::Layer& found = level.editor.layers[static_cast<size_t>(*index)];
    for (const std::string& s : state) {
        const bool holds = s == "visible"  ? found.visible
                           : s == "hidden" ? !found.visible
                           : s == "locked" ? found.locked
                                           : !found.locked;
        if (!holds) return Error("expected layer " + layer + " to be " + s);
    }
    return ok();
}

Result<void> ExpectInstance::run(ScriptContext& c) const {
    auto g = find_group(c.editor, group);
    if (!g) return g.error();
    if (!(*g)->has_prefab) return Error("group " + std::to_string(group) + " is not a prefab instance");
    if ((*g)->prefab.prefab != prefab)
        return Error("group " + std::to_string(group) + " is an instance of '" + (*g)->prefab.prefab +
                     "', not '" + prefab + "'");
    const auto& members = (*g)->prefab.members;
    return expect_count(
        c, "live members of instance " + std::to_string(group), count,
        static_cast<size_t>(std::count_if(members.begin(), members.end(), [](int id) { return id != 0; })));
}

Result<void> ExpectOverride::run(ScriptContext& c) const {
    ++c.report.expectations_checked;
    auto g = find_group(c.editor, group);
    if (!g) return g.error();
    const auto& link = (*g)->prefab;
    auto at = std::find(link.members.begin(), link.members.end(), entity_id);
    if (!(*g)->has_prefab || at == link.members.end())
        return Error("entity " + std::to_string(entity_id) + " is not a member of prefab instance " +
                     std::to_string(group));
    const auto& fields = link.overrides[static_cast<size_t>(at - link.members.begin())];
    const bool has = std::find(fields.begin(), fields.end(), field) != fields.end();
    if (has == wanted) return ok();
    return Error(
        "expected entity " + std::to_string(entity_id) + (has ? " not" : "") + " to override " + field,
        Location{}, "its overrides: " + (fields.empty() ? std::string("none") : jsonio::join(fields)));
}

} // namespace steps
} // namespace ks::editor
