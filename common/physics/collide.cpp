#include "physics/collide.h"

#include "physics/triangle_mesh.h"

#include "geometry/obb.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::physics {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Interval {
    float lo = kInf, hi = -kInf;
};

Interval project(std::span<const Vec3> pts, const Vec3& axis) {
    Interval iv;
    for (const Vec3& p : pts) {
        float d = glm::dot(p, axis);
        iv.lo = std::min(iv.lo, d);
        iv.hi = std::max(iv.hi, d);
    }
    return iv;
}

// Average of the points within `tol` of the maximum along `dir`, and their spread (largest extent).
Vec3 support_centre(std::span<const Vec3> pts, const Vec3& dir, float tol, float& spread) {
    float best = -kInf;
    for (const Vec3& p : pts) best = std::max(best, glm::dot(p, dir));
    Vec3 sum(0.0f);
    geometry::Aabb box = geometry::Aabb::empty();
    int n = 0;
    for (const Vec3& p : pts)
        if (glm::dot(p, dir) >= best - tol) {
            sum += p;
            box.grow(p);
            ++n;
        }
    spread = glm::length(box.max - box.min);
    return sum / static_cast<float>(n);
}

// Scratch for world-space vertices (thread-local: no allocation per call once warm).
thread_local std::vector<Vec3> t_verts_a, t_verts_b;
thread_local Polyhedron t_box;
thread_local Vec3 t_box_half{-1.0f};

const Polyhedron& box_polyhedron(const Vec3& half) {
    if (half != t_box_half) {
        t_box = make_box_polyhedron(half);
        t_box_half = half;
    }
    return t_box;
}

} // namespace

bool is_yaw_only(const Quat& q) {
    return std::abs(q.x) < 1e-6f && std::abs(q.z) < 1e-6f;
}

void closest_segment_segment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, float& s,
                             float& t) {
    // Ericson, Real-Time Collision Detection 5.1.9, with the parallel case handled.
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    constexpr float kTiny = 1e-12f;
    if (a <= kTiny && e <= kTiny) {
        s = t = 0.0f;
        return;
    }
    if (a <= kTiny) {
        s = 0.0f;
        t = std::clamp(f / e, 0.0f, 1.0f);
        return;
    }
    const float c = glm::dot(d1, r);
    if (e <= kTiny) {
        t = 0.0f;
        s = std::clamp(-c / a, 0.0f, 1.0f);
        return;
    }
    const float b = glm::dot(d1, d2), denom = a * e - b * b;
    s = denom > 1e-7f * a * e ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
    t = (b * s + f) / e;
    if (t < 0.0f) {
        t = 0.0f;
        s = std::clamp(-c / a, 0.0f, 1.0f);
    } else if (t > 1.0f) {
        t = 1.0f;
        s = std::clamp((b - c) / a, 0.0f, 1.0f);
    }
}

std::optional<Contact> collide_convex(const Polyhedron& a, const geometry::Transform& xa, const Polyhedron& b,
                                      const geometry::Transform& xb, SatAxes axes) {
    // Work in A's frame: only B's vertices move, and A's projections on its own normals are exact.
    const Quat rel = glm::conjugate(xa.rotation) * xb.rotation;
    const Vec3 offset = xa.to_local(xb.position);
    auto& va = t_verts_a;
    auto& vb = t_verts_b;
    va.assign(a.vertices.begin(), a.vertices.end());
    vb.resize(b.vertices.size());
    for (std::size_t i = 0; i < b.vertices.size(); ++i) vb[i] = offset + rel * b.vertices[i];

    float best_pen = kInf;
    Vec3 best_normal(0.0f);
    int best_kind = 0; // 0 face of A, 1 face of B, 2 edge pair
    int best_ea = -1, best_eb = -1;
    auto test = [&](const Vec3& axis, int kind, int ea, int eb) -> bool {
        const Interval ia = project(va, axis), ib = project(vb, axis);
        if (ia.lo > ib.hi || ib.lo > ia.hi) return false; // separated (touching still counts as contact)
        const geometry::AxisOverlap<float> o = geometry::interval_overlap(ia.lo, ia.hi, ib.lo, ib.hi);
        const float pen = o.depth;
        // Edge axes must win clearly: near-ties flip-flop between features across frames.
        const float bias = kind == 2 ? 1e-5f * (1.0f + pen) : 0.0f;
        if (pen + bias < best_pen) {
            best_pen = pen;
            best_normal = o.push_a_positive ? axis : -axis;
            best_kind = kind;
            best_ea = ea;
            best_eb = eb;
        }
        return true;
    };
    for (const auto& f : a.faces)
        if (!test(f.normal, 0, -1, -1)) return std::nullopt;
    for (const auto& f : b.faces)
        if (!test(rel * f.normal, 1, -1, -1)) return std::nullopt;
    if (axes == SatAxes::FacesAndEdges) {
        for (std::size_t i = 0; i < a.edge_directions.size(); ++i)
            for (std::size_t j = 0; j < b.edge_directions.size(); ++j) {
                Vec3 c = glm::cross(a.edge_directions[i], rel * b.edge_directions[j]);
                const float len = glm::length(c);
                if (len < 1e-5f) continue; // (nearly) parallel edges: the face axes already cover them
                if (!test(c / len, 2, static_cast<int>(i), static_cast<int>(j))) return std::nullopt;
            }
    }
    Contact contact;
    contact.penetration = best_pen;
    Vec3 point;
    const float tol = 1e-4f * (1.0f + glm::length(a.bounds.max - a.bounds.min));
    if (best_kind == 2) {
        // Closest points of the two support edges along the axis.
        const Vec3 da = a.edge_directions[best_ea], db = rel * b.edge_directions[best_eb];
        auto pick = [&](const Polyhedron& p, std::span<const Vec3> v, const Vec3& dir, const Vec3& want) {
            int best = -1;
            float best_d = -kInf;
            for (std::size_t e = 0; e < p.edges.size(); ++e) {
                Vec3 ed = glm::normalize(v[p.edges[e][1]] - v[p.edges[e][0]]);
                if (std::abs(glm::dot(ed, dir)) < 1.0f - 1e-4f) continue;
                float d = glm::dot(v[p.edges[e][0]] + v[p.edges[e][1]], want);
                if (d > best_d) best_d = d, best = static_cast<int>(e);
            }
            return best;
        };
        const int ea = pick(a, va, da, -best_normal), eb = pick(b, vb, db, best_normal);
        if (ea >= 0 && eb >= 0) {
            float s, t;
            const Vec3 a0 = va[a.edges[ea][0]], a1 = va[a.edges[ea][1]];
            const Vec3 b0 = vb[b.edges[eb][0]], b1 = vb[b.edges[eb][1]];
            closest_segment_segment(a0, a1, b0, b1, s, t);
            point = (a0 + (a1 - a0) * s + b0 + (b1 - b0) * t) * 0.5f;
        } else {
            float sa, sb;
            point =
                (support_centre(va, -best_normal, tol, sa) + support_centre(vb, best_normal, tol, sb)) * 0.5f;
        }
    } else {
        // The smaller of the two support features is the incident one; midway between the surfaces.
        float spread_a, spread_b;
        const Vec3 ca = support_centre(va, -best_normal, tol, spread_a);
        const Vec3 cb = support_centre(vb, best_normal, tol, spread_b);
        point =
            spread_a < spread_b ? ca + best_normal * (best_pen * 0.5f) : cb - best_normal * (best_pen * 0.5f);
    }
    contact.normal = xa.dir_to_world(best_normal);
    contact.point = xa.to_world(point);
    return contact;
}

Segment capsule_segment(const Shape& capsule, const Vec3& centre) {
    const Vec3 up(0.0f, capsule.half_height, 0.0f);
    return {centre - up, centre + up};
}

namespace {

// Whether a point on a face's plane lies inside the face polygon (edges inclusive).
bool inside_face(const Polyhedron& p, const Polyhedron::Face& f, const Vec3& q) {
    auto idx = p.face_indices(f);
    for (std::size_t i = 0; i < idx.size(); ++i) {
        const Vec3& a = p.vertices[idx[i]];
        const Vec3& b = p.vertices[idx[(i + 1) % idx.size()]];
        if (glm::dot(glm::cross(b - a, q - a), f.normal) < 0.0f) return false;
    }
    return true;
}

} // namespace

SegmentDistance segment_polyhedron_distance(const Segment& s, const Polyhedron& p,
                                            const geometry::Transform& xf) {
    const Vec3 p0 = xf.to_local(s.p0), p1 = xf.to_local(s.p1), d = p1 - p0;
    // Clip the segment by every face plane: a non-empty remainder means it intersects the solid.
    float t0 = 0.0f, t1 = 1.0f;
    bool intersects = true;
    for (const auto& f : p.faces) {
        const float dist = glm::dot(f.normal, p0) - f.offset, dn = glm::dot(f.normal, d);
        if (dn == 0.0f) {
            if (dist > 0.0f) {
                intersects = false;
                break;
            }
            continue;
        }
        const float t = -dist / dn;
        if (dn < 0.0f)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) {
            intersects = false;
            break;
        }
    }
    SegmentDistance out;
    if (intersects) {
        out.distance = 0.0f;
        out.on_segment = out.on_shape = xf.to_world(p0 + d * t0);
        return out;
    }
    float best = kInf;
    Vec3 bs(0.0f), bp(0.0f);
    for (const auto& f : p.faces)
        for (const Vec3& e : {p0, p1}) {
            const float dist = glm::dot(f.normal, e) - f.offset;
            if (dist < 0.0f || dist >= best) continue;
            const Vec3 q = e - f.normal * dist;
            if (inside_face(p, f, q)) best = dist, bs = e, bp = q;
        }
    for (const auto& edge : p.edges) {
        const Vec3 &q0 = p.vertices[edge[0]], &q1 = p.vertices[edge[1]];
        float a, b;
        closest_segment_segment(p0, p1, q0, q1, a, b);
        const Vec3 x = p0 + d * a, y = q0 + (q1 - q0) * b;
        const float dist = glm::length(x - y);
        if (dist < best) best = dist, bs = x, bp = y;
    }
    out.distance = best;
    out.on_segment = xf.to_world(bs);
    out.on_shape = xf.to_world(bp);
    out.away = xf.dir_to_world(bs - bp);
    return out;
}

namespace {

// `away` points from the shape to the core and is computed where it is exact — in the shape's frame, or
// analytically — not as the difference of two world points: 4000 units from the origin a float world point
// has lost 4e-4 of its digits, enough to tilt a normal by 10 % when the core is 0.003 from the shape.
inline std::optional<Contact> from_distance(float distance, const Vec3& on_core, const Vec3& on_shape,
                                            const Vec3& away, float r, float margin) {
    if (distance > r + margin) return std::nullopt;
    Contact c;
    const float len = glm::length(away);
    c.normal = len > 0.0f ? away / len : Vec3(0.0f, 1.0f, 0.0f);
    c.penetration = r - distance;
    c.point = (on_shape + (on_core - c.normal * r)) * 0.5f;
    return c;
}

constexpr float kCoreTouch = 1e-6f; // below this the core is treated as intersecting (normal from SAT)

} // namespace

std::optional<Contact> collide_capsule_polyhedron(const Segment& s, float r, const Polyhedron& p,
                                                  const geometry::Transform& xf, float contact_margin) {
    const SegmentDistance sd = segment_polyhedron_distance(s, p, xf);
    if (sd.distance > kCoreTouch)
        return from_distance(sd.distance, sd.on_segment, sd.on_shape, sd.away, r, contact_margin);
    // The core segment touches or crosses the solid: SAT between the segment and the polyhedron (axes: face
    // normals, and segment × edge directions), in the polyhedron's frame.
    const Vec3 p0 = xf.to_local(s.p0), p1 = xf.to_local(s.p1);
    const Vec3 seg = p1 - p0;
    float best = kInf;
    Vec3 best_axis(0.0f, 1.0f, 0.0f);
    auto test = [&](const Vec3& axis) {
        float lo = kInf, hi = -kInf;
        for (const Vec3& v : p.vertices) {
            float d = glm::dot(v, axis);
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
        const float s0 = glm::dot(p0, axis), s1 = glm::dot(p1, axis);
        const float push_pos = hi - std::min(s0, s1), push_neg = std::max(s0, s1) - lo;
        const float pen = std::min(push_pos, push_neg);
        if (pen < best) best = pen, best_axis = push_pos <= push_neg ? axis : -axis;
    };
    for (const auto& f : p.faces) test(f.normal);
    const float seg_len = glm::length(seg);
    if (seg_len > 1e-6f)
        for (const Vec3& e : p.edge_directions) {
            Vec3 c = glm::cross(seg / seg_len, e);
            float len = glm::length(c);
            if (len > 1e-5f) test(c / len);
        }
    Contact c;
    c.normal = xf.dir_to_world(best_axis);
    c.penetration = best + r;
    c.point = sd.on_segment;
    return c;
}

namespace {
// The box frame: a general rotation, or (walls, floors, most crates) none, where the frame changes are a
// translation only. Rotating by the identity quaternion returns its input exactly, so both give the same
// results; the translation-only frame just skips four quaternion rotations per call.
struct RotatedFrame {
    const geometry::Transform& xf;
    Vec3 to_local(const Vec3& p) const { return xf.to_local(p); }
    Vec3 to_world(const Vec3& p) const { return xf.to_world(p); }
    Vec3 dir_to_world(const Vec3& d) const { return xf.dir_to_world(d); }
};
struct TranslatedFrame {
    const Vec3& position;
    Vec3 to_local(const Vec3& p) const { return p - position; }
    Vec3 to_world(const Vec3& p) const { return position + p; }
    Vec3 dir_to_world(const Vec3& d) const { return d; }
};

template <class Frame>
std::optional<Contact> capsule_box_in(const Segment& s, float r, const Vec3& half, const Frame& xf,
                                      float contact_margin) {
    const Vec3 a = xf.to_local(s.p0), b = xf.to_local(s.p1);
    // Upright segment in a yaw-only frame: x and z are the same at both ends (up to rounding).
    const float px = (a.x + b.x) * 0.5f, pz = (a.z + b.z) * 0.5f;
    const float ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
    const float cx = std::clamp(px, -half.x, half.x), cz = std::clamp(pz, -half.z, half.z);
    float sy, cy; // closest y on the segment and on the box
    if (yhi < -half.y)
        sy = yhi, cy = -half.y;
    else if (ylo > half.y)
        sy = ylo, cy = half.y;
    else
        sy = cy = std::clamp(0.5f * (std::max(ylo, -half.y) + std::min(yhi, half.y)), ylo, yhi);
    const Vec3 on_core(px, sy, pz), on_box(cx, cy, cz);
    const Vec3 delta = on_core - on_box;
    const float dist = glm::length(delta);
    // from_distance's own refusal, before the frame changes
    if (dist > kCoreTouch && dist > r + contact_margin) return std::nullopt;
    if (dist > kCoreTouch) {
        return from_distance(dist, xf.to_world(on_core), xf.to_world(on_box), xf.dir_to_world(delta), r,
                             contact_margin);
    }
    // Core inside the box: least push among the six faces.
    const float pen_xp = half.x - px, pen_xn = px + half.x;
    const float pen_zp = half.z - pz, pen_zn = pz + half.z;
    const float pen_yp = half.y - ylo, pen_yn = yhi + half.y;
    float best = pen_yp;
    Vec3 n(0.0f, 1.0f, 0.0f);
    if (pen_yn < best) best = pen_yn, n = {0.0f, -1.0f, 0.0f};
    if (pen_xp < best) best = pen_xp, n = {1.0f, 0.0f, 0.0f};
    if (pen_xn < best) best = pen_xn, n = {-1.0f, 0.0f, 0.0f};
    if (pen_zp < best) best = pen_zp, n = {0.0f, 0.0f, 1.0f};
    if (pen_zn < best) best = pen_zn, n = {0.0f, 0.0f, -1.0f};
    Contact c;
    c.normal = xf.dir_to_world(n);
    c.penetration = best + r;
    c.point = xf.to_world(on_core);
    return c;
}
} // namespace

std::optional<Contact> collide_capsule_box(const Segment& s, float r, const Vec3& half,
                                           const geometry::Transform& xf, float contact_margin) {
    if (xf.rotation == Quat(1.0f, 0.0f, 0.0f, 0.0f))
        return capsule_box_in(s, r, half, TranslatedFrame{xf.position}, contact_margin);
    return capsule_box_in(s, r, half, RotatedFrame{xf}, contact_margin);
}

std::optional<Contact> collide_capsule_capsule(const Segment& a, float ra, const Segment& b, float rb,
                                               float contact_margin) {
    float s, t;
    closest_segment_segment(a.p0, a.p1, b.p0, b.p1, s, t);
    const Vec3 pa = a.p0 + (a.p1 - a.p0) * s, pb = b.p0 + (b.p1 - b.p0) * t;
    const Vec3 delta = pa - pb;
    const float dist = glm::length(delta);
    if (dist > ra + rb + contact_margin) return std::nullopt;
    Contact c;
    c.normal = dist > kCoreTouch ? delta / dist : Vec3(1.0f, 0.0f, 0.0f); // coincident cores: any direction
    c.penetration = ra + rb - dist;
    c.point = (pa - c.normal * ra + pb + c.normal * rb) * 0.5f;
    return c;
}

std::optional<Contact> collide_capsule_cylinder(const Segment& s, float r, const Vec3& centre, float radius,
                                                float half_height, float contact_margin) {
    // Both upright: an exact 2D problem in the (radial, y) half-plane through the capsule's axis.
    const float px = (s.p0.x + s.p1.x) * 0.5f, pz = (s.p0.z + s.p1.z) * 0.5f;
    const float ylo = std::min(s.p0.y, s.p1.y), yhi = std::max(s.p0.y, s.p1.y);
    Vec3 radial(px - centre.x, 0.0f, pz - centre.z);
    const float hd = glm::length(radial);
    radial = hd > 1e-7f ? radial / hd : Vec3(1.0f, 0.0f, 0.0f);
    const float bottom = centre.y - half_height, top = centre.y + half_height;
    const float gx = std::max(0.0f, hd - radius);
    float gy = 0.0f, sy, cy;
    if (ylo > top)
        gy = ylo - top, sy = ylo, cy = top;
    else if (yhi < bottom)
        gy = -(bottom - yhi), sy = yhi, cy = bottom;
    else
        sy = cy = std::clamp(0.5f * (std::max(ylo, bottom) + std::min(yhi, top)), ylo, yhi);
    const float dist = std::sqrt(gx * gx + gy * gy);
    const Vec3 on_core(px, sy, pz);
    const Vec3 on_cyl = Vec3(centre.x, cy, centre.z) + radial * std::min(hd, radius);
    if (dist > kCoreTouch)
        return from_distance(dist, on_core, on_cyl, radial * gx + Vec3(0.0f, gy, 0.0f), r, contact_margin);
    const float pen_radial = radius - hd, pen_up = top - ylo, pen_down = yhi - bottom;
    Contact c;
    c.point = on_core;
    if (pen_radial <= pen_up && pen_radial <= pen_down)
        c.normal = radial, c.penetration = pen_radial + r;
    else if (pen_up <= pen_down)
        c.normal = {0.0f, 1.0f, 0.0f}, c.penetration = pen_up + r;
    else
        c.normal = {0.0f, -1.0f, 0.0f}, c.penetration = pen_down + r;
    return c;
}

std::optional<Contact> collide_capsule_shape(const Segment& s, float r, const Shape& shape,
                                             const geometry::Transform& xf, float contact_margin) {
    switch (shape.kind) {
    case ShapeKind::Box:
        if (is_yaw_only(xf.rotation))
            return collide_capsule_box(s, r, shape.half_extents, xf, contact_margin);
        return collide_capsule_polyhedron(s, r, box_polyhedron(shape.half_extents), xf, contact_margin);
    case ShapeKind::Wedge:
    case ShapeKind::Hull:
        return collide_capsule_polyhedron(s, r, *shape.polyhedron, xf, contact_margin);
    case ShapeKind::Capsule:
        return collide_capsule_capsule(s, r, capsule_segment(shape, xf.position), shape.radius,
                                       contact_margin);
    case ShapeKind::Cylinder:
        return collide_capsule_cylinder(s, r, xf.position, shape.radius, shape.half_height, contact_margin);
    case ShapeKind::Mesh:
        return collide_capsule_mesh(s, r, *shape.mesh, xf, contact_margin);
    }
    return std::nullopt;
}

} // namespace ks::physics
