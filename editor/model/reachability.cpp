#include "model/reachability.h"

#include "level/diagnostics.h"
#include "model/patrol_validation.h"

#include "nav/nav_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ks::editor {
namespace {
using level::Entity;
using level::EntityType;

// What the navigation mesh is built from (level::static_solid_shape, brushes and the doorways): the entities
// whose edits can change the answer.
bool shapes_the_mesh(EntityType t) {
    switch (t) {
    case EntityType::Wall:
    case EntityType::Floor:
    case EntityType::Stair:
    case EntityType::FloorLight:
    case EntityType::GasCylinder:
    case EntityType::ControlPanel:
    case EntityType::Door:
    case EntityType::Brush:
    case EntityType::Model: // its collision (none: no solid in the mesh)
        return true;
    default:
        return false; // robots and pickups move or vanish, lights hang out of the way
    }
}

// The mesh the bot plans on (nav::player_nav_settings), for the options' body and character limits, at
// the options' cell size, with every door open.
nav::NavSettings walk_settings(const ValidationOptions& o) {
    const CharacterLimits& ch = o.character;
    nav::NavSettings s = nav::player_nav_settings(ch.step_height, ch.max_slope_degrees);
    s.agent_radius = ch.radius;
    s.agent_height = ch.height;
    s.cell_size = o.walk_cell;
    return s;
}

// Where the body stands beside the panel: three points along each side, a little farther out than the
// body's radius, snapped to the mesh at the panel's foot. The panel is a solid: the mesh keeps the body's
// radius away from it, so its own centre is never on the mesh.
std::vector<Vec3> panel_approaches(nav::NavMesh& mesh, const Entity& panel, const ValidationOptions& o) {
    constexpr float kGap = 0.25f; // beyond the radius, as a player stands to press E
    const geometry::Obb box = entity_obb(panel);
    const Vec3 foot = box.center - box.axes[1] * box.half.y;
    const float radius = o.character.radius, snap = kGap + o.walk_cell;
    const Vec3 extents(snap, o.character.step_height + o.support_tolerance, snap);
    std::vector<Vec3> out;
    for (int axis : {0, 2}) {
        const int along = 2 - axis;
        const float slide = std::max(0.0f, box.half[along] - radius);
        for (float side : {-1.0f, 1.0f})
            for (float t : {-1.0f, 0.0f, 1.0f}) {
                Vec3 p = foot + box.axes[axis] * (side * (box.half[axis] + radius + kGap)) +
                         box.axes[along] * (t * slide);
                p.y = foot.y;
                if (auto on_mesh = mesh.nearest_point(p, extents)) out.push_back(*on_mesh);
            }
    }
    return out;
}

bool has_trigger(const level::Level& level) {
    return std::any_of(level.entities.begin(), level.entities.end(),
                       [](const Entity& e) { return e.type() == EntityType::Trigger; });
}

// How far from a body's feet the mesh may lie and still be under them.
Vec3 feet_extents(const ValidationOptions& o) {
    const float reach = o.character.radius + o.walk_cell;
    return {reach, o.character.step_height + o.support_tolerance, reach};
}

// Whether the mesh, at a point whose island `accept` takes, lies inside the trigger's box the way the game
// tests a body (game/logic_step.cpp, trigger_holds): the feet within the footprint (grown by `grow` on each
// side), the body's upright extent [feet, feet + height] meeting the box's. The footprint is sampled in cells
// of about a unit, at most 8 x 8, each asked for its nearest mesh point.
template <class Accept>
bool box_meets_mesh(nav::NavMesh& mesh, const Entity& e, const level::TriggerProps& t, float height,
                    float grow, const ValidationOptions& o, Accept accept) {
    const Quat yaw = quat_from_ypr(radians(e.rotation.x), 0.0f, 0.0f); // the game turns triggers by yaw only
    const Vec3 ax = yaw * Vec3(1, 0, 0), az = yaw * Vec3(0, 0, 1);
    const float hx = t.size.x * 0.5f + grow, hz = t.size.z * 0.5f + grow;
    const int nx = std::clamp(static_cast<int>(std::ceil(2.0f * hx)), 1, 8);
    const int nz = std::clamp(static_cast<int>(std::ceil(2.0f * hz)), 1, 8);
    const float cx = hx / static_cast<float>(nx), cz = hz / static_cast<float>(nz); // half a cell
    const float c = std::abs(ax.x), s = std::abs(ax.z);
    const Vec3 extents(cx * c + cz * s, (t.size.y + height) * 0.5f, cx * s + cz * c);
    const float mid_y = e.position.y + (t.size.y - height) * 0.5f;
    const Vec3 snap(o.walk_cell, o.character.step_height, o.walk_cell);
    for (int i = 0; i < nx; ++i)
        for (int k = 0; k < nz; ++k) {
            Vec3 p = e.position + ax * (-hx + cx * static_cast<float>(2 * i + 1)) +
                     az * (-hz + cz * static_cast<float>(2 * k + 1));
            p.y = mid_y;
            const auto on_mesh = mesh.nearest_point(p, extents);
            if (!on_mesh) continue;
            const Vec3 local = *on_mesh - e.position;
            if (std::abs(glm::dot(local, ax)) > hx || std::abs(glm::dot(local, az)) > hz ||
                local.y > t.size.y || local.y + height < 0.0f)
                continue;
            if (accept(mesh.island(*on_mesh, snap))) return true;
        }
    return false;
}

const Entity* find_panel(const level::Level& level) {
    for (const auto& e : level.entities)
        if (e.type() == EntityType::ControlPanel) return &e;
    return nullptr;
}

} // namespace

WalkCheck walk_to_control_panel(const level::Level& level, const ValidationOptions& o) {
    WalkCheck check;
    const Entity* panel = find_panel(level);
    const Vec3 start = level.player_start.position;
    if ((!panel && !has_trigger(level)) || !is_finite(start)) return check;
    auto built = nav::NavMesh::build(level, walk_settings(o));
    if (!built) {
        check.build_problem = built.error().str();
        return check;
    }
    check.mesh = std::move(*built);
    nav::NavMesh& mesh = *check.mesh;
    check.polygons = mesh.stats().polygons;
    for (const auto& e : level.entities)
        if (e.type() == EntityType::Door) mesh.set_door_open(e.id, true);
    if (!panel) return check; // built for the triggers alone
    // The start must be on the mesh: the player stands there (the player_start rule reports it otherwise).
    const float reach = o.character.radius + o.walk_cell;
    if (!mesh.nearest_point(start, Vec3(reach, o.character.step_height + o.support_tolerance, reach)))
        return check;
    check.decided = true;
    const std::vector<Vec3> approaches = panel_approaches(mesh, *panel, o);
    check.panel_approaches = static_cast<int>(approaches.size());
    check.reachable = std::any_of(approaches.begin(), approaches.end(),
                                  [&](const Vec3& p) { return mesh.reachable(start, p); });
    return check;
}

std::uint64_t walk_fingerprint(const level::Level& level, const ValidationOptions& o) {
    // FNV-1a over the bytes of the values the check reads.
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    };
    auto mix_value = [&mix](const auto& v) { mix(&v, sizeof v); };
    mix_value(o.walk_cell), mix_value(o.support_tolerance);
    mix_value(o.character.radius), mix_value(o.character.height), mix_value(o.character.step_height);
    mix_value(o.character.max_slope_degrees);
    mix_value(level.player_start.position);
    const bool triggers = has_trigger(level); // without a panel, the mesh is built only for triggers
    mix_value(triggers);
    for (const auto& e : level.entities) {
        const EntityType t = e.type();
        if (!shapes_the_mesh(t)) continue;
        const auto* floor = e.try_as<level::FloorProps>();
        const geometry::Obb box = entity_obb(e);
        const int type = static_cast<int>(t), ceiling = floor && floor->ceiling ? 1 : 0;
        mix_value(e.id), mix_value(type), mix_value(ceiling), mix_value(e.position), mix_value(e.rotation);
        mix_value(box.center), mix_value(box.axes), mix_value(box.half);
    }
    return h;
}

PanelReachability check_panel_reachability(const level::Level& level, const ValidationOptions& options) {
    WalkCheck check = walk_to_control_panel(level, options);
    PanelReachability result;
    result.mesh = std::move(check.mesh);
    // Numbering the islands floods every polygon: done here, in the background job, so that the trigger
    // rule's questions on the UI thread are polygon lookups.
    if (result.mesh) (void)result.mesh->island(level.player_start.position, feet_extents(options));
    if (!check.decided || check.reachable) return result;
    const int panel_id = find_panel(level)->id;
    result.issues.push_back(
        {Rule::Reachability,
         IssueSeverity::Warning,
         panel_id,
         "control panel " + std::to_string(panel_id) +
             " cannot be reached on foot from the player start (doors count as open, jumps are not counted)",
         {}});
    return result;
}

void check_robot_reach(const level::Level& level, nav::NavMesh& mesh, const ValidationOptions& o,
                       std::vector<Issue>& out) {
    const float reach = o.character.radius + o.walk_cell;
    const Vec3 extents(reach, o.character.step_height + o.support_tolerance, reach);
    const auto start = mesh.nearest_point(level.player_start.position, extents);
    if (!start) return; // the player start rule reports a start off the floor
    for (const Entity& e : level.entities) {
        const auto* robot = e.try_as<level::RobotProps>();
        if (!robot || robot->dummy || !is_finite(e.position)) continue;
        const auto feet = mesh.nearest_point(e.position, extents);
        if (!feet || mesh.reachable(*feet, *start)) continue;
        out.push_back({Rule::RobotReach,
                       IssueSeverity::Warning,
                       e.id,
                       "robot " + std::to_string(e.id) + (e.name.empty() ? "" : " (\"" + e.name + "\")") +
                           " can never walk to the player's area (doors count as open): it will only shoot "
                           "from where it stands",
                       {}});
    }
}

void check_trigger_reach(const level::Level& level, nav::NavMesh& mesh, const ValidationOptions& o,
                         std::vector<Issue>& out) {
    const Vec3 extents = feet_extents(o);
    // Robots are narrower than the player: their mesh reaches this much closer to walls than the player's.
    const float robot_grow = std::max(0.0f, o.character.radius - level::kRobotRadius);
    const int player_island =
        is_finite(level.player_start.position) ? mesh.island(level.player_start.position, extents) : 0;
    std::vector<int> robot_islands;
    for (const Entity& e : level.entities) {
        const auto* robot = e.try_as<level::RobotProps>();
        if (!((robot && !robot->dummy) || e.type() == EntityType::Spawner) || !is_finite(e.position))
            continue;
        if (const int island = mesh.island(e.position, extents + Vec3(robot_grow, 0, robot_grow)))
            robot_islands.push_back(island);
    }
    std::sort(robot_islands.begin(), robot_islands.end());
    robot_islands.erase(std::unique(robot_islands.begin(), robot_islands.end()), robot_islands.end());
    for (const Entity& e : level.entities) {
        const auto* t = e.try_as<level::TriggerProps>();
        if (!t || !is_finite(e.position) || !is_finite(e.rotation)) continue;
        const bool for_player = t->who.value != "robots", for_robots = t->who.value != "player";
        if (for_player && player_island == 0 && !for_robots) continue; // the player start rule reports it
        if (for_player && player_island != 0 &&
            box_meets_mesh(mesh, e, *t, o.character.height, 0.0f, o,
                           [&](int island) { return island == player_island; }))
            continue;
        if (for_robots && box_meets_mesh(mesh, e, *t, level::kRobotHeight, robot_grow, o, [&](int island) {
                return std::binary_search(robot_islands.begin(), robot_islands.end(), island);
            }))
            continue;
        const std::string who = for_player && for_robots ? "neither the player nor any robot"
                                : for_player             ? "the player"
                                                         : "no robot";
        const std::string how = for_robots && robot_islands.empty() && !for_player
                                    ? "the level has no robot or spawner: place one, or set who to player"
                                    : "move or grow the box so that it meets the floor where they walk "
                                      "(doors count as open, jumps "
                                      "are not counted)";
        out.push_back({Rule::TriggerReach,
                       IssueSeverity::Warning,
                       e.id,
                       level::entity_subject(e) + " can never be set off: " + who +
                           (for_player && !for_robots ? " cannot" : " can") + " walk into its box; " + how,
                       {}});
    }
}

void check_reachability(const level::Level& level, const ValidationOptions& options,
                        std::vector<Issue>& out) {
    PanelReachability panel = check_panel_reachability(level, options);
    out.insert(out.end(), panel.issues.begin(), panel.issues.end());
    if (!panel.mesh) return;
    check_robot_reach(level, *panel.mesh, options, out);
    check_patrol_on_mesh(level, *panel.mesh, options, out);
    check_trigger_reach(level, *panel.mesh, options, out);
}

} // namespace ks::editor
