// The script language's level-logic steps (script_logic.h) run on the Editor's logic edits, and their
// expectations checked. Every edit is the Editor's own, so a script's line is one undo step like the panel's.
#include "model/edit_entities.h"
#include "model/edit_logic.h"
#include "model/script_command.h"

#include "jsonio/number_text.h"
#include "jsonio/suggest.h"

namespace ks::editor {
namespace {

std::string link_text(const level::Link& link) {
    std::string s = link.event + " " + link.target + " " + link.action;
    if (link.delay != 0.0f) s += " delay " + jsonio::format_readable(jsonio::float_to_double(link.delay));
    if (link.once) s += " once";
    return s;
}

std::string source_text(const LinkOwner& owner) {
    switch (owner.kind) {
    case LinkOwner::Kind::Entity:
        return std::to_string(owner.entity_id);
    case LinkOwner::Kind::Objective:
        return "objective:" + owner.objective_id;
    case LinkOwner::Kind::Level:
        return "level";
    }
    return {};
}

Error missing_objective(const Editor& editor, const std::string& id) {
    std::vector<std::string> ids;
    for (const auto& o : editor.level().objectives) ids.push_back(o.id);
    const std::string near = jsonio::closest_match(id, ids);
    return Error("no objective \"" + id + "\"", Location{},
                 (near.empty() ? std::string() : "did you mean \"" + near + "\"? ") +
                     (ids.empty() ? "the level has no objectives: objective add ID TEXT..."
                                  : "objectives: " + jsonio::join(ids)));
}

Result<const std::vector<level::Link>*> links(const Editor& editor, const LinkOwner& owner) {
    if (const auto* list = links_of(editor, owner)) return list;
    if (owner.kind == LinkOwner::Kind::Entity)
        return Error("no entity with id " + std::to_string(owner.entity_id));
    return missing_objective(editor, owner.objective_id);
}

// The position of objective `id`, or an error with a did-you-mean.
Result<int> objective_index(const Editor& editor, const std::string& id) {
    const auto& objectives = editor.level().objectives;
    for (size_t i = 0; i < objectives.size(); ++i)
        if (objectives[i].id == id) return static_cast<int>(i);
    return missing_objective(editor, id);
}

// Objective `id` edited by `edit`, then set back in one undo step.
template <class Edit>
Result<void> edit_objective(Editor& editor, const std::string& id, Edit edit) {
    auto index = objective_index(editor, id);
    if (!index) return index.error();
    level::Objective objective = editor.level().objectives[static_cast<size_t>(*index)];
    edit(objective);
    return objective_set(editor, *index, std::move(objective));
}

} // namespace

Result<void> LogicStep::run(ScriptContext& c) const {
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

namespace steps {

Result<void> Name::run(ScriptContext& c) const {
    return rename(c.editor, entity_id, name);
}

Result<void> LinkAdd::run(ScriptContext& c) const {
    auto r = link_add(c.editor, owner, link);
    if (!r) return r.error();
    return ok();
}

Result<void> LinkSet::run(ScriptContext& c) const {
    auto list = links(c.editor, owner);
    if (!list) return list.error();
    if (index >= static_cast<int>((*list)->size()))
        return Error("no link " + std::to_string(index + 1) + " on " + source_text(owner), Location{},
                     "it has " + std::to_string((*list)->size()) + " (counted from 1)");
    level::Link changed = (**list)[static_cast<size_t>(index)];
    if (field == "event")
        changed.event = value;
    else if (field == "target")
        changed.target = value;
    else if (field == "action")
        changed.action = value;
    else if (field == "delay")
        changed.delay = link.delay;
    else
        changed.once = link.once;
    return link_set(c.editor, owner, index, std::move(changed));
}

Result<void> LinkRemove::run(ScriptContext& c) const {
    return link_remove(c.editor, owner, index);
}

Result<void> ObjectiveAdd::run(ScriptContext& c) const {
    return objective_add(c.editor, {id, text, {}, {}});
}
Result<void> ObjectiveText::run(ScriptContext& c) const {
    return edit_objective(c.editor, id, [&](level::Objective& o) { o.text = text; });
}
Result<void> ObjectiveKill::run(ScriptContext& c) const {
    return edit_objective(c.editor, id, [&](level::Objective& o) { o.kill = names; });
}
Result<void> ObjectiveRemove::run(ScriptContext& c) const {
    auto at = objective_index(c.editor, id);
    if (!at) return at.error();
    return objective_remove(c.editor, *at);
}
Result<void> ObjectiveMove::run(ScriptContext& c) const {
    auto at = objective_index(c.editor, id);
    if (!at) return at.error();
    const size_t count = c.editor.level().objectives.size();
    if (index >= static_cast<int>(count))
        return Error("no position " + std::to_string(index + 1) + " among the objectives", Location{},
                     "the level has " + std::to_string(count) + " (counted from 1)");
    return objective_move(c.editor, *at, index);
}

Result<void> ExpectObjectives::run(ScriptContext& c) const {
    const size_t n = c.editor.level().objectives.size();
    return c.expect(n == static_cast<size_t>(count),
                    "the level has " + std::to_string(n) + " objectives, expected " + std::to_string(count));
}

Result<void> ExpectLinks::run(ScriptContext& c) const {
    auto list = links(c.editor, owner);
    if (!list) return list.error();
    const size_t n = (*list)->size();
    return c.expect(n == static_cast<size_t>(count), source_text(owner) + " has " + std::to_string(n) +
                                                         " links, expected " + std::to_string(count));
}

Result<void> ExpectLink::run(ScriptContext& c) const {
    auto list = links(c.editor, owner);
    if (!list) return list.error();
    const std::vector<level::Link>& have = **list;
    const std::string source = source_text(owner);
    if (index >= static_cast<int>(have.size()))
        return c.expect(false, source + " has " + std::to_string(have.size()) + " links, no link " +
                                   std::to_string(index + 1));
    const level::Link& actual = have[static_cast<size_t>(index)];
    return c.expect(actual == link, "link " + std::to_string(index + 1) + " of " + source + " is '" +
                                        link_text(actual) + "', expected '" + link_text(link) + "'");
}

} // namespace steps
} // namespace ks::editor
