#pragma once
// The level logic's problems as the inspector shows them beside the links, objectives and kill lists they
// are about: the level checks' errors and design warnings (level/logic_checks.h, the same the loader and
// validation report), each with the JSON path it names, found again by the path of the list being drawn.
#include "level/level.h"
#include "model/logic_edit.h"

#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

struct LogicProblem {
    std::string path; // "entities[12].links[0].target", "objectives[1].kill[0]", "links[0]"
    std::string message, hint;
    bool error = true; // else a design warning
};

// Every problem of the level's logic (check_logic), in the order found.
std::vector<LogicProblem> logic_problems(const level::Level& level);

// The path of `owner`'s list of links in the level file ("entities[12].links", "objectives[1].links",
// "links"); empty when there is no such owner.
std::string links_path(const level::Level& level, const LinkOwner& owner);

// The problems about `path` itself or anything under it ("path.x", "path[2]"), in `problems`' order.
std::vector<const LogicProblem*> problems_at(const std::vector<LogicProblem>& problems,
                                             std::string_view path);

} // namespace ks::editor
