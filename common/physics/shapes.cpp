#include "physics/shapes.h"

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
    p.edges.clear();
    p.edge_directions.clear();
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

struct HullTriangle {
    std::uint32_t v[3];
    Vec3 n;
    float d;
    bool alive;
};

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
        if (!is_finite(v) || std::abs(v.x) > 1e6f || std::abs(v.y) > 1e6f || std::abs(v.z) > 1e6f)
            return Error("vertex " + std::to_string(i) + " is not finite or beyond 1e6", Location(source),
                         "collision meshes need finite coordinates within +-1e6 units");
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

// Four extreme points spanning a volume: the start of the incremental hull.
Result<std::array<std::uint32_t, 4>> initial_tetrahedron(const std::vector<Vec3>& pts, float eps,
                                                         const std::string& source) {
    std::size_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
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
        if (float d = std::abs(glm::dot(pts[i] - pts[i0], n0)); d > best) best = d, i3 = i;
    if (best <= eps)
        return Error("collision mesh vertices are coplanar (zero volume)", Location(source),
                     "a flat object needs a thickness; use a box for walls and floors");

    return std::array<std::uint32_t, 4>{static_cast<std::uint32_t>(i0), static_cast<std::uint32_t>(i1),
                                        static_cast<std::uint32_t>(i2), static_cast<std::uint32_t>(i3)};
}

// The incremental hull: each point outside the current triangles replaces those it sees with a fan from
// their horizon. Dead triangles stay in the list (alive = false).
std::vector<HullTriangle> grow_hull(const std::vector<Vec3>& pts, const std::array<std::uint32_t, 4>& s,
                                    float eps) {
    std::vector<HullTriangle> tris;
    const Vec3 inside = (pts[s[0]] + pts[s[1]] + pts[s[2]] + pts[s[3]]) * 0.25f;
    auto make = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        Vec3 n = glm::normalize(glm::cross(pts[b] - pts[a], pts[c] - pts[a]));
        if (glm::dot(n, pts[a] - inside) < 0) {
            std::swap(b, c);
            n = -n;
        }
        tris.push_back({{a, b, c}, n, glm::dot(n, pts[a]), true});
    };
    make(s[0], s[1], s[2]);
    make(s[0], s[1], s[3]);
    make(s[0], s[2], s[3]);
    make(s[1], s[2], s[3]);
    std::vector<std::array<std::uint32_t, 2>> edges, horizon;
    for (std::uint32_t pi = 0; pi < pts.size(); ++pi) {
        if (pi == s[0] || pi == s[1] || pi == s[2] || pi == s[3]) continue;
        edges.clear();
        for (auto& t : tris)
            if (t.alive && glm::dot(t.n, pts[pi]) - t.d > eps) {
                t.alive = false;
                for (int k = 0; k < 3; ++k) edges.push_back({t.v[k], t.v[(k + 1) % 3]});
            }
        if (edges.empty()) continue;
        horizon.clear();
        for (auto& e : edges)
            if (std::find(edges.begin(), edges.end(), std::array<std::uint32_t, 2>{e[1], e[0]}) ==
                edges.end())
                horizon.push_back(e);
        for (auto& e : horizon) {
            Vec3 n = glm::cross(pts[e[1]] - pts[e[0]], pts[pi] - pts[e[0]]);
            float len = glm::length(n);
            if (len <= 1e-12f) continue; // degenerate sliver: the neighbours cover it
            n /= len;
            tris.push_back({{e[0], e[1], pi}, n, glm::dot(n, pts[pi]), true});
        }
    }
    return tris;
}

// Coplanar triangles merged into polygons, keeping only the vertices the hull uses.
Polyhedron hull_polyhedron(const std::vector<Vec3>& pts, const std::vector<HullTriangle>& tris, float eps) {
    Polyhedron p;
    std::vector<int> remap(pts.size(), -1);
    std::vector<bool> used(tris.size(), false);
    std::vector<std::uint32_t> group;
    for (std::size_t t = 0; t < tris.size(); ++t) {
        if (!tris[t].alive || used[t]) continue;
        group.clear();
        Vec3 n = tris[t].n;
        for (std::size_t u = t; u < tris.size(); ++u) {
            if (!tris[u].alive || used[u]) continue;
            if (glm::dot(tris[u].n, n) > 1.0f - 1e-5f && std::abs(tris[u].d - tris[t].d) <= eps) {
                used[u] = true;
                for (auto v : tris[u].v)
                    if (std::find(group.begin(), group.end(), v) == group.end()) group.push_back(v);
            }
        }
        Vec3 c(0.0f);
        for (auto v : group) c += pts[v];
        c /= static_cast<float>(group.size());
        const Vec3 u_axis = glm::normalize(pts[group[0]] - c);
        const Vec3 v_axis = glm::cross(n, u_axis);
        std::sort(group.begin(), group.end(), [&](std::uint32_t a, std::uint32_t b) {
            return std::atan2(glm::dot(pts[a] - c, v_axis), glm::dot(pts[a] - c, u_axis)) <
                   std::atan2(glm::dot(pts[b] - c, v_axis), glm::dot(pts[b] - c, u_axis));
        });
        // Drop vertices lying on a polygon edge (collinear): they would make zero-length edges.
        Polyhedron::Face f;
        f.first = static_cast<std::uint16_t>(p.face_vertices.size());
        for (std::size_t k = 0; k < group.size(); ++k) {
            const Vec3& a = pts[group[(k + group.size() - 1) % group.size()]];
            const Vec3& b = pts[group[k]];
            const Vec3& d = pts[group[(k + 1) % group.size()]];
            if (glm::length(glm::cross(b - a, d - b)) <= eps * eps) continue;
            if (remap[group[k]] < 0) {
                remap[group[k]] = static_cast<int>(p.vertices.size());
                p.vertices.push_back(pts[group[k]]);
            }
            p.face_vertices.push_back(static_cast<std::uint16_t>(remap[group[k]]));
        }
        f.count = static_cast<std::uint16_t>(p.face_vertices.size() - f.first);
        if (f.count >= 3)
            p.faces.push_back(f);
        else
            p.face_vertices.resize(f.first);
    }
    return p;
}

} // namespace

Result<Polyhedron> build_convex_hull(std::span<const Vec3> points, const std::string& source) {
    float eps = 0.0f;
    auto pts = weld_hull_points(points, source, eps);
    if (!pts) return pts.error();
    auto start = initial_tetrahedron(*pts, eps, source);
    if (!start) return start.error();
    Polyhedron p = hull_polyhedron(*pts, grow_hull(*pts, *start, eps), eps);
    if (p.faces.size() < 4 || p.vertices.size() > 65535)
        return Error("convex hull of the collision mesh is degenerate", Location(source),
                     "check the mesh for zero-area faces and near-duplicate vertices");
    finalize(p);
    return p;
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
