#include "render/brush_mesh.h"

#include "brush/texture_mapping.h"

#include <algorithm>

namespace ks::render {

namespace {
// A face's tangent points where its u coordinate grows and its bitangent where v grows (OpenGL normal
// maps): along the texture axes, flipped by a negative scale; w is the bitangent's handedness.
Vec4 face_tangent(const brush::Face& face) {
    const brush::TextureAxes axes = brush::texture_axes(face);
    const DVec3 t = axes.u * (face.attributes.scale.x < 0.0 ? -1.0 : 1.0);
    const DVec3 b = axes.v * (face.attributes.scale.y < 0.0 ? -1.0 : 1.0);
    const double handed = glm::dot(glm::cross(face.plane.normal, t), b) < 0.0 ? -1.0 : 1.0;
    return Vec4(Vec3(t), static_cast<float>(handed));
}

void append_face(MeshData& mesh, const brush::Brush& brush, std::size_t face_index,
                 std::vector<Vertex>& scratch) {
    const brush::Face& face = brush.faces()[face_index];
    const Vec3 normal(face.plane.normal);
    const Vec4 tangent = face_tangent(face);
    scratch.clear();
    for (int corner : brush.polygons()[face_index]) {
        const DVec3& p = brush.vertices()[static_cast<std::size_t>(corner)];
        Vertex v;
        v.position = Vec3(p);
        v.normal = normal;
        v.uv = Vec2(brush::texture_coordinates(face, p));
        v.tangent = tangent;
        scratch.push_back(v);
    }
    append_polygon(mesh, scratch);
}
} // namespace

BrushMesh build_brush_mesh(const brush::Brush& brush) {
    BrushMesh out;
    std::vector<std::size_t> order(brush.faces().size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    // Each material's faces together, materials in order of their first face, faces in brush order.
    std::vector<std::string> first_seen;
    for (const auto& f : brush.faces())
        if (std::find(first_seen.begin(), first_seen.end(), f.attributes.material) == first_seen.end())
            first_seen.push_back(f.attributes.material);
    auto rank = [&](std::size_t i) {
        return std::find(first_seen.begin(), first_seen.end(), brush.faces()[i].attributes.material) -
               first_seen.begin();
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
    std::vector<Vertex> scratch;
    for (std::size_t i : order) {
        const std::string& material = brush.faces()[i].attributes.material;
        if (out.materials.empty() || out.materials.back().material != material)
            out.materials.push_back({material, static_cast<std::uint32_t>(out.mesh.polygon_sizes.size()), 0});
        append_face(out.mesh, brush, i, scratch);
        ++out.materials.back().polygon_count;
    }
    out.mesh.solid_sizes.push_back(static_cast<std::uint32_t>(out.mesh.polygon_sizes.size()));
    return out;
}

Result<brush::Brush> placed_box_brush(const Vec3& local_centre, const Vec3& half,
                                      const geometry::Transform& frame, float world_per_repeat) {
    const glm::dquat q = glm::normalize(glm::dquat(frame.rotation));
    const glm::dmat3 turn = glm::mat3_cast(q);
    const DVec3 centre = DVec3(frame.position) + turn * DVec3(local_centre);
    brush::FaceAttributes attributes;
    attributes.scale = glm::dvec2(std::max(static_cast<double>(world_per_repeat), 1e-4));
    std::vector<brush::Face> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {1.0, -1.0}) {
            const DVec3 normal = turn[axis] * side;
            faces.push_back(
                {{normal, glm::dot(normal, centre) + static_cast<double>(half[axis])}, attributes});
        }
    return brush::Brush::from_faces(std::move(faces));
}

MeshData polygon_range(const MeshData& mesh, std::uint32_t first_polygon, std::uint32_t polygon_count) {
    MeshData out;
    std::size_t vertex = 0;
    for (std::uint32_t i = 0; i < first_polygon && i < mesh.polygon_sizes.size(); ++i)
        vertex += mesh.polygon_sizes[i];
    std::vector<Vertex> polygon;
    const std::size_t end =
        std::min<std::size_t>(mesh.polygon_sizes.size(), std::size_t(first_polygon) + polygon_count);
    for (std::size_t i = first_polygon; i < end; ++i) {
        const std::size_t n = mesh.polygon_sizes[i];
        polygon.assign(mesh.vertices.begin() + static_cast<std::ptrdiff_t>(vertex),
                       mesh.vertices.begin() + static_cast<std::ptrdiff_t>(vertex + n));
        append_polygon(out, polygon);
        vertex += n;
    }
    return out;
}

} // namespace ks::render
