#include "render/mesh_data.h"

#include <algorithm>

namespace ks::render {

geometry::Aabb MeshData::bounds() const {
    geometry::Aabb box = geometry::Aabb::empty();
    for (const auto& v : vertices) box = geometry::merge(box, {v.position, v.position});
    return box;
}

void append_polygon(MeshData& mesh, const std::vector<Vertex>& polygon) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), polygon.begin(), polygon.end());
    for (std::uint32_t i = 2; i < polygon.size(); ++i)
        mesh.indices.insert(mesh.indices.end(), {base, base + i - 1, base + i});
    mesh.polygon_sizes.push_back(static_cast<std::uint32_t>(polygon.size()));
}

void append_mesh(MeshData& mesh, const MeshData& more) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), more.vertices.begin(), more.vertices.end());
    for (std::uint32_t i : more.indices) mesh.indices.push_back(base + i);
    mesh.polygon_sizes.insert(mesh.polygon_sizes.end(), more.polygon_sizes.begin(), more.polygon_sizes.end());
    mesh.solid_sizes.insert(mesh.solid_sizes.end(), more.solid_sizes.begin(), more.solid_sizes.end());
}

namespace {
struct BoxFaceAxes {
    Vec3 normal, u, v; // outward normal and the two in-plane axes (u x v = normal)
};
constexpr BoxFaceAxes kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
};

// Picks the world axes a face's UVs follow: the face's world normal decides which plane it projects on.
void world_uv_axes(const Vec3& n, Vec3& u_axis, Vec3& v_axis) {
    Vec3 a = glm::abs(n);
    if (a.y >= a.x && a.y >= a.z) {
        u_axis = {1, 0, 0};
        v_axis = {0, 0, n.y > 0 ? -1.0f : 1.0f};
    } else if (a.x >= a.z) {
        u_axis = {0, 0, n.x > 0 ? -1.0f : 1.0f};
        v_axis = {0, 1, 0};
    } else {
        u_axis = {n.z > 0 ? 1.0f : -1.0f, 0, 0};
        v_axis = {0, 1, 0};
    }
}
} // namespace

void append_box(MeshData& mesh, const Vec3& center, const Vec3& size, const Mat4& to_world,
                float world_per_repeat) {
    const float inv_repeat = 1.0f / std::max(world_per_repeat, 1e-4f);
    const Mat3 normal_m = glm::transpose(glm::inverse(Mat3(to_world)));
    const Vec3 half = size * 0.5f;
    for (const BoxFaceAxes& f : kFaces) {
        auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        Vec3 wn = glm::normalize(normal_m * f.normal);
        Vec3 u_axis, v_axis;
        world_uv_axes(wn, u_axis, v_axis);
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            Vec3 p = center + half * (f.normal + c[0] * f.u + c[1] * f.v);
            Vec3 wp = Vec3(to_world * Vec4(p, 1.0f));
            Vertex vert;
            vert.position = wp;
            vert.normal = wn;
            vert.uv = Vec2(glm::dot(wp, u_axis), glm::dot(wp, v_axis)) * inv_repeat;
            // Tangent follows +u in world space; v grows up so the bitangent is v_axis (OpenGL normal maps).
            float handed = glm::dot(glm::cross(wn, u_axis), v_axis) < 0.0f ? -1.0f : 1.0f;
            vert.tangent = Vec4(u_axis, handed);
            mesh.vertices.push_back(vert);
        }
        // Winding: counter-clockwise seen from outside.
        Vec3 p0 = mesh.vertices[base].position, p1 = mesh.vertices[base + 1].position,
             p2 = mesh.vertices[base + 2].position;
        bool ccw = glm::dot(glm::cross(p1 - p0, p2 - p0), wn) > 0.0f;
        if (ccw)
            mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        else
            mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
        mesh.polygon_sizes.push_back(4);
    }
    mesh.solid_sizes.push_back(6);
}

MeshData unit_cube() {
    MeshData mesh;
    append_box(mesh, Vec3(0.0f), Vec3(1.0f), Mat4(1.0f), 1.0f);
    // World-mapped UVs of a centred unit cube run -0.5..0.5; shift them to 0..1.
    for (auto& v : mesh.vertices) v.uv += Vec2(0.5f);
    return mesh;
}

} // namespace ks::render
