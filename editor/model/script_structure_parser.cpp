// The script language's group, layer and prefab commands (script_structure.h): each command's parser and
// the table that registers it (script_command.h); their steps run in script_structure_runner.cpp.
#include "model/script_command.h"

#include <algorithm>

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kPickUsage = "pick [add|toggle] ID   (selects what a click on the entity selects)";
constexpr const char* kLayerUsage =
    "layer add NAME... | layer LAYER rename NAME... | layer LAYER remove|show|hide|lock|unlock|active | "
    "layer LAYER move   (LAYER: a name or an index from 0, the Default layer)";
constexpr const char* kPrefabUsage =
    "prefab folder PATH | prefab save NAME [replace] [title TEXT...] | prefab place NAME at X,Y,Z [yaw D] | "
    "prefab apply GROUP | prefab update | prefab revert GROUP [ID [FIELD]] | prefab unlink GROUP";
constexpr const char* kLayerExpectUsage = "expect layer LAYER N [visible|hidden] [locked|unlocked]";
constexpr const char* kInstanceUsage = "expect instance GROUP PREFAB N";
constexpr const char* kOverrideUsage = "expect override GROUP ID FIELD";
constexpr const char* kNoOverrideUsage = "expect no_override GROUP ID FIELD";

template <class T>
Result<ScriptStep> structure_step(T step) {
    return step_of<StructureStep>(std::move(step));
}

// Word `token` as a whole number of at least `min`.
Result<void> number(const LineWords& w, size_t token, int& out, const char* what, const char* usage,
                    int min = 1) {
    if (token >= w.size()) return w.fail(token, std::string("expected ") + what, usage);
    if (!to_int(w.text(token), out) || out < min)
        return w.fail(token, std::string("expected ") + what + ", got '" + w.word(token) + "'", usage);
    return ok();
}

// ---- groups -------------------------------------------------------------------------------------------

Result<ScriptStep> parse_group(const LineWords& w) {
    return structure_step(steps::Group{w.size() > 1 ? w.rest(1) : std::string()});
}

template <class T>
Result<ScriptStep> one_word(const LineWords& w) {
    if (auto r = w.need(1, 1, w.word(0)); !r) return r.error();
    return structure_step(T{});
}

Result<ScriptStep> parse_enter(const LineWords& w) {
    steps::Enter step;
    if (auto r = w.need(2, 2, "enter GROUP"); !r) return r.error();
    if (auto r = number(w, 1, step.group, "a group id", "enter GROUP"); !r) return r.error();
    return structure_step(step);
}

Result<ScriptStep> parse_pick(const LineWords& w) {
    steps::Pick step;
    size_t at = 1;
    if (w.size() > 1 && (w.text(1) == "add" || w.text(1) == "toggle")) {
        step.mode = w.text(1) == "add" ? SelectMode::Add : SelectMode::Toggle;
        at = 2;
    }
    if (auto r = w.need(at + 1, at + 1, kPickUsage); !r) return r.error();
    if (auto r = number(w, at, step.entity_id, "an entity id", kPickUsage); !r) return r.error();
    return structure_step(step);
}

// ---- layers -------------------------------------------------------------------------------------------

Result<ScriptStep> parse_layer(const LineWords& w) {
    if (w.size() < 3) return w.fail(w.size(), "missing words", kLayerUsage);
    if (w.text(1) == "add") return structure_step(steps::LayerAdd{w.rest(2)});
    const std::string layer = w.word(1);
    const std::string_view verb = w.text(2);
    if (verb == "rename") {
        if (w.size() < 4) return w.fail(3, "expected the new name", kLayerUsage);
        return structure_step(steps::LayerRename{layer, w.rest(3)});
    }
    static constexpr std::string_view kVerbs[] = {"remove", "show",   "hide", "lock",
                                                  "unlock", "active", "move"};
    if (std::find(std::begin(kVerbs), std::end(kVerbs), verb) == std::end(kVerbs))
        return w.fail(2, "unknown layer command '" + w.word(2) + "'", kLayerUsage);
    if (auto r = w.need(3, 3, kLayerUsage); !r) return r.error();
    if (verb == "remove") return structure_step(steps::LayerRemove{layer});
    if (verb == "show" || verb == "hide") return structure_step(steps::LayerVisible{layer, verb == "show"});
    if (verb == "lock" || verb == "unlock") return structure_step(steps::LayerLocked{layer, verb == "lock"});
    if (verb == "active") return structure_step(steps::LayerActive{layer});
    return structure_step(steps::LayerMove{layer});
}

// ---- prefabs ------------------------------------------------------------------------------------------

Result<ScriptStep> parse_prefab_save(const LineWords& w) {
    steps::PrefabSave step;
    step.name = w.word(2);
    for (size_t i = 3; i < w.size(); ++i) {
        if (w.text(i) == "replace") {
            step.replace = true;
        } else if (w.text(i) == "title" && i + 1 < w.size()) {
            step.title = w.rest(i + 1);
            break;
        } else {
            return w.fail(i, "expected 'replace' or 'title TEXT...'", kPrefabUsage);
        }
    }
    return structure_step(std::move(step));
}

Result<ScriptStep> parse_prefab_place(const LineWords& w) {
    steps::PrefabPlace step;
    step.name = w.word(2);
    if (w.size() < 5 || w.text(3) != "at") return w.fail(3, "expected 'at X,Y,Z'", kPrefabUsage);
    if (!to_vec3(w.text(4), step.position))
        return w.fail(4, "expected three numbers separated by commas, got '" + w.word(4) + "'", kPrefabUsage);
    if (w.size() == 5) return structure_step(std::move(step));
    if (w.size() != 7 || w.text(5) != "yaw" || !to_float(w.text(6), step.yaw))
        return w.fail(5, "expected 'yaw DEGREES'", kPrefabUsage);
    return structure_step(std::move(step));
}

Result<ScriptStep> parse_prefab_group(const LineWords& w, std::string_view verb) {
    int group = 0;
    if (verb == "revert") {
        steps::PrefabRevert step;
        if (auto r = w.need(3, 5, kPrefabUsage); !r) return r.error();
        if (auto r = number(w, 2, step.group, "a group id", kPrefabUsage); !r) return r.error();
        if (w.size() > 3)
            if (auto r = number(w, 3, step.entity_id, "an entity id", kPrefabUsage); !r) return r.error();
        if (w.size() > 4) step.field = w.word(4);
        return structure_step(std::move(step));
    }
    if (auto r = w.need(3, 3, kPrefabUsage); !r) return r.error();
    if (auto r = number(w, 2, group, "a group id", kPrefabUsage); !r) return r.error();
    if (verb == "apply") return structure_step(steps::PrefabApply{group});
    return structure_step(steps::PrefabUnlink{group});
}

Result<ScriptStep> parse_prefab(const LineWords& w) {
    if (w.size() < 2) return w.fail(1, "missing words", kPrefabUsage);
    const std::string_view verb = w.text(1);
    if (verb == "update") {
        if (auto r = w.need(2, 2, kPrefabUsage); !r) return r.error();
        return structure_step(steps::PrefabUpdate{});
    }
    if (w.size() < 3) return w.fail(2, "missing words", kPrefabUsage);
    if (verb == "folder") return structure_step(steps::PrefabFolder{w.rest(2)});
    if (verb == "save") return parse_prefab_save(w);
    if (verb == "place") return parse_prefab_place(w);
    if (verb == "apply" || verb == "unlink" || verb == "revert") return parse_prefab_group(w, verb);
    return w.fail(1, "unknown prefab command '" + std::string(verb) + "'", kPrefabUsage);
}

// ---- expectations -------------------------------------------------------------------------------------

// expect groups|layers|open_group N.
template <class T>
Result<ScriptStep> expect_number(const LineWords& w, const char* what, const char* usage) {
    T step;
    if (auto r = w.need(3, 3, usage); !r) return r.error();
    int& value = [&]() -> int& {
        if constexpr (requires { step.count; })
            return step.count;
        else
            return step.group;
    }();
    if (auto r = number(w, 2, value, what, usage, 0); !r) return r.error();
    return structure_step(step);
}

Result<ScriptStep> parse_expect_group(const LineWords& w) {
    constexpr const char* usage = "expect group GROUP N";
    steps::ExpectGroup step;
    if (auto r = w.need(4, 4, usage); !r) return r.error();
    if (auto r = number(w, 2, step.group, "a group id", usage); !r) return r.error();
    if (auto r = number(w, 3, step.count, "a count of entities", usage, 0); !r) return r.error();
    return structure_step(step);
}

Result<ScriptStep> parse_expect_layer(const LineWords& w) {
    steps::ExpectLayer step;
    if (auto r = w.need(4, 6, kLayerExpectUsage); !r) return r.error();
    step.layer = w.word(2);
    if (auto r = number(w, 3, step.count, "a count of entities", kLayerExpectUsage, 0); !r) return r.error();
    for (size_t i = 4; i < w.size(); ++i) {
        const std::string state = w.word(i);
        if (state != "visible" && state != "hidden" && state != "locked" && state != "unlocked")
            return w.fail(i, "expected visible, hidden, locked or unlocked", kLayerExpectUsage);
        step.state.push_back(state);
    }
    return structure_step(std::move(step));
}

Result<ScriptStep> parse_expect_instance(const LineWords& w) {
    steps::ExpectInstance step;
    if (auto r = w.need(5, 5, kInstanceUsage); !r) return r.error();
    if (auto r = number(w, 2, step.group, "a group id", kInstanceUsage); !r) return r.error();
    step.prefab = w.word(3);
    if (auto r = number(w, 4, step.count, "a count of members", kInstanceUsage, 0); !r) return r.error();
    return structure_step(std::move(step));
}

Result<ScriptStep> parse_expect_override(const LineWords& w, bool wanted) {
    const char* usage = wanted ? kOverrideUsage : kNoOverrideUsage;
    steps::ExpectOverride step;
    step.wanted = wanted;
    if (auto r = w.need(5, 5, usage); !r) return r.error();
    if (auto r = number(w, 2, step.group, "a group id", usage); !r) return r.error();
    if (auto r = number(w, 3, step.entity_id, "an entity id", usage); !r) return r.error();
    step.field = w.word(4);
    return structure_step(std::move(step));
}

Result<ScriptStep> parse_expect_hidden(const LineWords& w, bool hidden) {
    const char* usage = hidden ? "expect hidden ID" : "expect shown ID";
    steps::ExpectHidden step;
    step.hidden = hidden;
    if (auto r = w.need(3, 3, usage); !r) return r.error();
    if (auto r = number(w, 2, step.entity_id, "an entity id", usage); !r) return r.error();
    return structure_step(step);
}

constexpr CommandSpec kCommands[] = {
    {"group", false, "group [NAME...]", "the selection becomes one group (Ctrl+G)", parse_group},
    {"ungroup", false, "ungroup", "dissolve the groups the selection picks (Ctrl+Shift+G)",
     one_word<steps::Ungroup>},
    {"enter", false, "enter GROUP", "enter a group (a double click in the viewport)", parse_enter},
    {"exit", false, "exit", "leave the entered group, one level up (Esc)", one_word<steps::Exit>},
    {"pick", false, kPickUsage, "select what a click on the entity selects", parse_pick},
    {"layer", false, kLayerUsage,
     "add, rename, remove, show, hide, lock, unlock a layer; make it active; "
     "move the selection there",
     parse_layer},
    {"prefab", false, kPrefabUsage, "save, place, apply, update, revert and unlink prefabs", parse_prefab},
    {"groups", true, "expect groups N", "the number of groups",
     [](const LineWords& w) { return expect_number<steps::ExpectGroups>(w, "a count", "expect groups N"); }},
    {"group", true, "expect group GROUP N", "a group's entity count (children included)", parse_expect_group},
    {"layers", true, "expect layers N", "the number of layers",
     [](const LineWords& w) { return expect_number<steps::ExpectLayers>(w, "a count", "expect layers N"); }},
    {"layer", true, kLayerExpectUsage, "a layer's entity count and state", parse_expect_layer},
    {"instance", true, kInstanceUsage, "an instance of PREFAB with N members", parse_expect_instance},
    {"override", true, kOverrideUsage, "member ID keeps FIELD as its own",
     [](const LineWords& w) { return parse_expect_override(w, true); }},
    {"no_override", true, kNoOverrideUsage, "member ID follows the prefab's FIELD",
     [](const LineWords& w) { return parse_expect_override(w, false); }},
    {"hidden", true, "expect hidden ID", "the tools hide entity ID (itself or through its layer)",
     [](const LineWords& w) { return parse_expect_hidden(w, true); }},
    {"shown", true, "expect shown ID", "the tools show entity ID",
     [](const LineWords& w) { return parse_expect_hidden(w, false); }},
    {"open_group", true, "expect open_group GROUP", "the entered group (0: none)",
     [](const LineWords& w) {
         return expect_number<steps::ExpectOpenGroup>(w, "a group id (0: none)", "expect open_group GROUP");
     }},
};

} // namespace

std::span<const CommandSpec> structure_commands() {
    return kCommands;
}

} // namespace ks::editor
