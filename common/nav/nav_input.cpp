#include "nav/nav_input.h"

#include "level/entity_shapes.h"
#include "level/model_entity.h"

#include <Recast.h>

#include <algorithm>
#include <cmath>

namespace ks::nav {
namespace {

constexpr int kCylinderSides = 16;
constexpr float kAbsurdCoordinate = 1e5f; // beyond this a level is a typo, not a place
constexpr float kThinnestHalf = 0.01f;    // drawing in never makes a solid thinner than 0.02

// Recast marks a cell solid when a triangle touches any part of it, so every solid grows by up to a cell
// (half on average) and a doorway shrinks by up to two. Drawing each solid in by half a cell horizontally
// makes a cell solid about when its centre is inside the shape: no bias, half a cell either way. Thin
// walls keep a sliver, and a sliver still fills the cells it passes through, so they still block.
// Floors and stairs are surfaces, not obstacles: drawing them in would open seams where they meet.
bool is_obstacle(level::EntityType type) {
    return type != level::EntityType::Floor && type != level::EntityType::Stair;
}

level::PlacedShape drawn_in(level::PlacedShape shape, float cell_size) {
    const auto inset = [&](float half) {
        return std::max(std::min(half, kThinnestHalf), half - cell_size * 0.5f);
    };
    shape.half.x = inset(shape.half.x);
    shape.half.z = shape.kind == level::ShapeKind::Cylinder ? shape.half.x : inset(shape.half.z);
    return shape;
}

// A convex solid as corner points and faces (each a loop of corner indices, any winding). `surface`: the
// faces are a model's triangles ("mesh" collision), with no inside: each is wound to face up, as the
// two-sided physics triangles are stood on from either side.
struct ConvexSolid {
    std::vector<Vec3> corners;
    std::vector<std::vector<int>> faces;
    bool surface = false;
};

ConvexSolid box_solid(const level::PlacedShape& s) {
    ConvexSolid out;
    const Vec3 h = s.half;
    for (int i = 0; i < 8; ++i) {
        const float sx = (i & 1) ? 1.0f : -1.0f, sy = (i & 2) ? 1.0f : -1.0f, sz = (i & 4) ? 1.0f : -1.0f;
        out.corners.push_back(s.frame.to_world(s.local_centre + Vec3(sx * h.x, sy * h.y, sz * h.z)));
    }
    out.faces = {{0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    return out;
}

// The stair: full height at local -z, zero at +z (physics' make_wedge_polyhedron).
ConvexSolid wedge_solid(const level::PlacedShape& s) {
    const Vec3 h = s.half;
    const Vec3 local[6] = {{-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z},
                           {-h.x, -h.y, h.z},  {-h.x, h.y, -h.z}, {h.x, h.y, -h.z}};
    ConvexSolid out;
    for (const Vec3& p : local) out.corners.push_back(s.frame.to_world(s.local_centre + p));
    out.faces = {{0, 1, 2, 3}, {0, 4, 5, 1}, {3, 2, 5, 4}, {1, 5, 2}, {0, 3, 4}};
    return out;
}

ConvexSolid cylinder_solid(const level::PlacedShape& s) {
    ConvexSolid out;
    const Vec3 centre = s.centre();
    std::vector<int> bottom, top;
    for (int i = 0; i < kCylinderSides; ++i) {
        const float a = 2.0f * kPi * static_cast<float>(i) / kCylinderSides;
        // Corners on a circle a little larger than the radius, so the prism contains the round body.
        const float r = s.half.x / std::cos(kPi / kCylinderSides);
        const Vec3 rim(centre.x + r * std::cos(a), 0.0f, centre.z + r * std::sin(a));
        bottom.push_back(static_cast<int>(out.corners.size()));
        out.corners.push_back(rim + Vec3(0, centre.y - s.half.y, 0));
        top.push_back(static_cast<int>(out.corners.size()));
        out.corners.push_back(rim + Vec3(0, centre.y + s.half.y, 0));
    }
    out.faces = {bottom, top};
    for (int i = 0; i < kCylinderSides; ++i) {
        const int j = (i + 1) % kCylinderSides;
        out.faces.push_back({bottom[i], bottom[j], top[j], top[i]});
    }
    return out;
}

ConvexSolid solid_of(const level::PlacedShape& s) {
    switch (s.kind) {
    case level::ShapeKind::Wedge:
        return wedge_solid(s);
    case level::ShapeKind::Cylinder:
        return cylinder_solid(s);
    case level::ShapeKind::Box:
        break;
    }
    return box_solid(s);
}

// A brush's derived vertices and face polygons, rounded to float once.
ConvexSolid brush_solid(const brush::Brush& b) {
    ConvexSolid out;
    for (const DVec3& v : b.vertices()) out.corners.push_back(Vec3(v));
    out.faces = b.polygons();
    return out;
}

// A model's "mesh" collision: its triangles, rounded to float once.
ConvexSolid mesh_surface(const level::CollisionMesh& mesh) {
    ConvexSolid out;
    out.surface = true;
    out.corners.reserve(mesh.vertices.size());
    for (const DVec3& v : mesh.vertices) out.corners.push_back(Vec3(v));
    out.faces.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        out.faces.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
    return out;
}

// Appends the solid's faces as triangles wound so that Recast's normal (cross(b - a, c - a)) points out of
// the solid: its walkable test reads the normal's y.
void append_solid(const ConvexSolid& solid, InputGeometry& in) {
    Vec3 centre(0.0f);
    for (const Vec3& c : solid.corners) centre += c;
    centre /= static_cast<float>(solid.corners.size());
    const int base = static_cast<int>(in.vertices.size() / 3);
    for (const Vec3& c : solid.corners) {
        in.vertices.insert(in.vertices.end(), {c.x, c.y, c.z});
        in.bounds.grow(c);
    }
    for (const auto& face : solid.faces)
        for (size_t k = 1; k + 1 < face.size(); ++k) {
            int a = face[0], b = face[k], c = face[k + 1];
            const Vec3 pa = solid.corners[a], pb = solid.corners[b], pc = solid.corners[c];
            const Vec3 normal = glm::cross(pb - pa, pc - pa);
            if (solid.surface ? normal.y < 0.0f : glm::dot(normal, (pa + pb + pc) / 3.0f - centre) < 0.0f)
                std::swap(b, c);
            in.triangles.insert(in.triangles.end(), {base + a, base + b, base + c});
        }
}

bool sane(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) &&
           std::abs(v.x) < kAbsurdCoordinate && std::abs(v.y) < kAbsurdCoordinate &&
           std::abs(v.z) < kAbsurdCoordinate;
}

bool sane_shape(const level::PlacedShape& s) {
    const Quat& q = s.frame.rotation;
    return sane(s.frame.position) && sane(s.local_centre) && sane(s.half) && std::isfinite(q.w) &&
           std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

std::string entity_label(const level::Level& level, const level::Entity& e) {
    return "level '" + level.name + "': entity " + std::to_string(e.id) + " ('" + e.name + "', " +
           std::string(level::type_name(e.type())) + ")";
}

DoorFootprint door_footprint(const level::Entity& door, const NavSettings& settings) {
    const auto& d = door.as<level::DoorProps>();
    const geometry::Transform frame = level::upright_frame(door);
    // Across the opening, a cell past each jamb so no sliver of the doorway stays a plain polygon; along the
    // walking direction, the leaves' thickness plus the agent radius each side, so the door's polygons are
    // a band the agent's centre cannot step over.
    const float half_x = d.width * 0.5f + settings.cell_size;
    const float half_z = level::kDoorLeafHalfThickness + settings.agent_radius;
    DoorFootprint f;
    f.entity_id = door.id;
    f.open = d.open;
    const Vec3 local[4] = {
        {-half_x, 0, -half_z}, {half_x, 0, -half_z}, {half_x, 0, half_z}, {-half_x, 0, half_z}};
    for (int i = 0; i < 4; ++i) f.corners[i] = frame.to_world(local[i]);
    f.y_min = door.position.y - std::max(settings.agent_climb, settings.cell_height);
    f.y_max = door.position.y + d.height;
    return f;
}

void bin_triangles(InputGeometry& in, const NavSettings& settings) {
    const float border = static_cast<float>(tile_border_cells(settings)) * settings.cell_size;
    TileGrid& g = in.grid;
    g.origin = in.bounds.min;
    g.tile_world = static_cast<float>(settings.tile_size_cells) * settings.cell_size;
    g.columns = std::max(1, static_cast<int>(std::ceil((in.bounds.max.x - in.bounds.min.x) / g.tile_world)));
    g.rows = std::max(1, static_cast<int>(std::ceil((in.bounds.max.z - in.bounds.min.z) / g.tile_world)));
    in.tile_triangles.assign(static_cast<size_t>(g.columns) * static_cast<size_t>(g.rows), {});
    const auto tile_range = [&](float lo, float hi, float origin, int count, int& first, int& last) {
        first = std::clamp(static_cast<int>(std::floor((lo - border - origin) / g.tile_world)), 0, count - 1);
        last = std::clamp(static_cast<int>(std::floor((hi + border - origin) / g.tile_world)), 0, count - 1);
    };
    const int triangle_count = static_cast<int>(in.triangles.size() / 3);
    for (int t = 0; t < triangle_count; ++t) {
        float min_x = 3e38f, max_x = -3e38f, min_z = 3e38f, max_z = -3e38f;
        for (int k = 0; k < 3; ++k) {
            const float* v = &in.vertices[static_cast<size_t>(in.triangles[t * 3 + k]) * 3];
            min_x = std::min(min_x, v[0]), max_x = std::max(max_x, v[0]);
            min_z = std::min(min_z, v[2]), max_z = std::max(max_z, v[2]);
        }
        int x0, x1, z0, z1;
        tile_range(min_x, max_x, g.origin.x, g.columns, x0, x1);
        tile_range(min_z, max_z, g.origin.z, g.rows, z0, z1);
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x)
                in.tile_triangles[static_cast<size_t>(z * g.columns + x)].push_back(t);
    }
}

} // namespace

namespace {

bool same_grid(const TileGrid& a, const TileGrid& b) {
    return a.origin == b.origin && a.tile_world == b.tile_world && a.columns == b.columns && a.rows == b.rows;
}

bool same_triangle(const InputGeometry& a, int s, const InputGeometry& b, int t) {
    if (a.areas[static_cast<size_t>(s)] != b.areas[static_cast<size_t>(t)]) return false;
    for (int k = 0; k < 3; ++k) {
        const float* u = &a.vertices[static_cast<size_t>(a.triangles[static_cast<size_t>(s) * 3 + k]) * 3];
        const float* v = &b.vertices[static_cast<size_t>(b.triangles[static_cast<size_t>(t) * 3 + k]) * 3];
        if (u[0] != v[0] || u[1] != v[1] || u[2] != v[2]) return false;
    }
    return true;
}

// The doorways whose footprint reaches into the tile's area with its border (the ones its build marks).
std::vector<const DoorFootprint*> doors_over(const InputGeometry& in, int column, int row, float border) {
    const TileGrid& g = in.grid;
    const float x0 = g.origin.x + static_cast<float>(column) * g.tile_world - border;
    const float x1 = g.origin.x + static_cast<float>(column + 1) * g.tile_world + border;
    const float z0 = g.origin.z + static_cast<float>(row) * g.tile_world - border;
    const float z1 = g.origin.z + static_cast<float>(row + 1) * g.tile_world + border;
    std::vector<const DoorFootprint*> out;
    for (const DoorFootprint& d : in.doors) {
        float min_x = 3e38f, max_x = -3e38f, min_z = 3e38f, max_z = -3e38f;
        for (const Vec3& c : d.corners) {
            min_x = std::min(min_x, c.x), max_x = std::max(max_x, c.x);
            min_z = std::min(min_z, c.z), max_z = std::max(max_z, c.z);
        }
        if (max_x >= x0 && min_x <= x1 && max_z >= z0 && min_z <= z1) out.push_back(&d);
    }
    return out;
}

} // namespace

bool same_tile_input(const InputGeometry& a, const InputGeometry& b, int column, int row,
                     const NavSettings& settings) {
    if (!same_grid(a.grid, b.grid) || a.bounds.min.y != b.bounds.min.y || a.bounds.max.y != b.bounds.max.y)
        return false;
    if (column < 0 || row < 0 || column >= a.grid.columns || row >= a.grid.rows) return false;
    const size_t tile = static_cast<size_t>(row * a.grid.columns + column);
    const std::vector<int>& ta = a.tile_triangles[tile];
    const std::vector<int>& tb = b.tile_triangles[tile];
    if (ta.size() != tb.size()) return false;
    for (size_t i = 0; i < ta.size(); ++i)
        if (!same_triangle(a, ta[i], b, tb[i])) return false;
    const float border = static_cast<float>(tile_border_cells(settings)) * settings.cell_size;
    const auto da = doors_over(a, column, row, border), db = doors_over(b, column, row, border);
    if (da.size() != db.size()) return false;
    for (size_t i = 0; i < da.size(); ++i)
        if (da[i]->corners != db[i]->corners || da[i]->y_min != db[i]->y_min || da[i]->y_max != db[i]->y_max)
            return false;
    return true;
}

bool DoorFootprint::contains(const Vec3& p, float margin) const {
    if (p.y < y_min - margin || p.y > y_max + margin) return false;
    for (int i = 0; i < 4; ++i) { // inside every edge of the convex quad (either winding), within margin
        const Vec3 a = corners[i], b = corners[(i + 1) % 4], inner = corners[(i + 2) % 4];
        const Vec2 edge(b.x - a.x, b.z - a.z), normal = glm::normalize(Vec2(-edge.y, edge.x));
        const float side = glm::dot(normal, Vec2(inner.x - a.x, inner.z - a.z)) > 0.0f ? 1.0f : -1.0f;
        if (side * glm::dot(normal, Vec2(p.x - a.x, p.z - a.z)) < -margin) return false;
    }
    return true;
}

int tile_border_cells(const NavSettings& settings) {
    return agent_cells(settings).radius + 3;
}

// Only floors (not ceilings) and stairs are walked on: the tops of walls, ceilings, the panel and props are
// solid but never part of the mesh (robots cannot get up there, and a ceiling's roof would otherwise be a
// large unreachable island that nearest-point queries snap onto).
// Brushes are walked on where their slope allows (a ramp, a platform's top); their faces turned down are
// never walkable by slope, so they need no ceiling flag.
namespace {
bool walked_on(const level::Entity& e) {
    if (const auto* floor = e.try_as<level::FloorProps>()) return !floor->ceiling;
    return e.type() == level::EntityType::Stair || e.type() == level::EntityType::Brush ||
           e.type() == level::EntityType::Model;
}

Error absurd(const level::Level& level, const level::Entity& e) {
    return Error(entity_label(level, e) + " has a non-finite or absurd position, rotation or size",
                 Location{}, "fix its numbers in the editor");
}

// Every solid the mesh is built from, through this one function: the level's boxes, wedges and cylinders
// (static_solid_shape; obstacles drawn in by half a cell), a brush as its world brush, a model as its
// collision brushes (level::model_collision: one, or several for "hulls") or its triangles
// (level::model_mesh_collision). Brushes are not drawn in: like floors and stairs they are walked on, and
// drawing in would open seams where they meet; a brush wall grows by up to a cell instead, erring on the side
// of blocking. Empty: no solid.
Result<std::vector<ConvexSolid>> entity_solids(const level::Level& level, const level::Entity& e,
                                               const NavSettings& settings) {
    using Solids = std::vector<ConvexSolid>;
    if (e.type() == level::EntityType::Model) { // its collision, walked on like a brush; none if unread
        if (!sane(e.position) || !sane(e.rotation)) return absurd(level, e);
        Result<std::optional<level::CollisionMesh>> mesh = level::model_mesh_collision(e);
        if (mesh && mesh->has_value()) return Solids{mesh_surface(**mesh)};
        Result<std::vector<brush::Brush>> collision = level::model_collision(e);
        Solids solids;
        if (collision)
            for (const brush::Brush& hull : *collision) solids.push_back(brush_solid(hull));
        return solids;
    }
    if (e.type() == level::EntityType::Brush) {
        if (!sane(e.position) || !sane(e.rotation)) return absurd(level, e);
        Result<brush::Brush> world = level::world_brush(e);
        if (!world)
            return Error(entity_label(level, e) + ": " + world.error().message, Location{},
                         world.error().hint);
        return Solids{brush_solid(*world)};
    }
    const auto shape = level::static_solid_shape(e);
    if (!shape) return Solids();
    if (!sane(e.rotation) || !sane_shape(*shape)) return absurd(level, e);
    return Solids{solid_of(is_obstacle(e.type()) ? drawn_in(*shape, settings.cell_size) : *shape)};
}
} // namespace

Result<InputGeometry> collect_input(const level::Level& level, const NavSettings& settings) {
    InputGeometry in;
    std::vector<std::pair<int, int>> never_walked; // triangle ranges [first, last) of solids not walked on
    for (const level::Entity& e : level.entities) {
        if (e.type() == level::EntityType::Door) {
            const auto& d = e.as<level::DoorProps>();
            if (!sane(e.position) || !sane(e.rotation) || !std::isfinite(d.width) || !std::isfinite(d.height))
                return Error(entity_label(level, e) +
                                 " has a non-finite or absurd position, rotation or size",
                             Location{}, "fix its numbers in the editor");
            in.doors.push_back(door_footprint(e, settings));
            continue;
        }
        Result<std::vector<ConvexSolid>> solids = entity_solids(level, e, settings);
        if (!solids) return solids.error();
        if (solids->empty()) continue;
        const int first = static_cast<int>(in.triangles.size() / 3);
        for (const ConvexSolid& solid : *solids) append_solid(solid, in);
        if (!walked_on(e)) never_walked.emplace_back(first, static_cast<int>(in.triangles.size() / 3));
    }
    if (in.triangles.empty())
        return Error("level '" + level.name + "' has no solid shapes, so nothing to walk on", Location{},
                     "add a floor entity under the player start");
    const int triangle_count = static_cast<int>(in.triangles.size() / 3);
    in.areas.assign(static_cast<size_t>(triangle_count), RC_NULL_AREA);
    rcContext quiet(false);
    rcMarkWalkableTriangles(&quiet, settings.agent_max_slope_degrees, in.vertices.data(),
                            static_cast<int>(in.vertices.size() / 3), in.triangles.data(), triangle_count,
                            in.areas.data());
    for (const auto& [first, last] : never_walked)
        std::fill(in.areas.begin() + first, in.areas.begin() + last, RC_NULL_AREA);
    bin_triangles(in, settings);
    return in;
}

} // namespace ks::nav
