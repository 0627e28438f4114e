#include "view/link_problems.h"

#include "jsonio/json_path.h"
#include "level/diagnostics.h"
#include "level/logic_checks.h"

namespace ks::editor {

std::vector<LogicProblem> logic_problems(const level::Level& level) {
    level::DiagnosticSink sink("");
    level::check_logic(level, sink);
    std::vector<LogicProblem> out;
    for (const auto& d : sink.take_sorted())
        out.push_back({d.error.where.path, d.error.message, d.error.hint,
                       d.severity == level::Diagnostic::Severity::Error});
    return out;
}

std::string links_path(const level::Level& level, const LinkOwner& owner) {
    switch (owner.kind) {
    case LinkOwner::Kind::Level:
        return "links";
    case LinkOwner::Kind::Entity:
        for (size_t i = 0; i < level.entities.size(); ++i)
            if (level.entities[i].id == owner.entity_id)
                return jsonio::member_path(jsonio::element_path("entities", i), "links");
        return {};
    case LinkOwner::Kind::Objective:
        for (size_t i = 0; i < level.objectives.size(); ++i)
            if (level.objectives[i].id == owner.objective_id)
                return jsonio::member_path(jsonio::element_path("objectives", i), "links");
        return {};
    }
    return {};
}

std::vector<const LogicProblem*> problems_at(const std::vector<LogicProblem>& problems,
                                             std::string_view path) {
    std::vector<const LogicProblem*> out;
    if (path.empty()) return out;
    for (const auto& p : problems) {
        const std::string_view at = p.path;
        if (!at.starts_with(path)) continue;
        if (at.size() == path.size() || at[path.size()] == '.' || at[path.size()] == '[') out.push_back(&p);
    }
    return out;
}

} // namespace ks::editor
