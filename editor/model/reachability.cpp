#include "model/reachability.h"

#include "model/patrol_validation.h"

#include "nav/nav_mesh.h"

#include <algorithm>
#include <array>

namespace ks::editor {
namespace {
using level::Entity;
using level::EntityType;

// What the navigation mesh is built from (level::static_solid_shape and the doorways): the entities whose
// edits can change the answer.
bool shapes_the_mesh(EntityType t) {
    switch (t) {
    case EntityType::Wall:
    case EntityType::Floor:
    case EntityType::Stair:
    case EntityType::FloorLight:
    case EntityType::GasCylinder:
    case EntityType::ControlPanel:
    case EntityType::Door:
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
    if (!panel || !is_finite(start)) return check;
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

void check_reachability(const level::Level& level, const ValidationOptions& options,
                        std::vector<Issue>& out) {
    PanelReachability panel = check_panel_reachability(level, options);
    out.insert(out.end(), panel.issues.begin(), panel.issues.end());
    if (!panel.mesh) return;
    check_robot_reach(level, *panel.mesh, options, out);
    check_patrol_on_mesh(level, *panel.mesh, options, out);
}

} // namespace ks::editor
