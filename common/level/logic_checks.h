#pragma once
// The checks on a level's logic (links, objectives), shared by the loader and validate(). Errors: a link
// whose event its source does not emit, an unknown action, a target that names nothing, names two entities
// or does not take the action, a delay that is negative, NaN or over an hour, too many links; objectives
// without an id, with a duplicate id, or killing something that is not a robot or a spawner. Warnings (a
// level that loads but cannot work as meant): a zero-delay loop, an objective nothing can complete, a locked
// door nothing unlocks or opens.
#include "level/diagnostics.h"
#include "level/level.h"
#include "level/logic_names.h"

#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ks::level {

// The level's entities by name (named ones only): how link targets and kill lists are resolved, by the
// checks and by the game alike.
class NameIndex {
  public:
    explicit NameIndex(const Level& level);
    // Indices into level.entities of the entities called `name` (more than one: the name is ambiguous).
    std::span<const size_t> find(std::string_view name) const;
    // Names of the entities for which `accept(entity)` holds, for "did you mean" hints.
    template <class Accept>
    std::vector<std::string> names_where(const Level& level, Accept accept) const {
        std::vector<std::string> out;
        for (const auto& [name, indices] : by_name_)
            if (accept(level.entities[indices.front()])) out.push_back(name);
        return out;
    }

  private:
    std::unordered_map<std::string, std::vector<size_t>> by_name_;
};

// One list of links of one source: at most kMaxLinks, each with a delay in 0 .. kMaxLinkDelay, an event among
// `emitted` and a known action. `source` says what the source is in messages ("a door", "the level").
void check_links(const std::vector<Link>& links, std::span<const LinkEvent> emitted, std::string_view source,
                 const std::string& path, DiagnosticSink& sink);

// What an entity type is called in messages: "a door", "an objective".
std::string with_article(std::string_view noun);

// Level-wide: targets and kill lists resolve, objectives are well formed (errors); the design warnings.
// `source_index` as for check_level.
void check_logic(const Level& level, DiagnosticSink& sink, const std::vector<size_t>& source_index = {});

// The design warnings alone (logic_design_checks.cpp).
void check_logic_design(const Level& level, const NameIndex& names, DiagnosticSink& sink,
                        const std::vector<size_t>& source_index);

} // namespace ks::level
