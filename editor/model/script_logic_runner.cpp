// The script language's level-logic lines (script_logic.h) run on the Editor's logic edits, and their
// expectations checked. Every edit is the Editor's own, so a script's line is one undo step like the panel's.
#include "model/script_logic.h"

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

class LogicRunner {
  public:
    LogicRunner(Editor& editor, ScriptReport& report) : editor_(editor), report_(report) {}

    Result<void> run(const LogicStep& s) {
        switch (s.op) {
        case LogicOp::Name:
            return editor_.rename(s.entity_id, s.text);
        case LogicOp::LinkAdd: {
            auto r = editor_.link_add(s.owner, s.link);
            if (!r) return r.error();
            return ok();
        }
        case LogicOp::LinkSet:
            return link_set(s);
        case LogicOp::LinkRemove:
            return editor_.link_remove(s.owner, s.index);
        case LogicOp::ObjectiveAdd:
            return editor_.objective_add({s.text, s.value, {}, {}});
        case LogicOp::ObjectiveText:
        case LogicOp::ObjectiveKill:
        case LogicOp::ObjectiveRemove:
        case LogicOp::ObjectiveMove:
            return objective_edit(s);
        case LogicOp::ExpectLinks:
        case LogicOp::ExpectLink:
        case LogicOp::ExpectObjectives:
            return expectation(s);
        }
        return ok();
    }

  private:
    Result<const std::vector<level::Link>*> links(const LinkOwner& owner) const {
        if (const auto* list = editor_.links_of(owner)) return list;
        if (owner.kind == LinkOwner::Kind::Entity)
            return Error("no entity with id " + std::to_string(owner.entity_id));
        return missing_objective(owner.objective_id);
    }

    Error missing_objective(const std::string& id) const {
        std::vector<std::string> ids;
        for (const auto& o : editor_.level().objectives) ids.push_back(o.id);
        const std::string near = jsonio::closest_match(id, ids);
        return Error("no objective \"" + id + "\"", Location{},
                     (near.empty() ? std::string() : "did you mean \"" + near + "\"? ") +
                         (ids.empty() ? "the level has no objectives: objective add ID TEXT..."
                                      : "objectives: " + jsonio::join(ids)));
    }

    Result<void> link_set(const LogicStep& s) {
        auto list = links(s.owner);
        if (!list) return list.error();
        if (s.index >= static_cast<int>((*list)->size()))
            return Error("no link " + std::to_string(s.index + 1) + " on " + source_text(s.owner), Location{},
                         "it has " + std::to_string((*list)->size()) + " (counted from 1)");
        level::Link link = (**list)[static_cast<size_t>(s.index)];
        if (s.text == "event")
            link.event = s.value;
        else if (s.text == "target")
            link.target = s.value;
        else if (s.text == "action")
            link.action = s.value;
        else if (s.text == "delay")
            link.delay = s.link.delay;
        else
            link.once = s.link.once;
        return editor_.link_set(s.owner, s.index, std::move(link));
    }

    Result<void> objective_edit(const LogicStep& s) {
        const auto& objectives = editor_.level().objectives;
        int index = -1;
        for (size_t i = 0; i < objectives.size() && index < 0; ++i)
            if (objectives[i].id == s.text) index = static_cast<int>(i);
        if (index < 0) return missing_objective(s.text);
        level::Objective objective = objectives[static_cast<size_t>(index)];
        switch (s.op) {
        case LogicOp::ObjectiveText:
            objective.text = s.value;
            return editor_.objective_set(index, std::move(objective));
        case LogicOp::ObjectiveKill:
            objective.kill = s.words;
            return editor_.objective_set(index, std::move(objective));
        case LogicOp::ObjectiveRemove:
            return editor_.objective_remove(index);
        default:
            if (s.index >= static_cast<int>(objectives.size()))
                return Error("no position " + std::to_string(s.index + 1) + " among the objectives",
                             Location{},
                             "the level has " + std::to_string(objectives.size()) + " (counted from 1)");
            return editor_.objective_move(index, s.index);
        }
    }

    Result<void> expect(bool condition, std::string message) {
        ++report_.expectations_checked;
        if (!condition) return Error("expectation failed: " + std::move(message));
        return ok();
    }

    Result<void> expectation(const LogicStep& s) {
        if (s.op == LogicOp::ExpectObjectives) {
            const size_t n = editor_.level().objectives.size();
            return expect(n == static_cast<size_t>(s.count), "the level has " + std::to_string(n) +
                                                                 " objectives, expected " +
                                                                 std::to_string(s.count));
        }
        auto list = links(s.owner);
        if (!list) return list.error();
        const std::vector<level::Link>& have = **list;
        const std::string source = source_text(s.owner);
        if (s.op == LogicOp::ExpectLinks)
            return expect(have.size() == static_cast<size_t>(s.count),
                          source + " has " + std::to_string(have.size()) + " links, expected " +
                              std::to_string(s.count));
        if (s.index >= static_cast<int>(have.size()))
            return expect(false, source + " has " + std::to_string(have.size()) + " links, no link " +
                                     std::to_string(s.index + 1));
        const level::Link& actual = have[static_cast<size_t>(s.index)];
        return expect(actual == s.link, "link " + std::to_string(s.index + 1) + " of " + source + " is '" +
                                            link_text(actual) + "', expected '" + link_text(s.link) + "'");
    }

    Editor& editor_;
    ScriptReport& report_;
};

} // namespace

Result<void> run_logic_step(const LogicStep& step, Editor& editor, ScriptReport& report) {
    return LogicRunner(editor, report).run(step);
}

} // namespace ks::editor
