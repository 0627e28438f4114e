#include "shapes.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr double kPiD = 3.14159265358979323846;

// Trigonometry in double, rounded once to float: keeps vertex data identical between optimisation levels.
float dsin(double a) {
    return static_cast<float>(std::sin(a));
}
float dcos(double a) {
    return static_cast<float>(std::cos(a));
}

thread_local Detail g_detail;

// How far inside its circle a chord spanning `angle` radians of a circle of `radius` comes (its sag).
float chord_sag(double radius, double angle) {
    return static_cast<float>(radius * (1.0 - std::cos(0.5 * angle)));
}
// The fewest sides (3 up to `designed`) of a polygon inscribed in a circle of `radius` that sags at most
// `budget` inside it; `designed` when the budget is 0 (full detail).
int segments_within(int designed, double radius, double budget) {
    if (budget <= 0.0) return designed;
    for (int m = 3; m < designed; ++m)
        if (chord_sag(radius, 2.0 * kPiD / m) <= budget) return m;
    return designed;
}
// The fewest steps (1 up to `designed`) over an arc of `arc` radians of a circle of `radius` whose chords,
// with the designed ones', stay within `budget` of each other (each within its sag of the circle).
int arc_steps_within(int designed, double radius, double arc, double budget) {
    if (budget <= 0.0) return designed;
    const float designed_sag = chord_sag(radius, arc / designed);
    for (int k = 1; k < designed; ++k)
        if (chord_sag(radius, arc / k) + designed_sag <= budget) return k;
    return designed;
}

struct Face {
    vec3 n, a, b; // outward normal, image-right axis, image-up axis (a x b = n)
};
constexpr Face kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
};

// Grid positions along one axis of a face: the rounded band is sampled at equal angles.
std::vector<float> face_stops(float half, float inner, float radius, int segments) {
    std::vector<float> stops;
    if (radius <= 0.0f || segments <= 0) return {-half, half};
    for (int k = segments; k >= 1; --k)
        stops.push_back(-inner - radius * static_cast<float>(std::tan(k * kPiD / (4.0 * segments))));
    stops.push_back(-inner);
    stops.push_back(inner);
    for (int k = 1; k <= segments; ++k)
        stops.push_back(inner + radius * static_cast<float>(std::tan(k * kPiD / (4.0 * segments))));
    return stops;
}

// How far a rounded box's facets lie inside its ideal surface (the inner box grown by `radius`): each
// triangle's vertices are inner-box points plus radius times their normals, and every point of the triangle
// is at least radius * min_i(n_i . u) from that centre along u, the mean of the normals, so the triangle
// sits at most radius * (1 - min_i n_i . u) inside the rounding (and the rounding over it as far outside).
float rounded_facet_deviation(const Mesh& mesh, float radius) {
    float worst = 0.0f;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const vec3 n[3] = {mesh.vertices[mesh.indices[i]].normal, mesh.vertices[mesh.indices[i + 1]].normal,
                           mesh.vertices[mesh.indices[i + 2]].normal};
        const vec3 sum = n[0] + n[1] + n[2];
        const float len = glm::length(sum);
        if (len <= 0.0f) continue;
        const vec3 u = sum / len;
        const float least = std::min({glm::dot(n[0], u), glm::dot(n[1], u), glm::dot(n[2], u)});
        worst = std::max(worst, radius * (1.0f - least));
    }
    return worst;
}

Mesh build_rounded_box(vec3 size, float radius, int segments, float uv_scale, UvMode mode) {
    const vec3 half = size * 0.5f;
    const vec3 inner = half - vec3(radius);
    Mesh mesh;
    for (const Face& f : kFaces) {
        const float ha = glm::dot(glm::abs(f.a), half), hb = glm::dot(glm::abs(f.b), half);
        const float ia = glm::dot(glm::abs(f.a), inner), ib = glm::dot(glm::abs(f.b), inner);
        const float hn = glm::dot(glm::abs(f.n), half);
        const std::vector<float> sa = face_stops(ha, ia, radius, segments),
                                 sb = face_stops(hb, ib, radius, segments);
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (float b : sb)
            for (float a : sa) {
                const vec3 p = f.n * hn + f.a * a + f.b * b;
                const vec3 c = glm::clamp(p, -inner, inner);
                const vec3 d = p - c;
                Vertex v;
                v.normal = radius > 0.0f && glm::dot(d, d) > 0.0f ? glm::normalize(d) : f.n;
                v.position = radius > 0.0f ? c + v.normal * radius : p;
                const float pa = glm::dot(v.position, f.a), pb = glm::dot(v.position, f.b);
                v.uv = mode == UvMode::World ? vec2(pa, -pb) * uv_scale
                                             : vec2((pa + ha) / (2.0f * ha), 1.0f - (pb + hb) / (2.0f * hb));
                mesh.add(v);
            }
        const auto na = static_cast<std::uint32_t>(sa.size()), nb = static_cast<std::uint32_t>(sb.size());
        for (std::uint32_t j = 0; j + 1 < nb; ++j)
            for (std::uint32_t i = 0; i + 1 < na; ++i) {
                const std::uint32_t v00 = first + j * na + i, v10 = v00 + 1, v01 = v00 + na, v11 = v01 + 1;
                mesh.triangle(v00, v10, v11);
                mesh.triangle(v00, v11, v01);
            }
    }
    mesh.compute_tangents();
    return mesh;
}
} // namespace

const Detail& current_detail() {
    return g_detail;
}

DetailScope::DetailScope(const Detail& detail) : previous_(g_detail) {
    g_detail = detail;
}

DetailScope::~DetailScope() {
    g_detail = previous_;
}

Mesh rounded_box(vec3 size, float radius, int segments, float uv_scale, UvMode mode) {
    const vec3 half = size * 0.5f;
    radius = std::clamp(radius, 0.0f, std::min({half.x, half.y, half.z}) * 0.98f);
    const float budget = g_detail.tolerance;
    if (radius <= 0.0f || segments <= 0 || budget <= 0.0f)
        return build_rounded_box(size, radius, segments, uv_scale, mode);
    const float full =
        rounded_facet_deviation(build_rounded_box(size, radius, segments, uv_scale, mode), radius);
    for (int steps = 0; steps < segments; ++steps) {
        // Sharp edges (no steps): the box's corners stand (sqrt 3 - 1) radius off the rounding, the farthest
        // apart the two surfaces come; faces keep their planar texture mapping.
        Mesh mesh = build_rounded_box(size, steps == 0 ? 0.0f : radius, steps, uv_scale, mode);
        const float own =
            steps == 0 ? radius * (std::sqrt(3.0f) - 1.0f) : rounded_facet_deviation(mesh, radius);
        if (own + full <= budget) {
            mesh.deviation = own + full;
            return mesh;
        }
    }
    return build_rounded_box(size, radius, segments, uv_scale, mode);
}

namespace {
// lathe() with at most `budget` of deviation to spend on fewer segments around the axis.
Mesh lathe_within(const std::vector<vec2>& profile, const LatheOptions& o, double budget) {
    Mesh mesh;
    if (profile.size() < 2) return mesh;
    float widest = 0.0f;
    for (const vec2& p : profile) widest = std::max(widest, p.x);
    const int designed = std::max(3, o.segments);
    const int segs = segments_within(designed, widest, budget);
    float y_top = profile[0].y;
    for (const vec2& p : profile) y_top = std::max(y_top, p.y);

    std::vector<vec2> seg_normal;
    std::vector<float> arc(profile.size(), 0.0f);
    for (size_t k = 0; k + 1 < profile.size(); ++k) {
        const vec2 d = profile[k + 1] - profile[k];
        const float len = glm::length(d);
        seg_normal.push_back(len > 0.0f ? vec2(d.y, -d.x) / len : vec2(1, 0));
        arc[k + 1] = arc[k] + len;
    }
    const float cos_crease = static_cast<float>(std::cos(o.crease_degrees * kPiD / 180.0));
    auto point_normal = [&](size_t point, size_t seg) {
        // The normal at `point` as seen from segment `seg`: averaged with the neighbour unless creased.
        const size_t other = point == seg ? seg - 1 : seg + 1;
        if ((point == seg && seg == 0) || other >= seg_normal.size()) return seg_normal[seg];
        if (glm::dot(seg_normal[seg], seg_normal[other]) < cos_crease) return seg_normal[seg];
        return glm::normalize(seg_normal[seg] + seg_normal[other]);
    };
    for (size_t k = 0; k + 1 < profile.size(); ++k) {
        if (profile[k] == profile[k + 1]) continue;
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (size_t end = 0; end < 2; ++end) {
            const size_t pi = k + end;
            const vec2 p = profile[pi], n2 = point_normal(pi, k);
            for (int j = 0; j <= segs; ++j) {
                const double angle = 2.0 * kPiD * j / segs;
                const float s = dsin(angle), c = dcos(angle);
                Vertex v;
                v.position = vec3(p.x * s, p.y, p.x * c);
                v.normal = glm::normalize(vec3(n2.x * s, n2.y, n2.x * c));
                const float v_coord = o.v_by_height ? (y_top - p.y) * o.v_scale : -arc[pi] * o.v_scale;
                v.uv = vec2(static_cast<float>(j) / static_cast<float>(segs) * o.u_repeats, v_coord);
                mesh.add(v);
            }
        }
        const auto ring = static_cast<std::uint32_t>(segs + 1);
        for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(segs); ++j) {
            const std::uint32_t a = first + j, b = first + j + 1, c = first + ring + j + 1,
                                d = first + ring + j;
            if (profile[k].x > 0.0f) mesh.triangle(a, b, c);
            if (profile[k + 1].x > 0.0f) mesh.triangle(a, c, d);
        }
    }
    mesh.compute_tangents();
    // Each quad between two rings is planar, so a point at angle phi and profile radius r lies at r * f(phi)
    // from the axis, f the polygon's radial factor (between cos(pi / segments) and 1) at either detail: the
    // two surfaces differ by at most the coarser polygon's sag at the widest radius.
    if (segs < designed) mesh.deviation = chord_sag(widest, 2.0 * kPiD / segs);
    return mesh;
}
} // namespace

Mesh lathe(const std::vector<vec2>& profile, const LatheOptions& o) {
    return lathe_within(profile, o, g_detail.tolerance);
}

Mesh cylinder(float radius, float height, int segments, float bevel, LatheOptions o) {
    o.segments = segments;
    bevel = std::clamp(bevel, 0.0f, std::min(radius, height * 0.5f) * 0.9f);
    double budget = g_detail.tolerance;
    // Without its rim bevels the profile's corners stand bevel / sqrt 2 off the chamfers (the wall's texture,
    // mapped by arc length, slides by (sqrt 2 - 1) bevel, less): dropped when that is at most half the
    // budget.
    const float bevel_deviation = bevel / std::sqrt(2.0f);
    const bool drop_bevel = bevel > 0.0f && budget > 0.0 && bevel_deviation <= 0.5 * budget;
    if (drop_bevel) {
        budget -= bevel_deviation;
        bevel = 0.0f;
    }
    std::vector<vec2> profile = {{0, 0}};
    if (bevel > 0.0f) {
        profile.insert(
            profile.end(),
            {{radius - bevel, 0}, {radius, bevel}, {radius, height - bevel}, {radius - bevel, height}});
    } else {
        profile.insert(profile.end(), {{radius, 0}, {radius, height}});
    }
    profile.push_back({0, height});
    Mesh mesh = lathe_within(profile, o, budget);
    if (drop_bevel) mesh.deviation += bevel_deviation;
    return mesh;
}

Mesh tube(float outer, float inner, float height, int segments, LatheOptions o) {
    o.segments = segments;
    if (inner <= 0.0f) return lathe({{outer, 0}, {outer, height}}, o);
    // Outer wall up, top rim inward, inner wall down (facing the axis), bottom rim outward.
    return lathe({{outer, 0}, {outer, height}, {inner, height}, {inner, 0}, {outer, 0}}, o);
}

Mesh capsule(float radius, float height, int segments, int cap_rings) {
    const int designed_rings = std::max(1, cap_rings);
    // Half the budget for the caps' arcs (each within its chords' sag of the circle), the rest around.
    cap_rings = arc_steps_within(designed_rings, radius, 0.5 * kPiD, 0.5 * g_detail.tolerance);
    const float arc_deviation =
        cap_rings < designed_rings
            ? chord_sag(radius, 0.5 * kPiD / cap_rings) + chord_sag(radius, 0.5 * kPiD / designed_rings)
            : 0.0f;
    std::vector<vec2> profile;
    const float straight = std::max(0.0f, height - 2.0f * radius);
    for (int i = 0; i <= cap_rings; ++i) {
        const double a = -kPiD / 2 + (kPiD / 2) * i / cap_rings;
        profile.push_back({radius * dcos(a), radius + radius * dsin(a)});
    }
    for (int i = 0; i <= cap_rings; ++i) {
        const double a = (kPiD / 2) * i / cap_rings;
        profile.push_back({radius * dcos(a), radius + straight + radius * dsin(a)});
    }
    profile.front().x = 0.0f;
    profile.back().x = 0.0f;
    LatheOptions o;
    o.segments = segments;
    Mesh mesh = lathe_within(profile, o, g_detail.tolerance - arc_deviation);
    mesh.deviation += arc_deviation;
    return mesh;
}

Mesh torus(float major_radius, float minor_radius, int segments, int rings) {
    const int designed_rings = std::max(3, rings);
    rings = std::max(3, arc_steps_within(designed_rings, minor_radius, 2.0 * kPiD, 0.5 * g_detail.tolerance));
    const float arc_deviation = rings < designed_rings
                                    ? chord_sag(minor_radius, 2.0 * kPiD / rings) +
                                          chord_sag(minor_radius, 2.0 * kPiD / designed_rings)
                                    : 0.0f;
    std::vector<vec2> profile;
    for (int i = 0; i <= rings; ++i) {
        const double a = -kPiD / 2 + 2.0 * kPiD * i / rings;
        profile.push_back({major_radius + minor_radius * dcos(a), minor_radius * dsin(a)});
    }
    LatheOptions o;
    o.segments = segments;
    o.crease_degrees = 80.0f;
    Mesh mesh = lathe_within(profile, o, g_detail.tolerance - arc_deviation);
    mesh.deviation += arc_deviation;
    return mesh;
}

Mesh frustum(float r0, float r1, float height, int segments, LatheOptions o) {
    o.segments = segments;
    return lathe({{0, 0}, {r0, 0}, {r1, height}, {0, height}}, o);
}

namespace {
float cross2(vec2 a, vec2 b) {
    return a.x * b.y - a.y * b.x;
}

// Ear clipping for a simple counter-clockwise polygon.
std::vector<std::uint32_t> triangulate(const std::vector<vec2>& pts) {
    std::vector<std::uint32_t> out, idx(pts.size());
    for (std::uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
    size_t guard = 0;
    while (idx.size() > 3 && guard++ < pts.size() * pts.size()) {
        bool clipped = false;
        for (size_t i = 0; i < idx.size(); ++i) {
            const std::uint32_t ia = idx[(i + idx.size() - 1) % idx.size()], ib = idx[i],
                                ic = idx[(i + 1) % idx.size()];
            const vec2 a = pts[ia], b = pts[ib], c = pts[ic];
            if (cross2(b - a, c - b) <= 0.0f) continue; // reflex corner
            bool contains = false;
            for (std::uint32_t k : idx) {
                if (k == ia || k == ib || k == ic) continue;
                const vec2 p = pts[k];
                if (cross2(b - a, p - a) > 0 && cross2(c - b, p - b) > 0 && cross2(a - c, p - c) > 0) {
                    contains = true;
                    break;
                }
            }
            if (contains) continue;
            out.insert(out.end(), {ia, ib, ic});
            idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
            break;
        }
        if (!clipped) break; // not simple: leave the rest as a fan below
    }
    for (size_t i = 1; i + 1 < idx.size(); ++i) out.insert(out.end(), {idx[0], idx[i], idx[i + 1]});
    return out;
}
} // namespace

Mesh extrude(const std::vector<vec2>& outline, float depth, float uv_scale) {
    Mesh mesh;
    if (outline.size() < 3) return mesh;
    const float hz = depth * 0.5f;
    const std::vector<std::uint32_t> tris = triangulate(outline);
    for (int side = 0; side < 2; ++side) {
        const float z = side == 0 ? hz : -hz;
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (const vec2& p : outline) {
            Vertex v;
            v.position = vec3(p, z);
            v.normal = vec3(0, 0, side == 0 ? 1.0f : -1.0f);
            v.uv = vec2(side == 0 ? p.x : -p.x, -p.y) * uv_scale;
            mesh.add(v);
        }
        for (size_t i = 0; i + 2 < tris.size(); i += 3) {
            if (side == 0)
                mesh.triangle(first + tris[i], first + tris[i + 1], first + tris[i + 2]);
            else
                mesh.triangle(first + tris[i], first + tris[i + 2], first + tris[i + 1]);
        }
    }
    float u = 0.0f;
    for (size_t i = 0; i < outline.size(); ++i) {
        const vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        const float len = glm::length(b - a);
        if (len <= 0.0f) continue;
        const vec3 n = glm::normalize(vec3(b.y - a.y, a.x - b.x, 0.0f));
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        const vec3 corners[4] = {{a, -hz}, {b, -hz}, {b, hz}, {a, hz}};
        const vec2 uvs[4] = {{u, hz}, {u + len, hz}, {u + len, -hz}, {u, -hz}};
        for (int k = 0; k < 4; ++k) mesh.add(Vertex{corners[k], n, vec4(1, 0, 0, 1), uvs[k] * uv_scale});
        // Outward for a counter-clockwise outline: a(-z) -> b(-z) -> b(+z).
        mesh.triangle(first, first + 1, first + 2);
        mesh.triangle(first, first + 2, first + 3);
        u += len;
    }
    mesh.compute_tangents();
    return mesh;
}

} // namespace ks::assetgen
