// Layers, and hiding and locking one entity: edit_layers.h. Each edit is one undoable step on the level's
// editor section (saved in the file, read past by the game).
#include "model/edit_layers.h"

#include "model/groups.h"

#include <algorithm>

namespace ks::editor {
namespace {
using level::EditorData;
using level::Layer;

constexpr const char* kDefaultLayer = "Default";

void ensure_default_layer(EditorData& data) {
    if (data.layers.empty()) data.layers.push_back(Layer{kDefaultLayer, true, false, {}});
}

Result<void> check_layer(const EditorData& data, int index, const std::string& what) {
    if (index >= 0 && index < static_cast<int>(data.layers.size())) return ok();
    return Error(what + ": no layer " + std::to_string(index), Location{},
                 data.layers.empty()
                     ? "the level has no layers yet: add one first"
                     : "layers count from 0 (Default) to " + std::to_string(data.layers.size() - 1));
}

Result<void> set_entity_flag(Editor& editor, int id, std::vector<int> level::EditorData::*list, bool on,
                             const char* what) {
    const Document& doc = editor.doc();
    const level::Entity* e = doc.level.find(id);
    if (!e) return Error(std::string(what) + ": no entity with id " + std::to_string(id));
    level::EditorData data = doc.level.editor;
    if (on)
        insert_sorted(data.*list, id);
    else
        std::erase(data.*list, id);
    std::vector<int> selection = doc.selection;
    if (on && list == &level::EditorData::locked) std::erase(selection, id); // a locked entity is not picked
    std::string name =
        std::string(what) + " " + std::string(level::type_name(e->type())) + " " + std::to_string(id);
    editor.change_structure(std::move(name), std::move(data), std::move(selection));
    return ok();
}

Result<void> set_layer_flag(Editor& editor, int index, bool level::Layer::*flag, bool value,
                            const char* what) {
    const Document& doc = editor.doc();
    if (auto r = check_layer(doc.level.editor, index, what); !r) return r;
    EditorData data = doc.level.editor;
    Layer& layer = data.layers[static_cast<size_t>(index)];
    layer.*flag = value;
    std::string name = std::string(what) + " " + layer.name;
    editor.change_structure(std::move(name), std::move(data), doc.selection);
    return ok();
}
} // namespace

Result<int> layer_add(Editor& editor, std::string name) {
    const Document& doc = editor.doc();
    if (name.empty() || name.size() > static_cast<size_t>(level::kMaxLayerNameLength))
        return Error("Add layer: a layer's name has 1 to " + std::to_string(level::kMaxLayerNameLength) +
                         " characters",
                     Location{}, "type a name");
    EditorData data = doc.level.editor;
    ensure_default_layer(data);
    for (const Layer& layer : data.layers)
        if (layer.name == name)
            return Error("Add layer: a layer named '" + name + "' exists", Location{}, "choose another name");
    if (data.layers.size() >= static_cast<size_t>(level::kMaxLayers))
        return Error("Add layer: a level has at most " + std::to_string(level::kMaxLayers) + " layers",
                     Location{}, "merge layers you no longer need");
    data.layers.push_back(Layer{name, true, false, {}});
    const int index = static_cast<int>(data.layers.size()) - 1;
    editor.change_structure("Add layer " + name, std::move(data), doc.selection);
    return index;
}

Result<void> layer_rename(Editor& editor, int index, std::string name) {
    const Document& doc = editor.doc();
    if (auto r = check_layer(doc.level.editor, index, "Rename layer"); !r) return r;
    if (name.empty() || name.size() > static_cast<size_t>(level::kMaxLayerNameLength))
        return Error("Rename layer: a layer's name has 1 to " + std::to_string(level::kMaxLayerNameLength) +
                         " characters",
                     Location{}, "type a name");
    EditorData data = doc.level.editor;
    for (size_t i = 0; i < data.layers.size(); ++i)
        if (static_cast<int>(i) != index && data.layers[i].name == name)
            return Error("Rename layer: a layer named '" + name + "' exists", Location{},
                         "choose another name");
    data.layers[static_cast<size_t>(index)].name = std::move(name);
    editor.change_structure("Rename layer", std::move(data), doc.selection);
    return ok();
}

Result<void> layer_remove(Editor& editor, int index) {
    const Document& doc = editor.doc();
    if (auto r = check_layer(doc.level.editor, index, "Remove layer"); !r) return r;
    if (index == 0)
        return Error("Remove layer: the Default layer stays", Location{},
                     "it holds every entity no other layer lists");
    EditorData data = doc.level.editor;
    const std::string name = data.layers[static_cast<size_t>(index)].name;
    data.layers.erase(data.layers.begin() + index);
    if (data.active_layer == index)
        data.active_layer = 0;
    else if (data.active_layer > index)
        --data.active_layer;
    editor.change_structure("Remove layer " + name, std::move(data), doc.selection);
    return ok();
}

Result<void> layer_set_visible(Editor& editor, int index, bool visible) {
    return set_layer_flag(editor, index, &level::Layer::visible, visible,
                          visible ? "Show layer" : "Hide layer");
}

Result<void> layer_set_locked(Editor& editor, int index, bool locked) {
    return set_layer_flag(editor, index, &level::Layer::locked, locked,
                          locked ? "Lock layer" : "Unlock layer");
}

Result<void> layer_set_active(Editor& editor, int index) {
    const Document& doc = editor.doc();
    if (auto r = check_layer(doc.level.editor, index, "Set active layer"); !r) return r;
    EditorData data = doc.level.editor;
    data.active_layer = index;
    std::string name = "Set active layer " + data.layers[static_cast<size_t>(index)].name;
    editor.change_structure(std::move(name), std::move(data), doc.selection);
    return ok();
}

Result<void> move_selection_to_layer(Editor& editor, int index) {
    const Document& doc = editor.doc();
    if (auto r = check_layer(doc.level.editor, index, "Move to layer"); !r) return r;
    std::vector<int> ids;
    for (int id : doc.selection)
        if (doc.level.find(id) && !doc.locked.contains(id)) ids.push_back(id);
    if (ids.empty()) return Error("Move to layer: nothing is selected", Location{}, "select entities first");
    EditorData data = doc.level.editor;
    for (size_t i = 1; i < data.layers.size(); ++i)
        for (int id : ids) std::erase(data.layers[i].entities, id);
    if (index > 0) {
        auto& list = data.layers[static_cast<size_t>(index)].entities;
        list.insert(list.end(), ids.begin(), ids.end());
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    const std::string name =
        "Move " + std::to_string(ids.size()) + " to layer " + data.layers[static_cast<size_t>(index)].name;
    editor.change_structure(name, std::move(data), doc.selection);
    return ok();
}

Result<void> set_hidden(Editor& editor, int id, bool hidden) {
    return set_entity_flag(editor, id, &level::EditorData::hidden, hidden, hidden ? "Hide" : "Show");
}

Result<void> set_locked(Editor& editor, int id, bool locked) {
    return set_entity_flag(editor, id, &level::EditorData::locked, locked, locked ? "Lock" : "Unlock");
}

} // namespace ks::editor
