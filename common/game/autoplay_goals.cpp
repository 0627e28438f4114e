#include "game/autoplay_goals.h"

#include "geometry/ground_plane.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ks::game {
namespace {

using level::LinkAction;
using level::LinkEvent;

// Chains longer than this are not followed (a designer's chain is a handful of links; loops are cut before
// that, as no need is worked out twice in one choice).
constexpr int kMaxDepth = 12;
// Costs are path lengths; these rank what is not a walk: an unreachable goal below any reachable one, a wait
// below both (something that can be done beats waiting for something else to happen).
constexpr float kUnreachable = 1e5f;
constexpr float kWait = 1e6f;
constexpr float kWaitHopeless = 2e6f; // waiting where nothing found will help
// How far in front of a locked door the bot waits, and how close to a doorway a path counts as through it.
constexpr float kDoorWaitDistance = 3.0f;
constexpr float kDoorwayMargin = 0.5f;

constexpr std::array kDoorOpeners{LinkAction::Unlock, LinkAction::Open, LinkAction::Toggle};
constexpr std::array kCompleters{LinkAction::Complete};
constexpr std::array kSpawners{LinkAction::Spawn};
constexpr std::array kEnablers{LinkAction::Enable};
constexpr std::array kWinners{LinkAction::Win};

// What the search is working out: an objective by any means (`by_link` false), or a target a link must act
// on (an objective's complete link among them).
// The player takes a pickup only while below that kind's maximum (Game::take_pickup).
bool would_take(const Game& game, const Pickup& pickup) {
    const PlayerState& p = game.player();
    const GameSettings& settings = game.settings();
    switch (pickup.kind) {
    case PickupKind::Health:
        return p.health < settings.max_health;
    case PickupKind::Shield:
        return p.shield < settings.max_shield;
    case PickupKind::Ammo:
        return p.ammo < settings.max_ammo;
    }
    return false;
}

std::uint64_t search_key(LogicTarget target, std::uint32_t index, bool by_link = true) {
    return static_cast<std::uint64_t>(by_link) << 40 | static_cast<std::uint64_t>(target) << 32 | index;
}

} // namespace

const char* goal_kind_name(BotGoalKind kind) {
    switch (kind) {
    case BotGoalKind::None:
        return "none";
    case BotGoalKind::Use:
        return "use";
    case BotGoalKind::Enter:
        return "enter";
    case BotGoalKind::Hunt:
        return "hunt";
    case BotGoalKind::Pickup:
        return "pickup";
    case BotGoalKind::OpenDoor:
        return "open door";
    case BotGoalKind::Wait:
        return "wait";
    }
    return "?";
}

bool door_blocks(const Door& door) {
    return door.locked && !door.opening && door.progress < 1.0f;
}

bool close_blocking_doors(const Game& game, nav::NavMesh& mesh) {
    bool any = false;
    for (const Door& d : game.doors()) {
        const bool blocks = door_blocks(d);
        any = any || blocks;
        if (mesh.door_open(d.entity_id) == blocks) mesh.set_door_open(d.entity_id, !blocks);
    }
    return any;
}

struct GoalPlanner::Search {
    const Game& game;
    nav::NavMesh& mesh;
    Vec3 feet{0.0f};
    bool doors_block = false;
    BotGoal best;
    float best_cost = 0.0f;
    std::vector<std::uint64_t>& expanded; // needs worked out in this choice: a loop or a second way in stops
    std::vector<Vec3>& path;              // scratch
    bool enter(std::uint64_t key) {
        if (std::find(expanded.begin(), expanded.end(), key) != expanded.end()) return false;
        expanded.push_back(key);
        return true;
    }
};

GoalPlanner::GoalPlanner(const Game& game) {
    expanded_.reserve(64);
    path_.reserve(64);
    const LevelLogic& logic = game.logic();
    sources_.assign(logic.links().size(), Source{});
    auto own = [&](LinkRange range, SourceKind kind, std::size_t index) {
        for (std::uint32_t k = range.first; k < range.first + range.count && k < sources_.size(); ++k)
            sources_[k] = {kind, static_cast<std::uint32_t>(index)};
    };
    auto own_entities = [&](const auto& records, SourceKind kind) {
        for (std::size_t i = 0; i < records.size(); ++i)
            own(logic.entity_links(records[i].entity_id), kind, i);
    };
    own_entities(game.doors(), SourceKind::Door);
    own_entities(game.lights(), SourceKind::Light);
    own_entities(game.panels(), SourceKind::Panel);
    own_entities(game.pickups(), SourceKind::Pickup);
    own_entities(game.robots(), SourceKind::Robot);
    own_entities(logic.triggers(), SourceKind::Trigger);
    for (std::size_t i = 0; i < logic.objectives().size(); ++i)
        own(logic.objectives()[i].links, SourceKind::Objective, i);
    own(logic.level_links(), SourceKind::Level, 0);
}

BotGoal GoalPlanner::choose(const Game& game, nav::NavMesh& mesh) {
    expanded_.clear();
    Search s{game,
             mesh,
             game.player().feet,
             close_blocking_doors(game, mesh),
             BotGoal{},
             std::numeric_limits<float>::infinity(),
             expanded_,
             path_};
    const LevelLogic& logic = game.logic();
    // The first objective not complete; a later one only when nothing is found for it.
    for (std::size_t k = 0; k < logic.objectives().size() && s.best.kind == BotGoalKind::None; ++k)
        if (!logic.objectives()[k].completed) objective(s, k, 0);
    if (logic.objectives().empty()) action_on(s, LogicTarget::Level, 0, kWinners, s.feet, 0);
    // Nothing in the logic: as before the logic existed, the first control panel, else any robot.
    if (s.best.kind == BotGoalKind::None) {
        if (!game.panels().empty()) {
            cause(s, {SourceKind::Panel, 0}, LinkEvent::OnUse, 0);
        } else {
            for (std::size_t r = 0; r < game.robots().size(); ++r)
                if (game.robots()[r].alive()) hunt(s, static_cast<std::uint32_t>(r), 0);
        }
    }
    return s.best;
}

void GoalPlanner::objective(Search& s, std::size_t index, int depth) const {
    const ObjectiveState& o = s.game.logic().objectives()[index];
    if (o.completed || depth > kMaxDepth) return;
    if (!s.enter(search_key(LogicTarget::Objective, static_cast<std::uint32_t>(index), false))) return;
    action_on(s, LogicTarget::Objective, static_cast<std::uint32_t>(index), kCompleters, s.feet, depth);
    if (o.kill_condition) {
        for (std::uint32_t r : o.kill_robots)
            if (s.game.robots()[r].alive()) hunt(s, r, depth);
        for (std::uint32_t k : o.kill_spawners) {
            const SpawnerState& spawner = s.game.logic().spawners()[k];
            if (!spawner.started) {
                action_on(s, LogicTarget::Spawner, k, kSpawners, s.feet, depth + 1);
                continue;
            }
            bool alive = false;
            for (std::uint32_t r : spawner.robots) {
                if (!s.game.robots()[r].alive()) continue;
                alive = true;
                hunt(s, r, depth);
            }
            // Its next robot is due: wait for it where the bot stands.
            if (!alive && spawner.left > 0 && !spawner.stuck)
                offer(s, {BotGoalKind::Wait, -1, s.feet}, kWait);
        }
    }
}

void GoalPlanner::action_on(Search& s, LogicTarget target, std::uint32_t index,
                            std::span<const LinkAction> actions, const Vec3& wait_at, int depth) const {
    if (depth > kMaxDepth || !s.enter(search_key(target, index))) return;
    const LevelLogic& logic = s.game.logic();
    const auto links = logic.links();
    for (std::uint32_t k = 0; k < links.size(); ++k) {
        const LogicLink& link = links[k];
        if (link.target != target || link.target_index != index ||
            std::find(actions.begin(), actions.end(), link.action) == actions.end())
            continue;
        const auto pending = logic.pending();
        if (std::any_of(pending.begin(), pending.end(),
                        [&](const LevelLogic::Pending& p) { return p.link == k; })) {
            offer(s, {BotGoalKind::Wait, -1, wait_at}, kWait + geometry::ground_distance(s.feet, wait_at));
            continue;
        }
        if (link.once && link.fired) continue;
        cause(s, sources_[k], link.event, depth + 1);
    }
}

void GoalPlanner::cause(Search& s, const Source& source, LinkEvent event, int depth) const {
    const Game& game = s.game;
    nav::NavMesh& mesh = s.mesh;
    const float body = mesh.settings().agent_radius;
    switch (source.kind) {
    case SourceKind::Door: {
        const Door& d = game.doors()[source.index];
        if (event != LinkEvent::OnOpen || d.opening) return; // open already: its on_open has happened
        if (door_blocks(d)) {
            action_on(s, LogicTarget::Door, source.index, kDoorOpeners, door_wait_point(s, d, s.feet), depth);
            return;
        }
        if (const auto at = mesh.nearest_point(d.frame.position, Vec3(1.0f, 1.0f, 1.0f)))
            consider(s, {BotGoalKind::OpenDoor, d.entity_id, *at}, depth);
        return;
    }
    case SourceKind::Light: {
        const Light& l = game.lights()[source.index];
        const float reach = body + 1.5f; // beside the lamp's stand, within E's reach of the lamp
        if (event != LinkEvent::OnUse || !l.floor) return;
        if (const auto at = mesh.nearest_point(l.position, Vec3(reach, 1.0f, reach)))
            consider(s, {BotGoalKind::Use, l.entity_id, *at}, depth);
        return;
    }
    case SourceKind::Panel: {
        if (event != LinkEvent::OnUse) return;
        // The mesh point nearest to the panel's foot, searched within the panel's footprint plus the body's
        // radius and a margin, at about the foot's height (tall extents would snap onto the panel's top).
        const Panel& panel = game.panels()[source.index];
        const Vec3 foot = panel.centre - Vec3(0.0f, panel.size.y * 0.5f, 0.0f);
        const float reach = 0.5f * std::hypot(panel.size.x, panel.size.z) + body + 1.0f;
        if (const auto at = mesh.nearest_point(foot, Vec3(reach, 1.0f, reach)))
            consider(s, {BotGoalKind::Use, panel.entity_id, *at}, depth);
        return;
    }
    case SourceKind::Pickup: {
        const Pickup& p = game.pickups()[source.index];
        if (event != LinkEvent::OnPickup || p.taken || !would_take(game, p)) return;
        if (const auto at = mesh.nearest_point(p.centre, Vec3(1.5f, 3.0f, 1.5f)))
            consider(s, {BotGoalKind::Pickup, p.entity_id, *at}, depth);
        return;
    }
    case SourceKind::Robot:
        if ((event == LinkEvent::OnDeath || event == LinkEvent::OnAlert) &&
            game.robots()[source.index].alive())
            hunt(s, source.index, depth);
        return;
    case SourceKind::Trigger: {
        const TriggerState& t = game.logic().triggers()[source.index];
        if (event != LinkEvent::OnEnter || t.who == TriggerWho::Robots) return;
        if (!t.enabled) {
            action_on(s, LogicTarget::Trigger, source.index, kEnablers, s.feet, depth);
            return;
        }
        if (t.occupied) return; // it noticed the bot already; its links are running or done
        const float half = 0.5f * std::min(t.size.x, t.size.z);
        if (const auto at = mesh.nearest_point(t.frame.position, Vec3(half, std::max(1.0f, t.size.y), half)))
            consider(s, {BotGoalKind::Enter, t.entity_id, *at}, depth);
        return;
    }
    case SourceKind::Objective:
        if (event == LinkEvent::OnComplete) objective(s, source.index, depth);
        return;
    case SourceKind::Level: // on_start has happened
    case SourceKind::None:
        return;
    }
}

void GoalPlanner::hunt(Search& s, std::uint32_t robot, int depth) const {
    const Robot& r = s.game.robots()[robot];
    const Vec3 at = s.mesh.nearest_point(r.feet, Vec3(2.0f, 4.0f, 2.0f)).value_or(r.feet);
    consider(s, {BotGoalKind::Hunt, r.entity_id, at}, depth);
}

void GoalPlanner::consider(Search& s, BotGoal goal, int depth) const {
    // A walk is never shorter than the straight line: a goal that far cannot win, so skip its path query
    // (with no door in the way; a blocked goal's openers are goals of their own).
    if (!s.doors_block && geometry::ground_distance(s.feet, goal.point) >= s.best_cost) return;
    if (const auto length = s.mesh.path_length(s.feet, goal.point)) {
        offer(s, goal, *length);
        return;
    }
    if (s.doors_block) {
        door_in_the_way(s, goal, depth);
        return;
    }
    offer(s, goal, kUnreachable + geometry::ground_distance(s.feet, goal.point));
}

// The goal cannot be reached with the locked doors shut: the first of them on the path with every door
// open is in the way; what opens it is the goal instead, and failing that, waiting beside it.
void GoalPlanner::door_in_the_way(Search& s, const BotGoal& goal, int depth) const {
    for (const Door& d : s.game.doors()) s.mesh.set_door_open(d.entity_id, true);
    const nav::PathStatus status = s.mesh.find_path(s.feet, goal.point, s.path);
    close_blocking_doors(s.game, s.mesh);
    const auto doors = s.game.doors();
    std::size_t blocker = doors.size();
    Vec3 before = s.feet; // the corner before the doorway: the side the bot comes from
    for (std::size_t k = 1; status == nav::PathStatus::Found && k < s.path.size() && blocker == doors.size();
         ++k) {
        float nearest = 1e30f; // of the doorways this leg passes, the first along it
        for (std::size_t i = 0; i < doors.size(); ++i) {
            const Door& d = doors[i];
            if (!door_blocks(d)) continue;
            const Vec3& centre = d.frame.position;
            const float reach = 0.5f * d.props.width + kDoorwayMargin;
            if (geometry::ground_distance_to_segment(centre, s.path[k - 1], s.path[k]) > reach) continue;
            const float along = geometry::ground_distance(centre, s.path[k - 1]);
            if (along < nearest) {
                nearest = along;
                blocker = i;
                before = s.path[k - 1];
            }
        }
    }
    if (blocker == doors.size()) {
        offer(s, goal, kUnreachable + geometry::ground_distance(s.feet, goal.point));
        return;
    }
    const Vec3 wait_at = door_wait_point(s, doors[blocker], before);
    action_on(s, LogicTarget::Door, static_cast<std::uint32_t>(blocker), kDoorOpeners, wait_at, depth + 1);
    offer(s, {BotGoalKind::Wait, -1, wait_at}, kWaitHopeless + geometry::ground_distance(s.feet, wait_at));
}

Vec3 GoalPlanner::door_wait_point(Search& s, const Door& door, const Vec3& from) const {
    const Vec3 normal = door.frame.rotation * Vec3(0.0f, 0.0f, 1.0f);
    const float side = glm::dot(from - door.frame.position, normal) >= 0.0f ? 1.0f : -1.0f;
    const Vec3 front = door.frame.position + normal * (side * kDoorWaitDistance);
    return s.mesh.nearest_point(front, Vec3(1.5f, 2.0f, 1.5f)).value_or(front);
}

void GoalPlanner::offer(Search& s, const BotGoal& goal, float cost) const {
    if (cost < s.best_cost) {
        s.best = goal;
        s.best_cost = cost;
    }
}

} // namespace ks::game
