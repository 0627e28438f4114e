#include "model/logic_validation.h"

#include "level/shutdown_objective.h"

#include <algorithm>
#include <charconv>
#include <string_view>

namespace ks::editor {
namespace {
using Kind = level::Diagnostic::Kind;

// One step of a JSON path: "entities[3]" is {"entities", 3}, "props" is {"props", -1}.
struct PathStep {
    std::string_view name;
    int index = -1;
};

std::vector<PathStep> split_path(std::string_view path) {
    std::vector<PathStep> steps;
    while (!path.empty()) {
        const size_t dot = path.find('.');
        std::string_view part = path.substr(0, dot);
        path.remove_prefix(dot == std::string_view::npos ? path.size() : dot + 1);
        PathStep step;
        const size_t open = part.find('[');
        step.name = part.substr(0, open);
        if (open != std::string_view::npos && part.back() == ']') {
            const std::string_view digits = part.substr(open + 1, part.size() - open - 2);
            int index = -1;
            if (std::from_chars(digits.data(), digits.data() + digits.size(), index).ec == std::errc())
                step.index = index;
        }
        steps.push_back(step);
    }
    return steps;
}

// What a logic finding's path points at: an entity, an objective or the level's own links, and in them a
// link or a kill-list name.
struct Culprit {
    const level::Entity* entity = nullptr;
    int objective = -1;
    std::optional<LinkOwner> owner;
    int link = -1;
    int kill = -1;
};

Culprit culprit_at(const level::Level& level, std::string_view path) {
    Culprit c;
    const std::vector<PathStep> steps = split_path(path);
    if (steps.empty()) return c;
    size_t next = 1;
    const PathStep& first = steps.front();
    if (first.name == "entities" && first.index >= 0 &&
        static_cast<size_t>(first.index) < level.entities.size()) {
        c.entity = &level.entities[static_cast<size_t>(first.index)];
        c.owner = LinkOwner::entity(c.entity->id);
    } else if (first.name == "objectives" && first.index >= 0 &&
               static_cast<size_t>(first.index) < level.objectives.size()) {
        c.objective = first.index;
        c.owner = LinkOwner::objective(level.objectives[static_cast<size_t>(first.index)].id);
    } else if (first.name == "links") {
        c.owner = LinkOwner::level();
        next = 0;
    }
    if (next < steps.size() && steps[next].name == "links") c.link = steps[next].index;
    if (next < steps.size() && steps[next].name == "kill") c.kill = steps[next].index;
    return c;
}

const std::vector<level::Link>* links_at(const level::Level& level, const Culprit& c) {
    if (c.entity) return &c.entity->links;
    if (c.objective >= 0) return &level.objectives[static_cast<size_t>(c.objective)].links;
    if (c.owner) return &level.links;
    return nullptr;
}

const level::Link* link_at(const level::Level& level, const Culprit& c) {
    const auto* links = links_at(level, c);
    if (!links || c.link < 0 || static_cast<size_t>(c.link) >= links->size()) return nullptr;
    return &(*links)[static_cast<size_t>(c.link)];
}

QuickFix dangling_fix(const level::Level& level, const Culprit& c, const std::string& suggestion) {
    if (const level::Link* link = link_at(level, c)) {
        if (suggestion.empty()) return {"Remove the link", fixes::RemoveLink{*c.owner, c.link}};
        level::Link retargeted = *link;
        retargeted.target = suggestion;
        return {"Retarget to " + in_quotes(suggestion), fixes::SetLink{*c.owner, c.link, retargeted}};
    }
    if (c.objective >= 0 && c.kill >= 0 &&
        static_cast<size_t>(c.kill) < level.objectives[static_cast<size_t>(c.objective)].kill.size()) {
        if (suggestion.empty())
            return {"Remove from the kill list", fixes::RemoveKillName{c.objective, c.kill}};
        return {"Rename to " + in_quotes(suggestion), fixes::SetKillName{c.objective, c.kill, suggestion}};
    }
    return {};
}

QuickFix loop_fix(const level::Level& level, const Culprit& c) {
    const level::Link* link = link_at(level, c);
    if (!link) return {};
    level::Link delayed = *link;
    delayed.delay = kLoopBreakDelay;
    return {"Delay this link by 0.1 s", fixes::SetLink{*c.owner, c.link, delayed}};
}

// Nothing completes the objective: using the control panel will, when the level has one.
QuickFix objective_fix(const level::Level& level, const Culprit& c) {
    if (c.objective < 0 || c.kill >= 0) return {}; // a spawner nothing starts: the hint says what to add
    for (const level::Entity& e : level.entities) {
        if (e.type() != level::EntityType::ControlPanel) continue;
        level::Link link = level::shutdown_link();
        link.target = level.objectives[static_cast<size_t>(c.objective)].id;
        return {"Complete it at the control panel", fixes::AddLink{LinkOwner::entity(e.id), link}};
    }
    return {};
}

Rule rule_of(Kind kind) {
    switch (kind) {
    case Kind::DanglingTarget:
        return Rule::LinkTarget;
    case Kind::LogicLoop:
        return Rule::LogicLoop;
    case Kind::ObjectiveNeverCompletes:
        return Rule::Objective;
    case Kind::LockedDoor:
        return Rule::LockedDoor;
    case Kind::DisabledTrigger: // a trigger that can never fire, like one no one can walk into
        return Rule::TriggerReach;
    case Kind::UnknownTexture: // not a logic finding: validation.cpp makes it a texture issue
    case Kind::Other:
        break;
    }
    return Rule::Format;
}

} // namespace

void check_level_can_be_won(const level::Level& level, std::vector<Issue>& out) {
    if (!level.objectives.empty()) return;
    auto wins = [](const std::vector<level::Link>& links) {
        return std::any_of(links.begin(), links.end(),
                           [](const level::Link& l) { return l.action == "win"; });
    };
    if (wins(level.links)) return;
    bool panel = false;
    for (const level::Entity& e : level.entities) {
        if (wins(e.links)) return;
        panel |= e.type() == level::EntityType::ControlPanel;
    }
    Issue issue;
    issue.rule = Rule::Objective;
    issue.severity = IssueSeverity::Warning;
    issue.message = "the level has no objectives and no link wins it, so it can never be won";
    issue.message += panel ? " (using the control panel does nothing until an objective asks for it)"
                           : "; add an objective, or a link with the action win";
    if (panel) {
        issue.fix = {"Add the objective \"" + std::string(level::kShutdownObjective) +
                         "\": use the control panel",
                     fixes::AddShutdownObjective{}};
    }
    out.push_back(std::move(issue));
}

Issue logic_issue(const level::Level& level, const level::Diagnostic& d) {
    Issue issue;
    issue.rule = rule_of(d.kind);
    issue.severity =
        d.severity == level::Diagnostic::Severity::Error ? IssueSeverity::Error : IssueSeverity::Warning;
    issue.message = d.error.str();
    const Culprit c = culprit_at(level, d.error.where.path);
    issue.entity_id = c.entity ? c.entity->id : 0;
    issue.owner = c.owner;
    issue.link_index = c.link;
    switch (d.kind) {
    case Kind::DanglingTarget:
        issue.fix = dangling_fix(level, c, d.suggestion);
        break;
    case Kind::LogicLoop:
        issue.fix = loop_fix(level, c);
        break;
    case Kind::ObjectiveNeverCompletes:
        issue.fix = objective_fix(level, c);
        break;
    case Kind::LockedDoor:
        if (c.entity) issue.fix = {"Unlock the door", fixes::SetField{"locked", FieldValue(false)}};
        break;
    case Kind::DisabledTrigger:
        if (c.entity)
            issue.fix = {"Enable the trigger at start", fixes::SetField{"enabled", FieldValue(true)}};
        break;
    case Kind::UnknownTexture:
    case Kind::Other:
        break;
    }
    return issue;
}

} // namespace ks::editor
