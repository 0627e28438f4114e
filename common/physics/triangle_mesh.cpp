#include "physics/triangle_mesh.h"

#include "geometry/closest_on_triangle.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {

namespace {

DVec3 to_double(const Vec3& v) {
    return exact_double(v);
}

glm::dquat rotation_of(const geometry::Transform& xf) {
    return glm::dquat(static_cast<double>(xf.rotation.w), static_cast<double>(xf.rotation.x),
                      static_cast<double>(xf.rotation.y), static_cast<double>(xf.rotation.z));
}

// The shared algorithm (geometry/closest_on_triangle.h), in double.
DVec3 closest_on_triangle(const DVec3& p, const DVec3& a, const DVec3& b, const DVec3& c) {
    return geometry::closest_on_triangle(p, a, b, c).point;
}

// Ericson 5.1.9 in double, the parallel case included: parameters of the closest points of two segments.
void closest_segments(const DVec3& p1, const DVec3& q1, const DVec3& p2, const DVec3& q2, double& s,
                      double& t) {
    const DVec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    if (a <= 0.0 && e <= 0.0) {
        s = t = 0.0;
        return;
    }
    if (a <= 0.0) {
        s = 0.0;
        t = std::clamp(f / e, 0.0, 1.0);
        return;
    }
    const double c = glm::dot(d1, r);
    if (e <= 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
        return;
    }
    const double b = glm::dot(d1, d2), denom = a * e - b * b;
    s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
}

// Where the segment crosses the triangle's plane inside the triangle, if it does.
bool segment_crosses(const DVec3& p0, const DVec3& p1, const DVec3& a, const DVec3& b, const DVec3& c,
                     const DVec3& n, DVec3& at) {
    const double s0 = glm::dot(n, p0 - a), s1 = glm::dot(n, p1 - a);
    if ((s0 > 0.0 && s1 > 0.0) || (s0 < 0.0 && s1 < 0.0) || s0 == s1) return false;
    at = p0 + (p1 - p0) * (s0 / (s0 - s1));
    return glm::dot(glm::cross(b - a, at - a), n) >= 0.0 && glm::dot(glm::cross(c - b, at - b), n) >= 0.0 &&
           glm::dot(glm::cross(a - c, at - c), n) >= 0.0;
}

struct LocalTriangle {
    DVec3 a, b, c;
};
LocalTriangle local_triangle(const TriangleMesh& mesh, std::uint32_t i) {
    const auto& t = mesh.triangles[i];
    return {to_double(t[0]), to_double(t[1]), to_double(t[2])};
}

// The contact of a capsule around the local segment with a triangle, in the mesh frame (double).
struct LocalContact {
    DVec3 normal;
    double penetration;
    DVec3 point;
};
constexpr double kCrossing = 1e-7; // closer than this the direction between witnesses is noise: use the face

LocalContact local_contact(const LocalSegment& s, double r, const LocalTriangle& t) {
    const SegmentTriangleDistance d = segment_triangle_distance(s.p0, s.p1, t.a, t.b, t.c);
    LocalContact out;
    if (d.distance >= kCrossing) {
        out.normal = (d.on_segment - d.on_triangle) / d.distance;
        out.penetration = r - d.distance;
        out.point = (d.on_segment - out.normal * r + d.on_triangle) * 0.5;
        return out;
    }
    DVec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    if (glm::dot(n, (s.p0 + s.p1) * 0.5 - t.a) < 0.0) n = -n;
    const double behind = -std::min(glm::dot(n, s.p0 - t.a), glm::dot(n, s.p1 - t.a));
    out.normal = n;
    out.penetration = r - d.distance + std::max(0.0, behind);
    out.point = d.on_triangle;
    return out;
}

Contact world_contact(const LocalContact& c, const geometry::Transform& xf) {
    const glm::dquat q = rotation_of(xf);
    Contact out;
    out.normal = Vec3(glm::normalize(q * c.normal));
    out.penetration = static_cast<float>(c.penetration);
    out.point = Vec3(to_double(xf.position) + q * c.point);
    return out;
}

} // namespace

SegmentTriangleDistance segment_triangle_distance(const DVec3& p0, const DVec3& p1, const DVec3& a,
                                                  const DVec3& b, const DVec3& c) {
    SegmentTriangleDistance best;
    const DVec3 n = glm::cross(b - a, c - a);
    DVec3 at;
    if (segment_crosses(p0, p1, a, b, c, n, at)) {
        best.on_segment = best.on_triangle = at;
        return best;
    }
    best.distance = 1e300;
    auto consider = [&](const DVec3& on_segment, const DVec3& on_triangle) {
        const double d = glm::length(on_segment - on_triangle);
        if (d < best.distance) best = {d, on_segment, on_triangle};
    };
    consider(p0, closest_on_triangle(p0, a, b, c));
    consider(p1, closest_on_triangle(p1, a, b, c));
    const DVec3 corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
        const DVec3 &e0 = corners[k], &e1 = corners[(k + 1) % 3];
        double s = 0.0, t = 0.0;
        closest_segments(p0, p1, e0, e1, s, t);
        consider(p0 + (p1 - p0) * s, e0 + (e1 - e0) * t);
    }
    return best;
}

LocalSegment local_segment(const Segment& s, const geometry::Transform& xf) {
    const glm::dquat inv = glm::conjugate(rotation_of(xf));
    const DVec3 origin = to_double(xf.position);
    return {inv * (to_double(s.p0) - origin), inv * (to_double(s.p1) - origin)};
}

std::optional<Contact> collide_capsule_triangle(const Segment& s, float r, const TriangleMesh& mesh,
                                                std::uint32_t triangle, const geometry::Transform& xf,
                                                float contact_margin) {
    const LocalContact c = local_contact(local_segment(s, xf), r, local_triangle(mesh, triangle));
    if (c.penetration < -static_cast<double>(contact_margin)) return std::nullopt;
    return world_contact(c, xf);
}

std::optional<Contact> collide_capsule_mesh(const Segment& s, float r, const TriangleMesh& mesh,
                                            const geometry::Transform& xf, float contact_margin) {
    const LocalSegment ls = local_segment(s, xf);
    const double reach = static_cast<double>(r) + std::max(0.0, static_cast<double>(contact_margin));
    geometry::Aabb region{Vec3(glm::min(ls.p0, ls.p1) - reach), Vec3(glm::max(ls.p0, ls.p1) + reach)};
    region = region.expanded(1e-5f + 1e-6f * glm::length(region.max - region.min));
    std::optional<LocalContact> best;
    std::uint32_t best_triangle = 0;
    mesh.bvh.aabb_query(region, [&](std::uint32_t slot) {
        const LocalContact c = local_contact(ls, r, local_triangle(mesh, slot));
        if (c.penetration >= -static_cast<double>(contact_margin) &&
            (!best || c.penetration > best->penetration ||
             (c.penetration == best->penetration && slot < best_triangle)))
            best = c, best_triangle = slot;
        return true;
    });
    if (!best) return std::nullopt;
    return world_contact(*best, xf);
}

bool ray_mesh(const geometry::Ray& ray, const TriangleMesh& mesh, const geometry::Transform& xf,
              ShapeHit& hit) {
    const glm::dquat q = rotation_of(xf), inv = glm::conjugate(q);
    const DVec3 origin = inv * (to_double(ray.origin) - to_double(xf.position));
    const DVec3 dir = inv * to_double(ray.direction);
    const geometry::Ray local{Vec3(origin), Vec3(dir), ray.max_distance};
    double best = static_cast<double>(ray.max_distance);
    DVec3 best_normal(0.0);
    bool found = false;
    mesh.bvh.ray_query(local, ray.max_distance, [&](std::uint32_t slot, const Vec3&, float& max_t) {
        const LocalTriangle t = local_triangle(mesh, slot);
        // Möller-Trumbore in double, both sides, edges included.
        const DVec3 e1 = t.b - t.a, e2 = t.c - t.a, p = glm::cross(dir, e2);
        const double det = glm::dot(e1, p);
        if (det == 0.0) return true; // the ray lies in the triangle's plane: it grazes, as along a face
        const double inv_det = 1.0 / det;
        const DVec3 o = origin - t.a;
        const double u = glm::dot(o, p) * inv_det;
        if (u < 0.0 || u > 1.0) return true;
        const DVec3 qv = glm::cross(o, e1);
        const double v = glm::dot(dir, qv) * inv_det;
        if (v < 0.0 || u + v > 1.0) return true;
        const double d = glm::dot(e2, qv) * inv_det;
        if (d < 0.0 || d > best || (d == best && found)) return true;
        best = d, found = true;
        const DVec3 n = glm::cross(e1, e2);
        best_normal = glm::dot(n, dir) > 0.0 ? -n : n;
        max_t = std::nextafter(static_cast<float>(d), 3.4e38f); // never prunes the node holding d
        return true;
    });
    if (!found) return false;
    hit.distance = static_cast<float>(best);
    hit.normal = Vec3(glm::normalize(q * best_normal));
    return true;
}

Vec3 triangle_normal(const TriangleMesh& mesh, std::uint32_t triangle, const geometry::Transform& xf,
                     const Vec3& toward) {
    const LocalTriangle t = local_triangle(mesh, triangle);
    const Vec3 n = Vec3(glm::normalize(rotation_of(xf) * glm::cross(t.b - t.a, t.c - t.a)));
    return glm::dot(n, toward) < 0.0f ? -n : n;
}

geometry::Aabb triangle_world_bounds(const TriangleMesh& mesh, std::uint32_t triangle,
                                     const geometry::Transform& xf) {
    geometry::Aabb box = geometry::Aabb::empty();
    for (const Vec3& v : mesh.triangles[triangle]) box.grow(xf.to_world(v));
    const Vec3 pad = (glm::abs(box.min) + glm::abs(box.max)) * 2e-6f + Vec3(1e-5f);
    return {box.min - pad, box.max + pad};
}

geometry::Aabb local_region(const geometry::Aabb& world, const geometry::Transform& xf) {
    const Mat3 r = glm::mat3_cast(glm::conjugate(xf.rotation));
    const Vec3 c = xf.to_local(world.center()), h = world.extent();
    Vec3 e(0.0f);
    for (int i = 0; i < 3; ++i)
        e[i] = std::abs(r[0][i]) * h.x + std::abs(r[1][i]) * h.y + std::abs(r[2][i]) * h.z;
    const Vec3 pad = (glm::abs(c) + e) * 2e-6f + Vec3(1e-5f);
    return {c - e - pad, c + e + pad};
}

Result<MeshBody> mesh_body(std::span<const DVec3> vertices,
                           std::span<const std::array<std::uint32_t, 3>> triangles,
                           const std::string& source) {
    if (triangles.size() > kMaxMeshTriangles)
        return Error(source + ": " + std::to_string(triangles.size()) + " triangles, more than the " +
                         std::to_string(kMaxMeshTriangles) + " a collision mesh may have",
                     Location(source), "simplify the model, or choose collision \"hull\" or \"box\"");
    DVec3 lo(1e300), hi(-1e300);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const DVec3& v = vertices[i];
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(v[k]) || std::abs(v[k]) > kMaxMeshCoordinate)
                return Error(source + ": vertex " + std::to_string(i) + " is not finite or beyond +-1e6",
                             Location(source), "check the model's scale and position");
        lo = glm::min(lo, v), hi = glm::max(hi, v);
    }
    MeshBody body;
    body.transform.position = vertices.empty() ? Vec3(0.0f) : Vec3((lo + hi) * 0.5);
    const DVec3 origin = exact_double(body.transform.position);
    auto mesh = std::make_shared<TriangleMesh>();
    std::vector<std::array<Vec3, 3>> kept;
    kept.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        std::array<Vec3, 3> t;
        for (int k = 0; k < 3; ++k) {
            if (triangles[i][k] >= vertices.size())
                return Error(source + ": triangle " + std::to_string(i) + " names vertex " +
                                 std::to_string(triangles[i][k]) + " of " + std::to_string(vertices.size()),
                             Location(source), "the model's index buffer is broken: export it again");
            t[k] = Vec3(vertices[triangles[i][k]] - origin);
        }
        const DVec3 a = to_double(t[0]), b = to_double(t[1]), c = to_double(t[2]);
        const double longest =
            std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
        if (!(glm::length(glm::cross(b - a, c - a)) > 1e-10 * longest)) {
            ++mesh->dropped_degenerate;
            continue;
        }
        kept.push_back(t);
    }
    if (kept.empty())
        return Error(source + ": no triangle with an area (" + std::to_string(mesh->dropped_degenerate) +
                         " degenerate dropped)",
                     Location(source), "choose collision \"box\" or \"none\"");
    std::vector<geometry::Aabb> boxes(kept.size());
    mesh->bounds = geometry::Aabb::empty();
    for (std::size_t i = 0; i < kept.size(); ++i) {
        boxes[i] = geometry::Aabb::empty();
        for (const Vec3& v : kept[i]) boxes[i].grow(v);
        mesh->bounds.grow(boxes[i]);
    }
    mesh->bvh.build(boxes);
    mesh->triangles.reserve(kept.size());
    for (std::uint32_t item : mesh->bvh.item_order()) mesh->triangles.push_back(kept[item]);
    body.shape.kind = ShapeKind::Mesh;
    // Centred on the position only to float rounding: the half extents cover both sides.
    body.shape.half_extents =
        glm::max(glm::max(glm::abs(mesh->bounds.min), glm::abs(mesh->bounds.max)), Vec3(1e-4f));
    body.shape.mesh = std::move(mesh);
    return body;
}

} // namespace ks::physics
