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
} // namespace

Mesh rounded_box(vec3 size, float radius, int segments, float uv_scale, UvMode mode) {
    const vec3 half = size * 0.5f;
    radius = std::clamp(radius, 0.0f, std::min({half.x, half.y, half.z}) * 0.98f);
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

Mesh lathe(const std::vector<vec2>& profile, const LatheOptions& o) {
    Mesh mesh;
    if (profile.size() < 2) return mesh;
    const int segs = std::max(3, o.segments);
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
    return mesh;
}

Mesh cylinder(float radius, float height, int segments, float bevel, LatheOptions o) {
    o.segments = segments;
    bevel = std::clamp(bevel, 0.0f, std::min(radius, height * 0.5f) * 0.9f);
    std::vector<vec2> profile = {{0, 0}};
    if (bevel > 0.0f) {
        profile.insert(
            profile.end(),
            {{radius - bevel, 0}, {radius, bevel}, {radius, height - bevel}, {radius - bevel, height}});
    } else {
        profile.insert(profile.end(), {{radius, 0}, {radius, height}});
    }
    profile.push_back({0, height});
    return lathe(profile, o);
}

Mesh tube(float outer, float inner, float height, int segments, LatheOptions o) {
    o.segments = segments;
    if (inner <= 0.0f) return lathe({{outer, 0}, {outer, height}}, o);
    // Outer wall up, top rim inward, inner wall down (facing the axis), bottom rim outward.
    return lathe({{outer, 0}, {outer, height}, {inner, height}, {inner, 0}, {outer, 0}}, o);
}

Mesh capsule(float radius, float height, int segments, int cap_rings) {
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
    return lathe(profile, o);
}

Mesh torus(float major_radius, float minor_radius, int segments, int rings) {
    std::vector<vec2> profile;
    for (int i = 0; i <= rings; ++i) {
        const double a = -kPiD / 2 + 2.0 * kPiD * i / rings;
        profile.push_back({major_radius + minor_radius * dcos(a), minor_radius * dsin(a)});
    }
    LatheOptions o;
    o.segments = segments;
    o.crease_degrees = 80.0f;
    return lathe(profile, o);
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
