#include "model/validation.h"

#include "brush/brush_csg.h"
#include "brush/brush_query.h"
#include "level/entity_shapes.h"
#include "level/level_io.h"
#include "level/texture_names.h"
#include "model/ambush_validation.h"
#include "model/logic_validation.h"
#include "model/model_validation.h"
#include "model/patrol_validation.h"
#include "model/reachability.h"
#include "model/sound_validation.h"
#include "model/xz_grid.h"

#include <cmath>
#include <cstdio>

namespace ks::editor {
namespace {
using level::Entity;
using level::EntityType;
using level::Level;

std::string describe(const Entity& e) {
    std::string s = std::string(level::type_name(e.type())) + " " + std::to_string(e.id);
    if (!e.name.empty()) s += " '" + e.name + "'";
    return s;
}

std::string num(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", static_cast<double>(v));
    return buf;
}

// "entities[12].size" -> the id of entity 12, else 0.
int entity_id_from_path(const Level& level, const std::string& path) {
    const std::string prefix = "entities[";
    if (path.compare(0, prefix.size(), prefix) != 0) return 0;
    size_t index = 0, i = prefix.size();
    bool digits = false;
    for (; i < path.size() && std::isdigit(static_cast<unsigned char>(path[i])); ++i, digits = true)
        index = index * 10 + static_cast<size_t>(path[i] - '0');
    if (!digits || i >= path.size() || path[i] != ']' || index >= level.entities.size()) return 0;
    return level.entities[index].id;
}

// An entity with its box, computed once per validation.
struct Placed {
    const Entity* entity;
    geometry::Obb box;
    geometry::Aabb bounds;
};

// A brush entity with its world brush, made once per validation.
struct PlacedBrush {
    const Entity* entity;
    std::shared_ptr<const brush::Brush> brush;
    geometry::Aabb bounds;
};

// The level's walls, brushes and walkable surfaces (floors, stairs, brushes) with their boxes, indexed on
// the ground plane.
struct Solids {
    std::vector<Placed> walls;
    std::vector<PlacedBrush> brushes;
    std::vector<SupportSurface> supports;
    XzGrid wall_grid, brush_grid, support_grid;
    mutable std::vector<int> near; // query results, reused

    static std::vector<Placed> collect_walls(const Level& level) {
        std::vector<Placed> out;
        for (const auto& e : level.entities) {
            if (e.type() != EntityType::Wall || !is_finite(e.position) || !is_finite(e.rotation)) continue;
            const geometry::Obb box = entity_obb(e);
            out.push_back({&e, box, box.aabb()});
        }
        return out;
    }
    static std::vector<PlacedBrush> collect_brushes(const Level& level) {
        std::vector<PlacedBrush> out;
        for (const auto& e : level.entities) {
            if (e.type() != EntityType::Brush || !is_finite(e.position) || !is_finite(e.rotation)) continue;
            auto world = level::world_brush(e);
            if (!world) continue;
            const geometry::Aabb bounds{Vec3(world->bounds_min()), Vec3(world->bounds_max())};
            out.push_back({&e, std::make_shared<const brush::Brush>(std::move(*world)), bounds});
        }
        return out;
    }
    static std::vector<SupportSurface> collect_supports(const Level& level,
                                                        const std::vector<PlacedBrush>& brushes) {
        std::vector<SupportSurface> out;
        for (const auto& e : level.entities)
            if (e.type() != EntityType::Brush)
                if (auto surface = SupportSurface::of(e)) out.push_back(std::move(*surface));
        for (const PlacedBrush& b : brushes) out.push_back(SupportSurface::of_brush(*b.entity, b.brush));
        return out;
    }
    template <class T, class BoxOf>
    static std::vector<geometry::Aabb> bounds_of(const std::vector<T>& items, BoxOf box_of) {
        std::vector<geometry::Aabb> b;
        b.reserve(items.size());
        for (const T& item : items) b.push_back(box_of(item));
        return b;
    }
    explicit Solids(const Level& level)
        : walls(collect_walls(level)), brushes(collect_brushes(level)),
          supports(collect_supports(level, brushes)),
          wall_grid(bounds_of(walls, [](const Placed& p) { return p.bounds; })),
          brush_grid(bounds_of(brushes, [](const PlacedBrush& p) { return p.bounds; })),
          support_grid(bounds_of(supports, [](const SupportSurface& s) { return s.box().aabb(); })) {}
    // Walls whose box may overlap `box`, in level order.
    const std::vector<int>& walls_near(const geometry::Aabb& box) const {
        wall_grid.query(box, near);
        return near;
    }
    // Brushes whose bounds may overlap `box`, in level order.
    const std::vector<int>& brushes_near(const geometry::Aabb& box) const {
        brush_grid.query(box, near);
        return near;
    }
};

// The box as a brush (its six face planes), to ask whether a brush shares a volume with it.
std::optional<brush::Brush> box_brush(const geometry::Obb& box) {
    std::vector<brush::Face> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            const DVec3 normal = sign * glm::normalize(DVec3(box.axes[axis]));
            faces.push_back({{normal, glm::dot(normal, DVec3(box.center)) + double(box.half[axis])}, {}});
        }
    auto b = brush::Brush::from_faces(std::move(faces));
    if (!b) return std::nullopt;
    return std::move(*b);
}

// The first brush that shares a volume with `box` (more than touching it), if any.
const PlacedBrush* brush_overlapping(const Solids& solids, const geometry::Obb& box) {
    const auto cut = box_brush(box);
    if (!cut) return nullptr;
    for (int i : solids.brushes_near(box.aabb())) {
        const PlacedBrush& b = solids.brushes[static_cast<size_t>(i)];
        if (const auto common = brush::intersect(*b.brush, *cut); common && common->volume() > 1e-6)
            return &b;
    }
    return nullptr;
}

struct Support {
    bool over_any = false;      // some floor or stair lies under or over (x, z)
    std::optional<float> below; // highest surface at or below y (within tolerance)
    std::optional<float> sunk;  // lowest surface a little above y: the entity is sunk into it
};

Support find_support(const Solids& solids, int self_id, Vec3 p, const ValidationOptions& o) {
    Support s;
    solids.support_grid.query_point(p.x, p.z, solids.near);
    for (int i : solids.near) {
        const SupportSurface& e = solids.supports[static_cast<size_t>(i)];
        if (e.entity().id == self_id) continue;
        auto h = e.height_at(p.x, p.z);
        if (!h) continue;
        s.over_any = true;
        if (*h <= p.y + o.support_tolerance) {
            if (!s.below || *h > *s.below) s.below = h;
        } else if (*h <= p.y + o.sink_limit) {
            if (!s.sunk || *h < *s.sunk) s.sunk = h;
        }
    }
    return s;
}

bool stands_on_ground(EntityType t) {
    switch (t) {
    case EntityType::Stair:
    case EntityType::Door:
    case EntityType::FloorLight:
    case EntityType::Robot:
    case EntityType::Pickup:
    case EntityType::GasCylinder:
    case EntityType::ControlPanel:
    case EntityType::Spawner: // its robots appear where it stands: on no ground, they fall or never come
        return true;
    default:
        return false; // walls (lintels float by design), floors, ceiling lights, brushes
    }
}

bool is_gameplay_body(EntityType t) {
    switch (t) {
    case EntityType::FloorLight:
    case EntityType::Robot:
    case EntityType::Pickup:
    case EntityType::GasCylinder:
    case EntityType::ControlPanel:
        return true;
    default:
        return false; // architecture meets walls on purpose; doors sit in wall gaps (own rule)
    }
}

// Checks the ground under p; returns an issue message and the fixed height when something is wrong.
struct SupportProblem {
    std::string message;
    IssueSeverity severity = IssueSeverity::Warning;
    std::optional<float> fixed_y;
};
std::optional<SupportProblem> support_problem(const Solids& solids, int self_id, Vec3 p,
                                              const ValidationOptions& o) {
    Support s = find_support(solids, self_id, p, o);
    if (s.below && p.y - *s.below <= o.support_tolerance) return std::nullopt;
    if (s.sunk)
        return SupportProblem{"is sunk " + num(*s.sunk - p.y) + " units into the floor",
                              IssueSeverity::Warning, s.sunk};
    if (s.below)
        return SupportProblem{"floats " + num(p.y - *s.below) + " units above the floor",
                              IssueSeverity::Warning, s.below};
    if (s.over_any)
        return SupportProblem{"is below every floor at its spot", IssueSeverity::Error, std::nullopt};
    return SupportProblem{"is outside every floor", IssueSeverity::Error, std::nullopt};
}

// Horizontal push that takes `box` out of a wall it overlaps by `ov` (none for vertical overlaps).
std::optional<Vec3> push_out(const geometry::Overlap& ov) {
    Vec3 horizontal(ov.axis.x, 0.0f, ov.axis.z);
    const float len = glm::length(horizontal);
    if (len < 0.3f) return std::nullopt;
    return horizontal / len * (ov.depth / len + 0.01f);
}

// The loader warns about an unknown texture (the level still loads); the editor calls it an error (saved as
// a draft: the game would show magenta) with the did-you-mean as its quick fix.
Issue texture_issue(const Level& level, const level::Diagnostic& d) {
    Issue issue;
    issue.rule = Rule::Texture;
    issue.severity = IssueSeverity::Error;
    issue.entity_id = entity_id_from_path(level, d.error.where.path);
    issue.message = d.error.str();
    const std::string& path = d.error.where.path;
    const std::string field = path.substr(path.rfind('.') + 1);
    // A brush face's material ("faces[2].material") is no field the inspector sets by name: no quick fix.
    if (!d.suggestion.empty() && level::is_texture_field(field))
        issue.fix = {"Use " + d.suggestion, fixes::SetField{field, FieldValue(d.suggestion)}};
    return issue;
}

void check_format(const Level& level, std::vector<Issue>& out) {
    const auto report = level::validate(level);
    for (const auto& d : report.diagnostics) {
        if (d.kind == level::Diagnostic::Kind::UnknownTexture) {
            out.push_back(texture_issue(level, d));
            continue;
        }
        if (d.kind != level::Diagnostic::Kind::Other) {
            out.push_back(logic_issue(level, d));
            continue;
        }
        Issue issue;
        issue.rule = Rule::Format;
        issue.severity =
            d.severity == level::Diagnostic::Severity::Error ? IssueSeverity::Error : IssueSeverity::Warning;
        issue.entity_id = entity_id_from_path(level, d.error.where.path);
        issue.message = d.error.str();
        if (const level::Entity* e = issue.entity_id ? level.find(issue.entity_id) : nullptr)
            issue.fix = model_quick_fix(*e, d);
        out.push_back(std::move(issue));
    }
}

void check_player_start(const Level& level, const Solids& solids, const ValidationOptions& o,
                        std::vector<Issue>& out) {
    const auto& start = level.player_start;
    auto add = [&](IssueSeverity sev, std::string msg, QuickFix fix = {}) {
        out.push_back({Rule::PlayerStart, sev, 0, "player start " + std::move(msg), std::move(fix)});
    };
    if (!is_finite(start.position) || !std::isfinite(start.yaw)) {
        add(IssueSeverity::Error, "has a non-finite position or yaw");
        return;
    }
    if (auto problem = support_problem(solids, 0, start.position, o)) {
        QuickFix fix;
        if (problem->fixed_y)
            fix = {"Drop to floor",
                   fixes::MovePlayerStart{{start.position.x, *problem->fixed_y, start.position.z}}};
        // Without ground under it the player falls forever: that is an error, not a nit.
        add(problem->fixed_y ? problem->severity : IssueSeverity::Error, problem->message, std::move(fix));
    }
    const geometry::Obb body = player_obb(start);
    for (int i : solids.walls_near(body.aabb())) {
        const Placed& w = solids.walls[static_cast<size_t>(i)];
        geometry::Overlap ov = geometry::obb_overlap(body, w.box);
        if (!ov.overlapping) continue;
        QuickFix fix;
        if (auto delta = push_out(ov))
            fix = {"Push out of the wall", fixes::MovePlayerStart{start.position + *delta}};
        add(IssueSeverity::Error, "is inside " + describe(*w.entity) + " (by " + num(ov.depth) + ")",
            std::move(fix));
        return;
    }
    // Against brushes, the body above a step: a start on a ramp or at a platform's edge stands partly in
    // its ground, which the support rule judges.
    geometry::Obb upper = body;
    const float lift = std::min(o.character.step_height, upper.half.y);
    upper.center.y += lift / 2;
    upper.half.y -= lift / 2;
    if (const PlacedBrush* b = brush_overlapping(solids, upper))
        add(IssueSeverity::Error, "is inside " + describe(*b->entity) + "; move it into the open", {});
}

void check_control_panels(const Level& level, std::vector<Issue>& out) {
    int count = 0;
    for (const auto& e : level.entities) {
        if (e.type() != EntityType::ControlPanel) continue;
        if (++count == 1) continue;
        QuickFix fix{"Delete", fixes::DeleteEntity{}};
        out.push_back({Rule::ControlPanel, IssueSeverity::Warning, e.id,
                       describe(e) + " is an extra control panel; the level needs exactly one", fix});
    }
    // With objectives, the level is won by completing them: the objective rule says when it cannot be.
    if (count == 0 && level.objectives.empty())
        out.push_back({Rule::ControlPanel,
                       IssueSeverity::Error,
                       0,
                       "the level has no control panel, so it cannot be won; place one",
                       {}});
}

void check_wall_overlaps(const Level& level, const Solids& solids, std::vector<Issue>& out) {
    for (const auto& e : level.entities) {
        if (!is_gameplay_body(e.type())) continue;
        const geometry::Obb box = entity_obb(e);
        const geometry::Aabb bounds = box.aabb();
        for (int i : solids.walls_near(bounds)) {
            const Placed& w = solids.walls[static_cast<size_t>(i)];
            if (!bounds.overlaps(w.bounds)) continue;
            geometry::Overlap ov = geometry::obb_overlap(box, w.box, 0.01f);
            if (!ov.overlapping) continue;
            QuickFix fix;
            if (auto delta = push_out(ov))
                fix = {"Push out of the wall", fixes::MoveEntity{e.position + *delta}};
            out.push_back({Rule::WallOverlap, IssueSeverity::Error, e.id,
                           describe(e) + " overlaps " + describe(*w.entity) + " by " + num(ov.depth),
                           std::move(fix)});
            break;
        }
    }
}

void check_support(const Level& level, const Solids& solids, const ValidationOptions& o,
                   std::vector<Issue>& out) {
    for (const auto& e : level.entities) {
        if (!stands_on_ground(e.type()) || !is_finite(e.position)) continue;
        auto problem = support_problem(solids, e.id, e.position, o);
        if (!problem) continue;
        QuickFix fix{"Delete", fixes::DeleteEntity{}};
        if (problem->fixed_y)
            fix = {"Drop to floor", fixes::MoveEntity{{e.position.x, *problem->fixed_y, e.position.z}}};
        out.push_back(
            {Rule::Support, problem->severity, e.id, describe(e) + " " + problem->message, std::move(fix)});
    }
}

void check_stairs(const Level& level, const ValidationOptions& o, std::vector<Issue>& out) {
    const float limit = o.character.max_slope_degrees;
    for (const auto& e : level.entities) {
        const auto* s = e.try_as<level::StairProps>();
        if (!s) continue;
        const float slope = degrees(std::atan2(s->size.y, s->size.z));
        if (!(slope > limit + 1e-3f)) continue;
        // The shortest run the character can still climb, rounded up to a hundredth.
        const float run = std::ceil(s->size.y / std::tan(radians(limit)) * 100.0f) / 100.0f;
        QuickFix fix{"Lengthen the run to " + num(run),
                     fixes::SetField{"size", FieldValue(Vec3(s->size.x, s->size.y, run))}};
        out.push_back(
            {Rule::StairSlope, IssueSeverity::Error, e.id,
             describe(e) + " rises at " + num(slope) + " degrees; the character climbs at most " + num(limit),
             std::move(fix)});
    }
}

void check_doors(const Level& level, const Solids& solids, std::vector<Issue>& out) {
    for (const auto& e : level.entities) {
        const auto* d = e.try_as<level::DoorProps>();
        if (!d) continue;
        const geometry::Obb door = entity_obb(e);
        // Probes just beyond each jamb, at mid height, must be inside a wall; the doorway must be free.
        auto wall_at = [&](float side) {
            const Vec3 probe = door.center + door.axes[0] * (side * (d->width / 2 + 0.25f));
            for (int i : solids.walls_near(geometry::Aabb{probe, probe}))
                if (solids.walls[static_cast<size_t>(i)].box.contains(probe, 0.05f)) return true;
            for (int i : solids.brushes_near(geometry::Aabb{probe, probe}))
                if (brush::contains(*solids.brushes[static_cast<size_t>(i)].brush, DVec3(probe), 0.05))
                    return true;
            return false;
        };
        const bool left = wall_at(-1.0f), right = wall_at(1.0f);
        std::string problem;
        if (!left && !right)
            problem = "stands in the open: no wall on either side";
        else if (!left)
            problem = "has no wall beside its -x jamb";
        else if (!right)
            problem = "has no wall beside its +x jamb";
        geometry::Obb doorway = door;
        doorway.half = {std::max(d->width / 2 - 0.1f, 0.01f), std::max(d->height / 2 - 0.1f, 0.01f), 0.05f};
        if (problem.empty())
            for (int i : solids.walls_near(doorway.aabb())) {
                const Placed& w = solids.walls[static_cast<size_t>(i)];
                if (geometry::obb_overlap(doorway, w.box).overlapping) {
                    problem = "is blocked by " + describe(*w.entity);
                    break;
                }
            }
        if (problem.empty())
            if (const PlacedBrush* b = brush_overlapping(solids, doorway))
                problem = "is blocked by " + describe(*b->entity);
        if (!problem.empty())
            out.push_back({Rule::DoorGap,
                           IssueSeverity::Error,
                           e.id,
                           describe(e) + " is not in a wall gap: it " + problem,
                           {}});
    }
}
} // namespace

const char* rule_name(Rule rule) {
    switch (rule) {
    case Rule::Format:
        return "format";
    case Rule::PlayerStart:
        return "player_start";
    case Rule::ControlPanel:
        return "control_panel";
    case Rule::WallOverlap:
        return "wall_overlap";
    case Rule::Support:
        return "support";
    case Rule::StairSlope:
        return "stair_slope";
    case Rule::DoorGap:
        return "door_gap";
    case Rule::Reachability:
        return "reachability";
    case Rule::Patrol:
        return "patrol";
    case Rule::RobotReach:
        return "robot_reach";
    case Rule::Sound:
        return "sound";
    case Rule::LinkTarget:
        return "link_target";
    case Rule::LogicLoop:
        return "logic_loop";
    case Rule::TriggerReach:
        return "trigger_reach";
    case Rule::Objective:
        return "objective";
    case Rule::LockedDoor:
        return "locked_door";
    case Rule::Texture:
        return "texture";
    case Rule::Prefab:
        return "prefab";
    case Rule::StartAmbush:
        return "start_ambush";
    }
    return "?";
}

int count_errors(const std::vector<Issue>& issues) {
    int n = 0;
    for (const auto& i : issues) n += i.severity == IssueSeverity::Error;
    return n;
}

std::vector<Issue> validate_design(const Level& level, const ValidationOptions& options) {
    std::vector<Issue> out;
    check_format(level, out);
    const Solids solids(level);
    check_player_start(level, solids, options, out);
    check_control_panels(level, out);
    check_level_can_be_won(level, out);
    check_wall_overlaps(level, solids, out);
    check_support(level, solids, options, out);
    check_stairs(level, options, out);
    check_doors(level, solids, out);
    check_patrol_support(level, options, out);
    check_sound_names(level, options, out);
    check_start_ambush(level, out);
    if (options.check_reachability) check_reachability(level, options, out);
    return out;
}

} // namespace ks::editor
