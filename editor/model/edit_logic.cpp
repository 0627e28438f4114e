// The level logic's edits (links, objectives, names for link targets): edit_logic.h. Each builds one
// LevelChange and executes it through the Editor; renaming an objective takes the links that complete it
// along.
#include "model/edit_logic.h"

#include "model/edit_entities.h"

#include "jsonio/suggest.h"
#include "level/diagnostics.h"
#include "level/logic_checks.h"
#include "level/shutdown_objective.h"

#include <algorithm>
#include <optional>

namespace ks::editor {
namespace {

// An error from check_link about link `index` of a list (none: the link being added).
Error about_link(Error e, std::optional<int> index) {
    if (index) e.message = "link " + std::to_string(*index) + ": " + e.message;
    return e;
}

int objective_index(const level::Level& level, std::string_view id) {
    for (size_t i = 0; i < level.objectives.size(); ++i)
        if (level.objectives[i].id == id) return static_cast<int>(i);
    return -1;
}

std::vector<std::string> objective_ids(const level::Level& level) {
    std::vector<std::string> ids;
    for (const auto& o : level.objectives) ids.push_back(o.id);
    return ids;
}

// The objective at `index` of `list` is well formed on its own and its id is unique in the list.
Result<void> check_objective(const std::vector<level::Objective>& list, size_t index) {
    const level::Objective& o = list[index];
    const std::string subject = "objective " + in_quotes(o.id);
    if (o.id.empty())
        return Error("an objective needs an id", Location{}, "links name it: e.g. \"clear_hall\"");
    for (size_t i = 0; i < list.size(); ++i)
        if (i != index && list[i].id == o.id)
            return Error("there is already an objective " + in_quotes(o.id), Location{},
                         "objective ids must be unique; pick another");
    if (o.text.size() > static_cast<size_t>(level::kMaxMessageLength))
        return Error(subject + ": text of " + std::to_string(o.text.size()) + " characters is too long",
                     Location{}, "at most " + std::to_string(level::kMaxMessageLength) + " characters");
    if (o.kill.size() > static_cast<size_t>(level::kMaxKillNames))
        return Error(subject + ": " + std::to_string(o.kill.size()) + " names to kill; at most " +
                         std::to_string(level::kMaxKillNames),
                     Location{}, "a spawner stands for all the robots it makes");
    if (o.links.size() > static_cast<size_t>(level::kMaxLinks))
        return Error(subject + ": " + std::to_string(o.links.size()) + " links; at most " +
                         std::to_string(level::kMaxLinks),
                     Location{}, "start a chain instead");
    const std::array events{level::kObjectiveEvent};
    for (size_t k = 0; k < o.links.size(); ++k)
        if (auto r = check_link(o.links[k], events, "an objective"); !r)
            return about_link(r.error(), static_cast<int>(k));
    return ok();
}

} // namespace

const std::vector<level::Link>* links_of(const Editor& editor, const LinkOwner& owner) {
    const Document& doc = editor.doc();
    switch (owner.kind) {
    case LinkOwner::Kind::Entity: {
        const level::Entity* e = doc.level.find(owner.entity_id);
        return e ? &e->links : nullptr;
    }
    case LinkOwner::Kind::Objective: {
        const int i = objective_index(doc.level, owner.objective_id);
        return i < 0 ? nullptr : &doc.level.objectives[static_cast<size_t>(i)].links;
    }
    case LinkOwner::Kind::Level:
        return &doc.level.links;
    }
    return nullptr;
}

namespace {
Result<void> edit_links(Editor& editor, const LinkOwner& owner, std::string name,
                        const std::function<Result<void>(std::vector<level::Link>&)>& edit,
                        std::string merge_key = {}) {
    const Document& doc = editor.doc();
    const std::string subject = owner_subject(doc.level, owner);
    const std::vector<level::Link>* current = links_of(editor, owner);
    if (!current) {
        if (owner.kind == LinkOwner::Kind::Entity)
            return Error(name + ": no entity with id " + std::to_string(owner.entity_id));
        const std::vector<std::string> ids = objective_ids(doc.level);
        return Error(name + ": no objective " + in_quotes(owner.objective_id), Location{},
                     ids.empty() ? "the level has no objectives" : "objectives: " + jsonio::join(ids));
    }
    if (owner.kind == LinkOwner::Kind::Entity && doc.locked.contains(owner.entity_id))
        return Error(name + ": " + subject + " is locked", Location{}, "unlock it first");
    std::vector<level::Link> links = *current;
    if (auto r = edit(links); !r) {
        Error e = r.error();
        e.message = name + ": " + e.message;
        return e;
    }
    if (links.size() > static_cast<size_t>(level::kMaxLinks))
        return Error(name + ": " + subject + " has " + std::to_string(level::kMaxLinks) +
                         " links, the most one owner may have",
                     Location{}, "split the work over more entities (a trigger can start a chain)");
    if (links == *current) return ok(); // nothing changed: no history step
    auto change = std::make_unique<LevelChange>();
    change->set_name(name + " (" + subject + ")");
    change->merge_key = std::move(merge_key);
    switch (owner.kind) {
    case LinkOwner::Kind::Entity: {
        const level::Entity& before = *doc.level.find(owner.entity_id);
        level::Entity after = before;
        after.links = std::move(links);
        change->updates.push_back({before, std::move(after)});
        break;
    }
    case LinkOwner::Kind::Objective: {
        std::vector<level::Objective> after = doc.level.objectives;
        after[static_cast<size_t>(objective_index(doc.level, owner.objective_id))].links = std::move(links);
        change->objectives = Change<std::vector<level::Objective>>{doc.level.objectives, std::move(after)};
        break;
    }
    case LinkOwner::Kind::Level:
        change->level_links = Change<std::vector<level::Link>>{doc.level.links, std::move(links)};
        break;
    }
    editor.execute(std::move(change), doc.selection);
    return ok();
}
} // namespace

Result<int> link_add(Editor& editor, const LinkOwner& owner, level::Link link) {
    const Document& doc = editor.doc();
    int index = 0;
    const std::string subject = owner_subject(doc.level, owner);
    auto r = edit_links(editor, owner, "Add link", [&](std::vector<level::Link>& links) -> Result<void> {
        if (auto checked = check_link(link, owner_events(doc.level, owner), subject); !checked)
            return about_link(checked.error(), std::nullopt);
        index = static_cast<int>(links.size());
        links.push_back(std::move(link));
        return ok();
    });
    if (!r) return r.error();
    return index;
}

Result<void> link_set(Editor& editor, const LinkOwner& owner, int index, level::Link link,
                      std::string merge_key) {
    const Document& doc = editor.doc();
    const std::string subject = owner_subject(doc.level, owner);
    return edit_links(
        editor, owner, "Set link",
        [&](std::vector<level::Link>& links) -> Result<void> {
            if (auto r = check_index(index, links.size(), "link", subject); !r) return r;
            if (auto checked = check_link(link, owner_events(doc.level, owner), subject); !checked)
                return about_link(checked.error(), index);
            links[static_cast<size_t>(index)] = std::move(link);
            return ok();
        },
        std::move(merge_key));
}

Result<void> link_remove(Editor& editor, const LinkOwner& owner, int index) {
    const Document& doc = editor.doc();
    const std::string subject = owner_subject(doc.level, owner);
    return edit_links(editor, owner, "Remove link", [&](std::vector<level::Link>& links) -> Result<void> {
        if (auto r = check_index(index, links.size(), "link", subject); !r) return r;
        links.erase(links.begin() + index);
        return ok();
    });
}

namespace {
Result<void> edit_objectives(Editor& editor, std::string name,
                             const std::function<Result<void>(std::vector<level::Objective>&)>& edit,
                             std::string merge_key = {}, const TargetRenames& renames = {}) {
    const Document& doc = editor.doc();
    std::vector<level::Objective> objectives = doc.level.objectives;
    if (auto r = edit(objectives); !r) {
        Error e = r.error();
        e.message = name + ": " + e.message;
        return e;
    }
    if (objectives == doc.level.objectives) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name(std::move(name));
    change->merge_key = std::move(merge_key);
    change->objectives = Change<std::vector<level::Objective>>{doc.level.objectives, std::move(objectives)};
    add_retargets(doc.level, renames, *change);
    editor.execute(std::move(change), doc.selection);
    return ok();
}
} // namespace

Result<void> objective_add(Editor& editor, level::Objective objective) {
    return edit_objectives(editor, "Add objective " + in_quotes(objective.id),
                           [&](std::vector<level::Objective>& list) -> Result<void> {
                               if (list.size() >= static_cast<size_t>(level::kMaxObjectives))
                                   return Error("the level has " + std::to_string(level::kMaxObjectives) +
                                                    " objectives, the most it may have",
                                                Location{}, "a level is a few objectives; merge some");
                               list.push_back(std::move(objective));
                               return check_objective(list, list.size() - 1);
                           });
}

Result<void> objective_set(Editor& editor, int index, level::Objective objective, std::string merge_key) {
    const Document& doc = editor.doc();
    TargetRenames renames;
    if (index >= 0 && static_cast<size_t>(index) < doc.level.objectives.size()) {
        const std::string& old_id = doc.level.objectives[static_cast<size_t>(index)].id;
        const auto ids = objective_ids(doc.level);
        if (old_id != objective.id && !old_id.empty() && std::count(ids.begin(), ids.end(), old_id) == 1)
            renames.objectives.emplace(old_id, objective.id);
    }
    return edit_objectives(
        editor, "Edit objective",
        [&](std::vector<level::Objective>& list) -> Result<void> {
            if (auto r = check_index(index, list.size(), "objective", "the level"); !r) return r;
            list[static_cast<size_t>(index)] = std::move(objective);
            return check_objective(list, static_cast<size_t>(index));
        },
        std::move(merge_key), renames);
}

Result<void> objective_remove(Editor& editor, int index) {
    return edit_objectives(editor, "Remove objective",
                           [&](std::vector<level::Objective>& list) -> Result<void> {
                               if (auto r = check_index(index, list.size(), "objective", "the level"); !r)
                                   return r;
                               list.erase(list.begin() + index);
                               return ok();
                           });
}

Result<void> objective_move(Editor& editor, int from, int to) {
    return edit_objectives(
        editor, "Move objective", [&](std::vector<level::Objective>& list) -> Result<void> {
            if (auto r = check_index(from, list.size(), "objective", "the level"); !r) return r;
            if (auto r = check_index(to, list.size(), "position", "the objective list"); !r) return r;
            level::Objective moving = std::move(list[static_cast<size_t>(from)]);
            list.erase(list.begin() + from);
            list.insert(list.begin() + to, std::move(moving));
            return ok();
        });
}

Result<void> add_shutdown_objective(Editor& editor) {
    const Document& doc = editor.doc();
    level::Level after = doc.level;
    if (!level::add_shutdown_objective(after))
        return Error("the shutdown objective: nothing to add", Location{},
                     doc.level.entities.empty() ? "place a control panel first"
                                                : "it needs a control panel, and is added once");
    auto change = std::make_unique<LevelChange>();
    change->set_name("Add the shutdown objective");
    for (size_t i = 0; i < after.entities.size(); ++i)
        if (!(after.entities[i] == doc.level.entities[i]))
            change->updates.push_back({doc.level.entities[i], after.entities[i]});
    if (after.objectives != doc.level.objectives)
        change->objectives = Change<std::vector<level::Objective>>{doc.level.objectives, after.objectives};
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<std::string> ensure_link_name(Editor& editor, int entity_id) {
    const Document& doc = editor.doc();
    const level::Entity* e = doc.level.find(entity_id);
    if (!e) return Error("name for links: no entity with id " + std::to_string(entity_id));
    const level::NameIndex names(doc.level);
    if (!e->name.empty() && names.find(e->name).size() == 1) return e->name;
    // One word, so that scripts (`link 3 add on_use door_2 open`) can write it too.
    std::string base = e->name.empty() ? std::string(level::type_name(e->type())) : e->name;
    std::replace_if(
        base.begin(), base.end(), [](char c) { return c == ' ' || c == '\t'; }, '_');
    const std::string name = unique_entity_name(doc.level, base);
    if (auto r = rename(editor, entity_id, name); !r) return r.error();
    return name;
}

} // namespace ks::editor
