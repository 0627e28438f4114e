// The warnings about a level's logic that loads but cannot work as the designer meant: a zero-delay loop of
// doors, an objective nothing can complete (nothing completes it, it waits on a spawner nothing starts, or
// every chain of links toward it breaks: PossibleEvents), a locked door nothing frees. Links whose targets do
// not resolve are left to the errors (logic_checks.cpp).
#include "jsonio/json_path.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"
#include "level/diagnostics.h"
#include "level/logic_checks.h"

#include <algorithm>
#include <limits>

namespace ks::level {
namespace {

using jsonio::element_path;
using jsonio::member_path;

constexpr size_t kNone = std::numeric_limits<size_t>::max();
constexpr size_t kMaxLoopLinksShown = 6;

struct LinkRef {
    const Link* link = nullptr;
    size_t source = kNone;    // entity index; kNone: the level or an objective
    size_t objective = kNone; // the objective whose on_complete links hold it
    size_t target = kNone;    // entity index of a resolved, unique entity target
    std::string path;
};

std::vector<LinkRef> gather_links(const Level& level, const NameIndex& names,
                                  const std::vector<size_t>& source_index) {
    std::vector<LinkRef> refs;
    auto add = [&](const std::vector<Link>& links, size_t source, const std::string& path,
                   size_t objective = kNone) {
        if (links.size() > static_cast<size_t>(kMaxLinks)) return;
        for (size_t k = 0; k < links.size(); ++k) {
            LinkRef ref{&links[k], source, objective, kNone, element_path(path, k)};
            const auto action = action_from_name(links[k].action);
            if (action && target_kind(*action) == TargetKind::Entity) {
                const auto found = names.find(links[k].target);
                if (found.size() == 1) ref.target = found.front();
            }
            refs.push_back(std::move(ref));
        }
    };
    for (size_t i = 0; i < level.entities.size(); ++i)
        add(level.entities[i].links, i, member_path(entity_path(i, source_index), "links"));
    add(level.links, kNone, "links");
    for (size_t i = 0; i < level.objectives.size(); ++i)
        add(level.objectives[i].links, kNone, member_path(element_path("objectives", i), "links"), i);
    return refs;
}

bool is_action(const LinkRef& ref, std::initializer_list<LinkAction> actions) {
    const auto action = action_from_name(ref.link->action);
    return action && std::find(actions.begin(), actions.end(), *action) != actions.end();
}

// Strongly connected components (Tarjan, iterative: a generated level may chain thousands of links) of the
// graph `edges` (node -> successors); calls found(component) for each component that holds a cycle.
template <class Found>
void find_cycles(const std::vector<std::vector<size_t>>& edges, Found found) {
    const size_t n = edges.size();
    std::vector<size_t> index(n, kNone), low(n, 0), stack;
    std::vector<bool> on_stack(n, false);
    size_t counter = 0;
    struct Frame {
        size_t node, next_edge;
    };
    std::vector<Frame> calls;
    for (size_t root = 0; root < n; ++root) {
        if (index[root] != kNone) continue;
        calls.push_back({root, 0});
        index[root] = low[root] = counter++;
        stack.push_back(root);
        on_stack[root] = true;
        while (!calls.empty()) {
            Frame& frame = calls.back();
            const size_t v = frame.node;
            if (frame.next_edge < edges[v].size()) {
                const size_t w = edges[v][frame.next_edge++];
                if (index[w] == kNone) {
                    index[w] = low[w] = counter++;
                    stack.push_back(w);
                    on_stack[w] = true;
                    calls.push_back({w, 0});
                } else if (on_stack[w]) {
                    low[v] = std::min(low[v], index[w]);
                }
                continue;
            }
            if (low[v] == index[v]) {
                std::vector<size_t> component;
                size_t w = kNone;
                do {
                    w = stack.back();
                    stack.pop_back();
                    on_stack[w] = false;
                    component.push_back(w);
                } while (w != v);
                const bool self_loop = std::find(edges[v].begin(), edges[v].end(), v) != edges[v].end();
                if (component.size() > 1 || self_loop) found(component);
            }
            calls.pop_back();
            if (!calls.empty()) low[calls.back().node] = std::min(low[calls.back().node], low[v]);
        }
    }
}

// Only doors can loop for ever within one step: a robot dies once and an objective completes once, so a
// chain through them ends. A cycle of zero-delay door links loops when it turns some door both ways (a
// toggle, or an open and a close); one that only opens (or only closes) stops at the first door already so.
void check_door_loops(const Level& level, const std::vector<LinkRef>& refs, DiagnosticSink& sink) {
    std::vector<size_t> nodes; // indices into refs
    for (size_t i = 0; i < refs.size(); ++i) {
        const LinkRef& r = refs[i];
        if (r.source == kNone || r.target == kNone || r.link->once || r.link->delay != 0.0f) continue;
        if (level.entities[r.source].type() != EntityType::Door ||
            level.entities[r.target].type() != EntityType::Door)
            continue;
        if (is_action(r, {LinkAction::Open, LinkAction::Close, LinkAction::Toggle})) nodes.push_back(i);
    }
    if (nodes.empty()) return;
    std::vector<std::vector<size_t>> by_source(level.entities.size());
    for (size_t n = 0; n < nodes.size(); ++n) by_source[refs[nodes[n]].source].push_back(n);
    std::vector<std::vector<size_t>> edges(nodes.size());
    for (size_t n = 0; n < nodes.size(); ++n) {
        const LinkRef& from = refs[nodes[n]];
        const auto caused = events_caused(*action_from_name(from.link->action));
        for (size_t m : by_source[from.target]) {
            const auto event = event_from_name(refs[nodes[m]].link->event);
            if (event && std::find(caused.begin(), caused.end(), *event) != caused.end())
                edges[n].push_back(m);
        }
    }
    find_cycles(edges, [&](std::vector<size_t> component) {
        std::sort(component.begin(), component.end());
        std::vector<std::pair<size_t, LinkAction>> turns; // door, action
        std::string chain;
        for (size_t k = 0; k < component.size(); ++k) {
            const LinkRef& r = refs[nodes[component[k]]];
            turns.emplace_back(r.target, *action_from_name(r.link->action));
            if (k < kMaxLoopLinksShown)
                chain += (k ? "; " : "") + jsonio::quote_text(level.entities[r.source].name) + " " +
                         r.link->event + " -> " + r.link->action + " " + jsonio::quote_text(r.link->target);
        }
        if (component.size() > kMaxLoopLinksShown) chain += "; ...";
        bool both_ways = false;
        for (const auto& turn : turns) {
            const size_t door = turn.first;
            auto turned = [&](LinkAction a) {
                return std::any_of(turns.begin(), turns.end(),
                                   [&](const auto& t) { return t.first == door && t.second == a; });
            };
            both_ways |=
                turn.second == LinkAction::Toggle || (turned(LinkAction::Open) && turned(LinkAction::Close));
        }
        if (!both_ways) return;
        sink.warning(refs[nodes[component.front()]].path,
                     "zero-delay loop of door links (" + chain +
                         "): each sets the next off in the same step, for ever (the game cuts it off)",
                     "give one of these links a delay, or make one of them \"once\"");
        sink.tag_last(Diagnostic::Kind::LogicLoop);
    });
}

void check_reachability(const Level& level, const NameIndex& names, const std::vector<LinkRef>& refs,
                        DiagnosticSink& sink, const std::vector<size_t>& source_index) {
    std::vector<bool> spawned(level.entities.size()), freed(level.entities.size()),
        enabled(level.entities.size());
    std::vector<std::string> completed;
    for (const LinkRef& r : refs) {
        if (is_action(r, {LinkAction::Complete})) completed.push_back(r.link->target);
        if (r.target == kNone) continue;
        if (is_action(r, {LinkAction::Spawn})) spawned[r.target] = true;
        if (is_action(r, {LinkAction::Unlock, LinkAction::Open, LinkAction::Toggle})) freed[r.target] = true;
        if (is_action(r, {LinkAction::Enable})) enabled[r.target] = true;
    }
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& e = level.entities[i];
        const std::string path = entity_path(i, source_index);
        SubjectScope scope(sink, entity_subject(e));
        if (const auto* door = e.try_as<DoorProps>(); door && door->locked && !door->open && !freed[i]) {
            sink.warning(member_path(member_path(path, "props"), "locked"),
                         "the door is locked and no link unlocks or opens it: the player can never pass",
                         "add a link with \"action\": \"unlock\" (or \"open\") and \"target\": " +
                             jsonio::quote_text(e.name));
            sink.tag_last(Diagnostic::Kind::LockedDoor);
        }
        if (const auto* trigger = e.try_as<TriggerProps>();
            trigger && !trigger->enabled && !enabled[i] && !e.links.empty()) {
            sink.warning(member_path(member_path(path, "props"), "enabled"),
                         "the trigger starts disabled and no link enables it: its links never fire",
                         "set \"enabled\": true, or add a link with \"action\": \"enable\" and \"target\": " +
                             jsonio::quote_text(e.name));
            sink.tag_last(Diagnostic::Kind::DisabledTrigger);
        }
    }
    for (size_t i = 0; i < level.objectives.size(); ++i) {
        const Objective& o = level.objectives[i];
        const std::string path = element_path("objectives", i);
        SubjectScope scope(sink, "objective " + jsonio::quote_text(o.id));
        const bool by_link = std::find(completed.begin(), completed.end(), o.id) != completed.end();
        if (o.kill.empty() && !by_link) {
            sink.warning(path,
                         "nothing completes the objective (no link completes it and it lists nothing to "
                         "kill), so the level can never be won",
                         "add a link with \"action\": \"complete\" and \"target\": " +
                             jsonio::quote_text(o.id) + ", or list robots or spawners under \"kill\"");
            sink.tag_last(Diagnostic::Kind::ObjectiveNeverCompletes);
            continue;
        }
        if (by_link) continue;
        for (size_t k = 0; k < o.kill.size(); ++k) {
            const auto found = names.find(o.kill[k]);
            if (found.size() == 1 && level.entities[found.front()].type() == EntityType::Spawner &&
                !spawned[found.front()]) {
                sink.warning(element_path(member_path(path, "kill"), k),
                             "spawner " + jsonio::quote_text(o.kill[k]) +
                                 " never spawns, so the objective can never complete",
                             "add a link that spawns it, or remove it from \"kill\"");
                sink.tag_last(Diagnostic::Kind::ObjectiveNeverCompletes);
            }
        }
    }
}

// What can happen in a level, read from its links alone and optimistically: the player is assumed to reach
// every place and to do everything (the editor's reachability rule judges the geometry). An event left out
// can never happen, whatever the player does: a trigger that starts disabled and is enabled only by links
// that never fire, a door locked for good, a spawner nothing that happens starts, an objective waiting on
// them. Found by iterating to a fixed point (each pass fires the links whose events became possible).
class PossibleEvents {
  public:
    PossibleEvents(const Level& level, const NameIndex& names, const std::vector<LinkRef>& refs)
        : level_(level), names_(names), refs_(refs), enabled_(level.entities.size()),
          freed_(level.entities.size()), spawns_(level.entities.size()), completed_(level.objectives.size()),
          done_(level.objectives.size()) {
        for (size_t pass = 0; pass <= refs.size() + level.objectives.size(); ++pass)
            if (!fire_all()) break;
    }
    bool done(size_t objective) const { return done_[objective]; }
    bool wins() const { return won_; }

    bool happens(size_t i, LinkEvent event) const {
        const Entity& e = level_.entities[i];
        const auto events = entity_events(e.type());
        if (std::find(events.begin(), events.end(), event) == events.end()) return false;
        if (const auto* t = e.try_as<TriggerProps>()) return t->enabled || enabled_[i];
        if (const auto* d = e.try_as<DoorProps>()) return !d->locked || d->open || freed_[i];
        return true; // robots die and notice, panels and lights are used, pickups taken
    }
    bool fires(const LinkRef& r) const {
        const auto event = event_from_name(r.link->event);
        if (!event) return false;
        if (r.source != kNone) return happens(r.source, *event);
        if (r.objective != kNone) return *event == kObjectiveEvent && done_[r.objective];
        return *event == kLevelEvent;
    }
    // Why link `r` never fires, as a phrase.
    std::string why_not(const LinkRef& r) const {
        if (r.objective != kNone)
            return "objective " + jsonio::quote_text(level_.objectives[r.objective].id) + " never completes";
        if (r.source == kNone) return "the level's links fire on on_start only";
        const Entity& e = level_.entities[r.source];
        const std::string who = std::string(type_name(e.type())) + " " + jsonio::quote_text(e.name);
        if (e.try_as<TriggerProps>()) return who + " starts disabled and nothing that can happen enables it";
        if (e.try_as<DoorProps>()) return who + " is locked and nothing that can happen unlocks or opens it";
        return who + " never emits " + r.link->event;
    }
    // Whether a name in an objective's kill list can die: a robot can; a spawner's robots can once it spawns.
    bool killable(const std::string& name) const {
        const auto found = names_.find(name);
        if (found.size() != 1) return false;
        const Entity& e = level_.entities[found.front()];
        return e.type() == EntityType::Robot || (e.type() == EntityType::Spawner && spawns_[found.front()]);
    }
    size_t objective_index(const std::string& id) const {
        for (size_t j = 0; j < level_.objectives.size(); ++j)
            if (level_.objectives[j].id == id) return j;
        return kNone;
    }

  private:
    // One pass: fire every link whose event can happen; true when something new became possible.
    bool fire_all() {
        bool changed = false;
        auto set = [&changed](std::vector<bool>::reference flag) {
            if (!flag) flag = true, changed = true;
        };
        for (const LinkRef& r : refs_) {
            if (!fires(r)) continue;
            const auto action = action_from_name(r.link->action);
            if (!action) continue;
            if (*action == LinkAction::Complete) {
                if (const size_t j = objective_index(r.link->target); j != kNone) set(completed_[j]);
            } else if (*action == LinkAction::Win) {
                if (!won_) won_ = true, changed = true;
            } else if (r.target != kNone) {
                if (*action == LinkAction::Enable) set(enabled_[r.target]);
                if (*action == LinkAction::Spawn) set(spawns_[r.target]);
                if (is_action(r, {LinkAction::Unlock, LinkAction::Open, LinkAction::Toggle}))
                    set(freed_[r.target]);
            }
        }
        for (size_t j = 0; j < level_.objectives.size(); ++j) {
            const auto& kill = level_.objectives[j].kill;
            const bool all_killable =
                !kill.empty() &&
                std::all_of(kill.begin(), kill.end(), [&](const auto& n) { return killable(n); });
            if (completed_[j] || all_killable) set(done_[j]);
        }
        return changed;
    }

    const Level& level_;
    const NameIndex& names_;
    const std::vector<LinkRef>& refs_;
    std::vector<bool> enabled_, freed_, spawns_; // per entity: a trigger enabled, a door freed, a spawner
    std::vector<bool> completed_, done_;         // per objective: a complete link fires; it completes
    bool won_ = false;
};

constexpr size_t kMaxReasonsShown = 3;

// Objectives that can never complete although something is meant to complete them (the plainer cases,
// nothing at all or a spawner no link names, are warned about in check_reachability).
void check_objectives_can_complete(const Level& level, const NameIndex& names,
                                   const std::vector<LinkRef>& refs, DiagnosticSink& sink) {
    const PossibleEvents possible(level, names, refs);
    for (size_t j = 0; j < level.objectives.size(); ++j) {
        if (possible.done(j)) continue;
        const Objective& o = level.objectives[j];
        std::vector<std::string> reasons;
        for (const LinkRef& r : refs)
            if (is_action(r, {LinkAction::Complete}) && r.link->target == o.id)
                reasons.push_back("the link completing it (" + r.link->event +
                                  ") never fires: " + possible.why_not(r));
        const bool by_link = !reasons.empty();
        for (const std::string& name : o.kill) {
            if (possible.killable(name)) continue;
            const auto found = names.find(name);
            if (found.size() != 1 || level.entities[found.front()].type() != EntityType::Spawner) continue;
            std::string why;
            for (const LinkRef& r : refs)
                if (r.target == found.front() && is_action(r, {LinkAction::Spawn})) {
                    why = possible.why_not(r);
                    break;
                }
            if (why.empty() && !by_link) continue; // no link spawns it: check_reachability says so
            reasons.push_back(
                "spawner " + jsonio::quote_text(name) + " never spawns" +
                (why.empty() ? std::string() : " (the link that spawns it never fires: " + why + ")"));
        }
        if (reasons.empty()) continue; // nothing is meant to complete it: check_reachability says so
        std::string message = "the objective can never be completed, whatever the player does: ";
        for (size_t k = 0; k < reasons.size() && k < kMaxReasonsShown; ++k)
            message += (k ? "; " : "") + reasons[k];
        if (reasons.size() > kMaxReasonsShown) message += "; ...";
        SubjectScope scope(sink, "objective " + jsonio::quote_text(o.id));
        sink.warning(
            element_path("objectives", j), message,
            "make the first link of the chain fire: enable the trigger at start, unlock the door, or "
            "complete the objective from the control panel");
        sink.tag_last(Diagnostic::Kind::ObjectiveNeverCompletes);
    }
    // A level without objectives is won by a win link: one at least must be able to fire.
    if (!level.objectives.empty()) return;
    const auto win = std::find_if(refs.begin(), refs.end(),
                                  [](const LinkRef& r) { return is_action(r, {LinkAction::Win}); });
    if (win == refs.end() || possible.wins()) return;
    sink.warning(win->path,
                 "no link that wins the level can fire, so it can never be won: " + possible.why_not(*win),
                 "make the link's event possible, or add an objective");
    sink.tag_last(Diagnostic::Kind::ObjectiveNeverCompletes);
}

} // namespace

void check_logic_design(const Level& level, const NameIndex& names, DiagnosticSink& sink,
                        const std::vector<size_t>& source_index) {
    const std::vector<LinkRef> refs = gather_links(level, names, source_index);
    check_door_loops(level, refs, sink);
    check_reachability(level, names, refs, sink, source_index);
    check_objectives_can_complete(level, names, refs, sink);
}

} // namespace ks::level
