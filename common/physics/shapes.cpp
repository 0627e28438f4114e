#include "physics/shapes.h"

#include "brush/brush_build.h"
#include "physics/brush_shape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace ks::physics {
namespace {

// Fills normals, offsets, centres, edges, edge directions and bounds from vertices + face vertex lists.
void finalize(Polyhedron& p) {
    p.bounds = geometry::Aabb::empty();
    for (const Vec3& v : p.vertices) p.bounds.grow(v);
    for (auto& f : p.faces) {
        auto idx = p.face_indices(f);
        Vec3 n(0.0f), c(0.0f);
        for (std::size_t i = 0; i < idx.size(); ++i) { // Newell's method: robust for any planar polygon
            const Vec3& a = p.vertices[idx[i]];
            const Vec3& b = p.vertices[idx[(i + 1) % idx.size()]];
            n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            c += a;
        }
        f.normal = glm::normalize(n);
        f.centre = c / static_cast<float>(idx.size());
        f.offset = glm::dot(f.normal, f.centre);
    }
    derive_edges(p);
}

void add_face(Polyhedron& p, std::initializer_list<std::uint16_t> idx) {
    Polyhedron::Face f;
    f.first = static_cast<std::uint16_t>(p.face_vertices.size());
    f.count = static_cast<std::uint16_t>(idx.size());
    p.face_vertices.insert(p.face_vertices.end(), idx);
    p.faces.push_back(f);
}

bool finite_positive(float v) {
    return std::isfinite(v) && v > 0.0f && v < 1e5f;
}

} // namespace

void derive_edges(Polyhedron& p) {
    p.edges.clear();
    p.edge_directions.clear();
    for (const auto& f : p.faces) {
        auto idx = p.face_indices(f);
        for (std::size_t i = 0; i < idx.size(); ++i) {
            std::uint16_t a = idx[i], b = idx[(i + 1) % idx.size()];
            std::array<std::uint16_t, 2> e{std::min(a, b), std::max(a, b)};
            if (std::find(p.edges.begin(), p.edges.end(), e) == p.edges.end()) p.edges.push_back(e);
        }
    }
    for (auto& e : p.edges) {
        Vec3 d = glm::normalize(p.vertices[e[1]] - p.vertices[e[0]]);
        bool seen = false;
        for (const Vec3& o : p.edge_directions)
            if (std::abs(glm::dot(o, d)) > 1.0f - 1e-6f) seen = true;
        if (!seen) p.edge_directions.push_back(d);
    }
}

Polyhedron make_box_polyhedron(const Vec3& h) {
    Polyhedron p;
    for (int i = 0; i < 8; ++i)
        p.vertices.push_back({(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z});
    // Counter-clockwise seen from outside.
    add_face(p, {1, 3, 7, 5}); // +x
    add_face(p, {0, 4, 6, 2}); // -x
    add_face(p, {2, 6, 7, 3}); // +y
    add_face(p, {0, 1, 5, 4}); // -y
    add_face(p, {4, 5, 7, 6}); // +z
    add_face(p, {0, 2, 3, 1}); // -z
    finalize(p);
    return p;
}

Polyhedron make_wedge_polyhedron(const Vec3& h) {
    // Full height at local -z, zero height at +z: the ramp rises toward -z.
    Polyhedron p;
    p.vertices = {{-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z},
                  {-h.x, -h.y, h.z},  {-h.x, h.y, -h.z}, {h.x, h.y, -h.z}};
    add_face(p, {0, 1, 2, 3}); // bottom (-y)
    add_face(p, {0, 4, 5, 1}); // back (-z)
    add_face(p, {3, 2, 5, 4}); // slope
    add_face(p, {1, 5, 2});    // +x side
    add_face(p, {0, 3, 4});    // -x side
    finalize(p);
    return p;
}

namespace {

// The distinct input points (near-duplicates closer than `eps` welded), after checking count and range.
Result<std::vector<Vec3>> weld_hull_points(std::span<const Vec3> points, const std::string& source,
                                           float& eps) {
    constexpr std::size_t kMaxPoints = 8192;
    if (points.size() > kMaxPoints)
        return Error("convex hull has " + std::to_string(points.size()) + " vertices", Location(source),
                     "use a simplified collision mesh of at most 8192 vertices");
    geometry::Aabb box = geometry::Aabb::empty();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3& v = points[i];
        constexpr float kLimit = static_cast<float>(brush::kMaxCoordinate);
        if (!is_finite(v) || std::abs(v.x) > kLimit || std::abs(v.y) > kLimit || std::abs(v.z) > kLimit)
            return Error("vertex " + std::to_string(i) + " is not finite or beyond 65536", Location(source),
                         "collision meshes need finite coordinates within +-65536 units");
        box.grow(v);
    }
    const float scale = points.empty() ? 0.0f : glm::length(box.max - box.min);
    eps = std::max(scale * 1e-5f, 1e-6f);
    // Weld duplicates (and near-duplicates closer than eps).
    std::vector<Vec3> pts;
    for (const Vec3& v : points) {
        bool dup = false;
        for (const Vec3& u : pts)
            if (glm::length(u - v) <= eps) dup = true;
        if (!dup) pts.push_back(v);
    }
    if (pts.size() < 4)
        return Error("convex hull needs at least 4 distinct vertices, got " + std::to_string(pts.size()),
                     Location(source), "a collision mesh must enclose a volume");
    return pts;
}

// Refuses points with no four spanning a volume (within `eps`), naming what they are instead: the checks the
// hull itself would make, with the prop's words.
Result<void> check_spans_volume(const std::vector<Vec3>& pts, float eps, const std::string& source) {
    std::size_t i0 = 0, i1 = 0, i2 = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (pts[i].x < pts[i0].x) i0 = i;
    float best = -1;
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (float d = glm::length(pts[i] - pts[i0]); d > best) best = d, i1 = i;
    best = -1;
    const Vec3 axis = glm::normalize(pts[i1] - pts[i0]);
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (float d = glm::length(glm::cross(pts[i] - pts[i0], axis)); d > best) best = d, i2 = i;
    if (best <= eps)
        return Error("collision mesh vertices are collinear (zero volume)", Location(source),
                     "a collision mesh must enclose a volume");
    const Vec3 n0 = glm::normalize(glm::cross(pts[i1] - pts[i0], pts[i2] - pts[i0]));
    best = -1;
    for (std::size_t i = 0; i < pts.size(); ++i)
        best = std::max(best, std::abs(glm::dot(pts[i] - pts[i0], n0)));
    if (best <= eps)
        return Error("collision mesh vertices are coplanar (zero volume)", Location(source),
                     "a flat object needs a thickness; use a box for walls and floors");

    return ok();
}

} // namespace

Result<Polyhedron> build_convex_hull(std::span<const Vec3> points, const std::string& source) {
    float eps = 0.0f;
    auto pts = weld_hull_points(points, source, eps);
    if (!pts) return pts.error();
    if (auto spans = check_spans_volume(*pts, eps, source); !spans) return spans.error();
    std::vector<DVec3> exact(pts->begin(), pts->end());
    auto hull = brush::make_from_points(exact);
    if (!hull)
        return Error("convex hull of the collision mesh: " + hull.error().message, Location(source),
                     "check the mesh for zero-area faces and near-duplicate vertices");
    return brush_polyhedron(*hull, DVec3(0.0));
}

Shape Shape::box(const Vec3& half) {
    Shape s;
    s.kind = ShapeKind::Box;
    s.half_extents = half;
    return s;
}

Shape Shape::wedge(const Vec3& half) {
    Shape s;
    s.kind = ShapeKind::Wedge;
    s.half_extents = half;
    s.polyhedron = std::make_shared<const Polyhedron>(make_wedge_polyhedron(half));
    return s;
}

Shape Shape::capsule(float radius, float half_segment) {
    Shape s;
    s.kind = ShapeKind::Capsule;
    s.radius = radius;
    s.half_height = half_segment;
    s.half_extents = {radius, half_segment + radius, radius};
    return s;
}

Shape Shape::cylinder(float radius, float half_height) {
    Shape s;
    s.kind = ShapeKind::Cylinder;
    s.radius = radius;
    s.half_height = half_height;
    s.half_extents = {radius, half_height, radius};
    return s;
}

Shape Shape::hull(Polyhedron polyhedron) {
    Shape s;
    s.kind = ShapeKind::Hull;
    // Recentre so the body position is the centre of the bounding box, like every other shape.
    const Vec3 c = polyhedron.bounds.center();
    if (c != Vec3(0.0f)) {
        for (Vec3& v : polyhedron.vertices) v -= c;
        for (auto& f : polyhedron.faces) {
            f.centre -= c;
            f.offset = glm::dot(f.normal, f.centre);
        }
        polyhedron.bounds = {polyhedron.bounds.min - c, polyhedron.bounds.max - c};
    }
    s.half_extents = (polyhedron.bounds.max - polyhedron.bounds.min) * 0.5f;
    s.polyhedron = std::make_shared<const Polyhedron>(std::move(polyhedron));
    return s;
}

Result<void> Shape::validate(const std::string& what) const {
    auto bad = [&](const std::string& field, float v) {
        return Error(what + ": " + field + " is " + std::to_string(v), Location(what),
                     "sizes must be finite, greater than 0 and below 1e5 units");
    };
    switch (kind) {
    case ShapeKind::Box:
    case ShapeKind::Wedge:
    case ShapeKind::Hull:
        for (int i = 0; i < 3; ++i)
            if (!finite_positive(half_extents[i]))
                return bad("half extent " + std::to_string(i), half_extents[i]);
        if (kind != ShapeKind::Box && !polyhedron)
            return Error(what + ": polyhedron missing", Location(what), "build wedges with Shape::wedge");
        break;
    case ShapeKind::Mesh:
        for (int i = 0; i < 3; ++i)
            if (!finite_positive(half_extents[i]))
                return bad("half extent " + std::to_string(i), half_extents[i]);
        if (!mesh)
            return Error(what + ": triangle mesh missing", Location(what), "build meshes with mesh_body");
        break;
    case ShapeKind::Capsule:
    case ShapeKind::Cylinder:
        if (!finite_positive(radius)) return bad("radius", radius);
        if (!(std::isfinite(half_height) && half_height >= 0.0f && half_height < 1e5f) ||
            (kind == ShapeKind::Cylinder && half_height <= 0.0f))
            return bad("half height", half_height);
        break;
    }
    return ok();
}

geometry::Aabb Shape::bounds(const geometry::Transform& xf) const {
    if (kind == ShapeKind::Capsule || kind == ShapeKind::Cylinder)
        return {xf.position - half_extents, xf.position + half_extents};
    const Mat3 r = glm::mat3_cast(xf.rotation);
    Vec3 e(0.0f);
    for (int i = 0; i < 3; ++i)
        e[i] = std::abs(r[0][i]) * half_extents.x + std::abs(r[1][i]) * half_extents.y +
               std::abs(r[2][i]) * half_extents.z;
    return {xf.position - e, xf.position + e};
}

} // namespace ks::physics
