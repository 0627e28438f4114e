#pragma once
// The script language's structure steps: groups (`group`, `ungroup`, `enter`, `exit`, `pick`), layers
// (`layer ...`) and prefabs (`prefab ...`), and their expectations; parsed and registered by
// script_structure_parser.cpp, run on the Editor by script_structure_runner.cpp. Documented in
// docs/editor.md.
#include "model/edit_selection.h"

#include <string>
#include <variant>
#include <vector>

namespace ks::editor {

struct ScriptContext;

namespace steps {

// ---- groups -------------------------------------------------------------------------------------------
struct Group {
    std::string name; // empty: "Group N"
    Result<void> run(ScriptContext& c) const;
};
struct Ungroup {
    Result<void> run(ScriptContext& c) const;
};
struct Enter {
    int group = 0;
    Result<void> run(ScriptContext& c) const;
};
struct Exit {
    Result<void> run(ScriptContext& c) const;
};
struct Pick {
    int entity_id = 0;
    SelectMode mode = SelectMode::Replace;
    Result<void> run(ScriptContext& c) const;
};

// ---- layers: `layer` names one by name or index, resolved when the line runs --------------------------
struct LayerAdd {
    std::string name;
    Result<void> run(ScriptContext& c) const;
};
struct LayerRename {
    std::string layer, name;
    Result<void> run(ScriptContext& c) const;
};
struct LayerRemove {
    std::string layer;
    Result<void> run(ScriptContext& c) const;
};
struct LayerVisible {
    std::string layer;
    bool visible = true;
    Result<void> run(ScriptContext& c) const;
};
struct LayerLocked {
    std::string layer;
    bool locked = true;
    Result<void> run(ScriptContext& c) const;
};
struct LayerActive {
    std::string layer;
    Result<void> run(ScriptContext& c) const;
};
struct LayerMove {
    std::string layer;
    Result<void> run(ScriptContext& c) const;
};

// ---- prefabs ------------------------------------------------------------------------------------------
struct PrefabFolder {
    std::string path;
    Result<void> run(ScriptContext& c) const;
};
struct PrefabSave {
    std::string name, title;
    bool replace = false;
    Result<void> run(ScriptContext& c) const;
};
struct PrefabPlace {
    std::string name;
    Vec3 position{0.0f};
    float yaw = 0.0f;
    Result<void> run(ScriptContext& c) const;
};
struct PrefabApply {
    int group = 0;
    Result<void> run(ScriptContext& c) const;
};
struct PrefabUpdate {
    Result<void> run(ScriptContext& c) const;
};
struct PrefabRevert {
    int group = 0, entity_id = 0; // entity 0: every member
    std::string field;            // empty: every field
    Result<void> run(ScriptContext& c) const;
};
struct PrefabUnlink {
    int group = 0;
    Result<void> run(ScriptContext& c) const;
};

// ---- expectations -------------------------------------------------------------------------------------
struct ExpectGroups {
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectGroup {
    int group = 0, count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectLayers {
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectLayer {
    std::string layer;
    int count = 0;
    std::vector<std::string> state; // "visible", "hidden", "locked", "unlocked"
    Result<void> run(ScriptContext& c) const;
};
struct ExpectInstance {
    int group = 0;
    std::string prefab;
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectOverride {
    int group = 0, entity_id = 0;
    std::string field;
    bool wanted = true; // false: `expect no_override`
    Result<void> run(ScriptContext& c) const;
};
struct ExpectHidden {
    int entity_id = 0;
    bool hidden = true; // false: `expect shown`
    Result<void> run(ScriptContext& c) const;
};
struct ExpectOpenGroup {
    int group = 0; // 0: none
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct StructureStep {
    std::variant<steps::Group, steps::Ungroup, steps::Enter, steps::Exit, steps::Pick, steps::LayerAdd,
                 steps::LayerRename, steps::LayerRemove, steps::LayerVisible, steps::LayerLocked,
                 steps::LayerActive, steps::LayerMove, steps::PrefabFolder, steps::PrefabSave,
                 steps::PrefabPlace, steps::PrefabApply, steps::PrefabUpdate, steps::PrefabRevert,
                 steps::PrefabUnlink, steps::ExpectGroups, steps::ExpectGroup, steps::ExpectLayers,
                 steps::ExpectLayer, steps::ExpectInstance, steps::ExpectOverride, steps::ExpectHidden,
                 steps::ExpectOpenGroup>
        step;
    Result<void> run(ScriptContext& c) const;
};

} // namespace ks::editor
