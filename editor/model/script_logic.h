#pragma once
// The script language's level-logic steps: naming entities for links, links of an entity, an objective or
// the level, objectives, and their expectations; parsed and registered by script_logic_parser.cpp, run on
// the Editor's logic edits (logic_edit.h) by script_logic_runner.cpp. Links and objective positions are
// kept counted from 0 (scripts count from 1).
#include "model/editor.h"
#include "model/logic_edit.h"

#include <string>
#include <variant>
#include <vector>

namespace ks::editor {

struct ScriptContext;

namespace steps {

struct Name {
    int entity_id = 0;
    std::string name;
    Result<void> run(ScriptContext& c) const;
};
struct LinkAdd {
    LinkOwner owner;
    level::Link link;
    Result<void> run(ScriptContext& c) const;
};
// One field of a link: `field` is event, target, action, delay or once; event, target and action take
// `value`, delay and once `link`'s.
struct LinkSet {
    LinkOwner owner;
    int index = 0;
    std::string field, value;
    level::Link link;
    Result<void> run(ScriptContext& c) const;
};
struct LinkRemove {
    LinkOwner owner;
    int index = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ObjectiveAdd {
    std::string id, text;
    Result<void> run(ScriptContext& c) const;
};
struct ObjectiveText {
    std::string id, text;
    Result<void> run(ScriptContext& c) const;
};
struct ObjectiveKill {
    std::string id;
    std::vector<std::string> names;
    Result<void> run(ScriptContext& c) const;
};
struct ObjectiveRemove {
    std::string id;
    Result<void> run(ScriptContext& c) const;
};
struct ObjectiveMove {
    std::string id;
    int index = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectLinks {
    LinkOwner owner;
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectLink {
    LinkOwner owner;
    int index = 0;
    level::Link link;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectObjectives {
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct LogicStep {
    std::variant<steps::Name, steps::LinkAdd, steps::LinkSet, steps::LinkRemove, steps::ObjectiveAdd,
                 steps::ObjectiveText, steps::ObjectiveKill, steps::ObjectiveRemove, steps::ObjectiveMove,
                 steps::ExpectLinks, steps::ExpectLink, steps::ExpectObjectives>
        step;
    Result<void> run(ScriptContext& c) const;
};

} // namespace ks::editor
