// The script language's group, layer and prefab lines (script_structure.h) run on the Editor, and their
// expectations checked. Every edit is the Editor's own, so a line is one undo step like the panel's.
#include "model/script_structure.h"

#include "jsonio/suggest.h"

#include <algorithm>

namespace ks::editor {
namespace {
namespace fs = std::filesystem;
using level::Group;

class StructureRunner {
  public:
    StructureRunner(Editor& editor, const fs::path& base_dir, ScriptReport& report)
        : editor_(editor), base_dir_(base_dir), report_(report) {}

    Result<void> run(const StructureStep& s) {
        switch (s.op) {
        case StructureOp::Group: {
            auto r = editor_.group_selection(s.name);
            return r ? ok() : Result<void>(r.error());
        }
        case StructureOp::Ungroup:
            return editor_.ungroup_selection();
        case StructureOp::Enter:
            return editor_.enter_group(s.id);
        case StructureOp::Exit:
            editor_.exit_group();
            return ok();
        case StructureOp::Pick:
            return editor_.select_picked(s.id, s.mode);
        case StructureOp::LayerAdd: {
            auto r = editor_.layer_add(s.name);
            return r ? ok() : Result<void>(r.error());
        }
        default:
            break;
        }
        if (s.op >= StructureOp::LayerRename && s.op <= StructureOp::LayerMove) return layer(s);
        if (s.op >= StructureOp::PrefabFolder && s.op <= StructureOp::PrefabUnlink) return prefab(s);
        ++report_.expectations_checked;
        return expectation(s);
    }

  private:
    Result<int> layer_index(const std::string& word) const {
        const auto& layers = editor_.level().editor.layers;
        std::vector<std::string> names;
        for (size_t i = 0; i < layers.size(); ++i) {
            if (layers[i].name == word) return static_cast<int>(i);
            names.push_back(layers[i].name);
        }
        int index = -1;
        if (script_tokens::to_int(word, index) && index >= 0 && index < static_cast<int>(layers.size()))
            return index;
        const std::string near = jsonio::closest_match(word, names);
        return Error("no layer '" + word + "'", Location{},
                     (near.empty() ? std::string() : "did you mean '" + near + "'? ") +
                         (names.empty() ? "the level has no layers: layer add NAME"
                                        : "layers: " + jsonio::join(names)));
    }

    Result<void> layer(const StructureStep& s) {
        auto index = layer_index(s.layer);
        if (!index) return index.error();
        switch (s.op) {
        case StructureOp::LayerRename:
            return editor_.layer_rename(*index, s.name);
        case StructureOp::LayerRemove:
            return editor_.layer_remove(*index);
        case StructureOp::LayerShow:
        case StructureOp::LayerHide:
            return editor_.layer_set_visible(*index, s.op == StructureOp::LayerShow);
        case StructureOp::LayerLock:
        case StructureOp::LayerUnlock:
            return editor_.layer_set_locked(*index, s.op == StructureOp::LayerLock);
        case StructureOp::LayerActive:
            return editor_.layer_set_active(*index);
        default:
            return editor_.move_selection_to_layer(*index);
        }
    }

    Result<void> prefab(const StructureStep& s) {
        switch (s.op) {
        case StructureOp::PrefabFolder: {
            const fs::path path(s.text);
            editor_.prefabs().set_folders({path.is_absolute() ? path : base_dir_ / path});
            return ok();
        }
        case StructureOp::PrefabSave: {
            auto r = editor_.save_prefab(s.name, s.text, s.replace);
            if (!r) return r.error();
            report_.saved.push_back(*r);
            return ok();
        }
        case StructureOp::PrefabPlace: {
            auto r = editor_.place_prefab(s.name, s.position, s.yaw);
            return r ? ok() : Result<void>(r.error());
        }
        case StructureOp::PrefabApply: {
            auto r = editor_.apply_instance_to_prefab(s.id);
            if (!r) return r.error();
            report_.saved.push_back(*r);
            return ok();
        }
        case StructureOp::PrefabUpdate: {
            auto r = editor_.update_prefab_instances();
            return r ? ok() : Result<void>(r.error());
        }
        case StructureOp::PrefabRevert:
            return editor_.revert_prefab_overrides(s.id, s.entity_id, s.text);
        default:
            return editor_.unlink_prefab(s.id);
        }
    }

    Result<const Group*> group(int id) const {
        if (const Group* g = editor_.level().editor.find_group(id)) return g;
        std::string ids;
        for (const Group& g : editor_.level().editor.groups)
            ids += (ids.empty() ? "" : ", ") + std::to_string(g.id);
        return Error("no group " + std::to_string(id), Location{},
                     ids.empty() ? "the level has no groups" : "groups: " + ids);
    }

    static Result<void> expect_count(const std::string& what, int expected, size_t actual) {
        if (static_cast<size_t>(expected) == actual) return ok();
        return Error("expected " + what + " " + std::to_string(expected) + ", found " +
                     std::to_string(actual));
    }

    Result<void> expectation(const StructureStep& s) {
        const level::EditorData& data = editor_.level().editor;
        switch (s.op) {
        case StructureOp::ExpectGroups:
            return expect_count("groups", s.count, data.groups.size());
        case StructureOp::ExpectLayers:
            return expect_count("layers", s.count, data.layers.size());
        case StructureOp::ExpectGroup:
            if (auto g = group(s.id); !g) return g.error();
            return expect_count("group " + std::to_string(s.id) + " entities", s.count,
                                group_entities_deep(data, s.id).size());
        case StructureOp::ExpectLayer:
            return expect_layer(s);
        case StructureOp::ExpectInstance:
            return expect_instance(s);
        case StructureOp::ExpectOverride:
        case StructureOp::ExpectNoOverride:
            return expect_override(s);
        case StructureOp::ExpectOpenGroup:
            return expect_count("the entered group", s.id, static_cast<size_t>(editor_.open_group()));
        default: {
            const bool hidden = editor_.doc().hidden.contains(s.entity_id);
            if (hidden == (s.op == StructureOp::ExpectHidden)) return ok();
            return Error("expected entity " + std::to_string(s.entity_id) + " to be " +
                         (hidden ? "shown" : "hidden") + ", it is " + (hidden ? "hidden" : "shown"));
        }
        }
    }

    Result<void> expect_layer(const StructureStep& s) {
        auto index = layer_index(s.layer);
        if (!index) return index.error();
        const level::Level& level = editor_.level();
        size_t count = 0;
        for (const level::Entity& e : level.entities) count += layer_of(level.editor, e.id) == *index;
        if (auto r = expect_count("layer " + s.layer + " entities", s.count, count); !r) return r;
        const level::Layer& layer = level.editor.layers[static_cast<size_t>(*index)];
        for (const std::string& state : s.state) {
            const bool holds = state == "visible"  ? layer.visible
                               : state == "hidden" ? !layer.visible
                               : state == "locked" ? layer.locked
                                                   : !layer.locked;
            if (!holds) return Error("expected layer " + s.layer + " to be " + state);
        }
        return ok();
    }

    Result<void> expect_instance(const StructureStep& s) {
        auto g = group(s.id);
        if (!g) return g.error();
        if (!(*g)->has_prefab) return Error("group " + std::to_string(s.id) + " is not a prefab instance");
        if ((*g)->prefab.prefab != s.name)
            return Error("group " + std::to_string(s.id) + " is an instance of '" + (*g)->prefab.prefab +
                         "', not '" + s.name + "'");
        const auto& members = (*g)->prefab.members;
        return expect_count("live members of instance " + std::to_string(s.id), s.count,
                            static_cast<size_t>(std::count_if(members.begin(), members.end(),
                                                              [](int id) { return id != 0; })));
    }

    Result<void> expect_override(const StructureStep& s) {
        auto g = group(s.id);
        if (!g) return g.error();
        const auto& link = (*g)->prefab;
        auto at = std::find(link.members.begin(), link.members.end(), s.entity_id);
        if (!(*g)->has_prefab || at == link.members.end())
            return Error("entity " + std::to_string(s.entity_id) + " is not a member of prefab instance " +
                         std::to_string(s.id));
        const auto& fields = link.overrides[static_cast<size_t>(at - link.members.begin())];
        const bool has = std::find(fields.begin(), fields.end(), s.text) != fields.end();
        if (has == (s.op == StructureOp::ExpectOverride)) return ok();
        return Error(
            "expected entity " + std::to_string(s.entity_id) + (has ? " not" : "") + " to override " + s.text,
            Location{}, "its overrides: " + (fields.empty() ? std::string("none") : jsonio::join(fields)));
    }

    Editor& editor_;
    const fs::path& base_dir_;
    ScriptReport& report_;
};

} // namespace

Result<void> run_structure_step(const StructureStep& step, Editor& editor, const fs::path& base_dir,
                                ScriptReport& report) {
    return StructureRunner(editor, base_dir, report).run(step);
}

} // namespace ks::editor
