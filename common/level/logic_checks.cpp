#include "level/logic_checks.h"
#include "level/diagnostics.h"

#include "jsonio/json_path.h"
#include "jsonio/number_text.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace ks::level {
namespace {

using jsonio::element_path;
using jsonio::join;
using jsonio::member_path;

// "Did you mean" compares a typo with every candidate; past this many misses in one level the messages go
// without it, so a generated file with a million dangling targets still loads in bounded time.
constexpr int kMaxSuggestions = 64;

// The candidate closest to `word`, while the budget lasts.
std::string closest(std::string_view word, const std::vector<std::string>& candidates, int& budget) {
    if (budget <= 0 || candidates.empty()) return {};
    --budget;
    return jsonio::closest_match(word, candidates);
}

std::string did_you_mean(const std::string& near) {
    return near.empty() ? std::string() : "did you mean " + jsonio::quote_text(near) + "? ";
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates, int& budget) {
    return did_you_mean(closest(word, candidates, budget));
}

std::vector<std::string> type_list_where(bool (*accept)(EntityType)) {
    std::vector<std::string> names;
    for (EntityType t : all_types())
        if (accept(t)) names.emplace_back(type_name(t));
    return names;
}

// Resolves links and kill lists against the level and reports what does not resolve.
class TargetChecker {
  public:
    TargetChecker(const Level& level, const NameIndex& names, DiagnosticSink& sink)
        : level_(level), names_(names), sink_(sink) {
        for (const Objective& o : level.objectives) objective_ids_.push_back(o.id);
    }

    void check(const Link& link, const std::string& path) {
        const auto action = action_from_name(link.action);
        if (!action) return; // check_links reported it
        const std::string target_path = member_path(path, "target");
        switch (target_kind(*action)) {
        case TargetKind::Level:
            if (link.target != kLevelTarget) {
                sink_.error(target_path,
                            jsonio::quote_text(link.action) + " acts on the level, not on " +
                                jsonio::quote_text(link.target),
                            "write \"target\": \"level\"");
                sink_.tag_last(Diagnostic::Kind::DanglingTarget, std::string(kLevelTarget));
            }
            return;
        case TargetKind::Objective:
            check_objective_target(link, target_path);
            return;
        case TargetKind::Entity:
            check_entity_target(link, *action, target_path);
            return;
        }
    }

    // A kill list names robots (not dummies) and spawners, each by a unique name.
    void check_kill(const std::string& name, const std::string& path) {
        const auto found = names_.find(name);
        auto killable = [](const Entity& e) {
            const auto* robot = e.try_as<RobotProps>();
            return (robot && !robot->dummy) || e.type() == EntityType::Spawner;
        };
        if (found.empty()) {
            const std::string near = closest(name, names_.names_where(level_, killable), budget_);
            sink_.error(path, "no robot or spawner named " + jsonio::quote_text(name),
                        did_you_mean(near) + "name robots and spawners by their \"name\"");
            sink_.tag_last(Diagnostic::Kind::DanglingTarget, near);
        } else if (found.size() > 1) {
            ambiguous(name, found, path);
        } else if (!killable(level_.entities[found.front()])) {
            const Entity& e = level_.entities[found.front()];
            sink_.error(path, entity_subject(e) + " cannot be killed",
                        e.try_as<RobotProps>() ? "an animation dummy never dies; name a fighting robot"
                                               : "an objective's \"kill\" lists robots and spawners");
        }
    }

  private:
    void check_objective_target(const Link& link, const std::string& path) {
        if (std::find(objective_ids_.begin(), objective_ids_.end(), link.target) != objective_ids_.end())
            return;
        const std::string near = closest(link.target, objective_ids_, budget_);
        std::string hint = did_you_mean(near);
        hint += objective_ids_.empty() ? "the level has no objectives; add one under \"objectives\""
                                       : "objectives: " + join(objective_ids_);
        sink_.error(path, "no objective " + jsonio::quote_text(link.target), hint);
        sink_.tag_last(Diagnostic::Kind::DanglingTarget, near);
    }

    void check_entity_target(const Link& link, LinkAction action, const std::string& path) {
        if (link.target.empty()) {
            sink_.error(path, "the link has no target", "name the entity it acts on");
            sink_.tag_last(Diagnostic::Kind::DanglingTarget);
            return;
        }
        const auto found = names_.find(link.target);
        if (found.empty()) {
            auto takes = [action](const Entity& e) { return entity_takes(e.type(), action); };
            std::vector<std::string> candidates = names_.names_where(level_, takes);
            const std::string near = closest(link.target, candidates, budget_);
            std::string hint = did_you_mean(near);
            hint += candidates.empty() ? "no entity in the level takes " + jsonio::quote_text(link.action)
                                       : "name the target by its \"name\"";
            sink_.error(path, "no entity named " + jsonio::quote_text(link.target), hint);
            sink_.tag_last(Diagnostic::Kind::DanglingTarget, near);
            return;
        }
        if (found.size() > 1) {
            ambiguous(link.target, found, path);
            return;
        }
        const Entity& target = level_.entities[found.front()];
        if (!entity_takes(target.type(), action)) {
            const auto actions = entity_actions(target.type());
            sink_.error(path, entity_subject(target) + " cannot " + jsonio::quote_text(link.action),
                        actions.empty() ? with_article(type_name(target.type())) + " takes no actions"
                                        : with_article(type_name(target.type())) +
                                              " takes: " + join(action_names(actions)));
        } else if (const auto* robot = target.try_as<RobotProps>(); robot && robot->dummy) {
            sink_.error(path, entity_subject(target) + " is an animation dummy: links cannot move it",
                        "target a fighting robot");
        }
    }

    void ambiguous(const std::string& name, std::span<const size_t> found, const std::string& path) {
        std::vector<std::string> holders;
        for (size_t i = 0; i < found.size() && i < 4; ++i)
            holders.push_back(entity_subject(level_.entities[found[i]]));
        if (found.size() > 4) holders.push_back("...");
        sink_.error(path,
                    jsonio::quote_text(name) + " names " + std::to_string(found.size()) + " entities (" +
                        join(holders) + ")",
                    "a name that links or objectives use must be unique; rename the others");
    }

    const Level& level_;
    const NameIndex& names_;
    DiagnosticSink& sink_;
    std::vector<std::string> objective_ids_;
    int budget_ = kMaxSuggestions;
};

void check_objectives(const Level& level, TargetChecker& targets, DiagnosticSink& sink) {
    std::unordered_set<std::string> seen;
    for (size_t i = 0; i < level.objectives.size(); ++i) {
        const Objective& o = level.objectives[i];
        const std::string path = element_path("objectives", i);
        SubjectScope scope(sink, "objective " + jsonio::quote_text(o.id));
        if (o.id.empty())
            sink.error(member_path(path, "id"), "the objective has no id",
                       "give it a short unique id, e.g. \"clear_hall\"");
        else if (!seen.insert(o.id).second)
            sink.error(member_path(path, "id"), "duplicate objective id " + jsonio::quote_text(o.id),
                       "objective ids must be unique");
        const size_t length = jsonio::character_count(o.text);
        if (o.text.empty() || length > static_cast<size_t>(kMaxMessageLength))
            sink.error(member_path(path, "text"),
                       o.text.empty() ? "the objective has no text"
                                      : "text of " + std::to_string(length) + " characters is too long",
                       "write what the player must do, in at most " + std::to_string(kMaxMessageLength) +
                           " characters");
        if (o.kill.size() > static_cast<size_t>(kMaxKillNames))
            sink.error(member_path(path, "kill"),
                       std::to_string(o.kill.size()) + " names; at most " + std::to_string(kMaxKillNames),
                       "a spawner stands for all the robots it makes");
        else
            for (size_t k = 0; k < o.kill.size(); ++k)
                targets.check_kill(o.kill[k], element_path(member_path(path, "kill"), k));
        const std::array events{kObjectiveEvent};
        const std::string links_path = member_path(path, "links");
        check_links(o.links, events, "an objective", links_path, sink);
        if (o.links.size() <= static_cast<size_t>(kMaxLinks))
            for (size_t k = 0; k < o.links.size(); ++k)
                targets.check(o.links[k], element_path(links_path, k));
    }
    if (level.objectives.size() > static_cast<size_t>(kMaxObjectives))
        sink.error("objectives",
                   std::to_string(level.objectives.size()) + " objectives; at most " +
                       std::to_string(kMaxObjectives),
                   "a level is a few objectives; merge some");
}

} // namespace

NameIndex::NameIndex(const Level& level) {
    for (size_t i = 0; i < level.entities.size(); ++i)
        if (!level.entities[i].name.empty()) by_name_[level.entities[i].name].push_back(i);
}

std::span<const size_t> NameIndex::find(std::string_view name) const {
    auto it = by_name_.find(std::string(name));
    return it == by_name_.end() ? std::span<const size_t>() : std::span<const size_t>(it->second);
}

std::string with_article(std::string_view noun) {
    const bool vowel =
        !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
    std::string out = (vowel ? "an " : "a ") + std::string(noun);
    std::replace(out.begin(), out.end(), '_', ' ');
    return out;
}

void check_links(const std::vector<Link>& links, std::span<const LinkEvent> emitted, std::string_view source,
                 const std::string& path, DiagnosticSink& sink) {
    if (links.empty()) return;
    if (links.size() > static_cast<size_t>(kMaxLinks)) {
        sink.error(path, std::to_string(links.size()) + " links; at most " + std::to_string(kMaxLinks),
                   "split the work over more entities (a trigger can start a chain), or remove links");
        return;
    }
    if (emitted.empty()) {
        const auto emitters = type_list_where([](EntityType t) { return !entity_events(t).empty(); });
        sink.error(path, std::string(source) + " emits no events, so its links never fire",
                   "links belong on " + join(emitters) + ", objectives and the level");
        return;
    }
    const std::vector<std::string> emitted_names = event_names(emitted);
    const std::vector<std::string> every_action = action_names(all_actions());
    int budget = kMaxSuggestions;
    for (size_t i = 0; i < links.size(); ++i) {
        const Link& link = links[i];
        const std::string link_path = element_path(path, i);
        const auto event = event_from_name(link.event);
        const bool emits = event && std::find(emitted.begin(), emitted.end(), *event) != emitted.end();
        if (!emits) {
            const std::string message =
                event ? std::string(source) + " does not emit " + jsonio::quote_text(link.event)
                      : "unknown event " + jsonio::quote_text(link.event);
            sink.error(member_path(link_path, "event"), message,
                       did_you_mean(link.event, emitted_names, budget) + std::string(source) +
                           " emits: " + join(emitted_names));
        }
        if (!action_from_name(link.action))
            sink.error(member_path(link_path, "action"), "unknown action " + jsonio::quote_text(link.action),
                       did_you_mean(link.action, every_action, budget) + "valid: " + join(every_action));
        if (!std::isfinite(link.delay) || link.delay < 0.0f || link.delay > static_cast<float>(kMaxLinkDelay))
            sink.error(member_path(link_path, "delay"),
                       "delay " + jsonio::readable_float(link.delay) +
                           (std::isfinite(link.delay) ? " is out of range" : " is not a finite number"),
                       "valid: 0 .. " + jsonio::format_readable(kMaxLinkDelay) +
                           " s, the seconds between the event and the action");
    }
}

void check_logic(const Level& level, DiagnosticSink& sink, const std::vector<size_t>& source_index) {
    const NameIndex names(level);
    TargetChecker targets(level, names, sink);
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& e = level.entities[i];
        if (e.links.empty() || e.links.size() > static_cast<size_t>(kMaxLinks) ||
            entity_events(e.type()).empty())
            continue; // check_entity reported the list itself
        SubjectScope scope(sink, entity_subject(e));
        const std::string path = member_path(entity_path(i, source_index), "links");
        for (size_t k = 0; k < e.links.size(); ++k) targets.check(e.links[k], element_path(path, k));
    }
    {
        SubjectScope scope(sink, "the level");
        const std::array events{kLevelEvent};
        check_links(level.links, events, "the level", "links", sink);
        if (level.links.size() <= static_cast<size_t>(kMaxLinks))
            for (size_t k = 0; k < level.links.size(); ++k)
                targets.check(level.links[k], element_path("links", k));
    }
    check_objectives(level, targets, sink);
    check_logic_design(level, names, sink, source_index);
}

} // namespace ks::level
