#include "model/model_collision_wire.h"

#include "level/model_entity.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_set>

namespace ks::editor {

namespace {

// Every edge once, however many triangles share it: vertices at the same place (a file splits them where
// normals or UVs differ) are one.
void mesh_edges(const level::CollisionMesh& mesh, CollisionWire& wire) {
    std::map<std::array<double, 3>, std::uint32_t> first_at;
    std::vector<std::uint32_t> welded(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const DVec3& v = mesh.vertices[i];
        welded[i] = first_at.try_emplace({v.x, v.y, v.z}, static_cast<std::uint32_t>(i)).first->second;
    }
    std::unordered_set<std::uint64_t> seen;
    for (const auto& triangle : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t p = welded[triangle[static_cast<std::size_t>(k)]],
                                q = welded[triangle[static_cast<std::size_t>((k + 1) % 3)]];
            const std::uint32_t a = std::min(p, q), b = std::max(p, q);
            if (!seen.insert(std::uint64_t{a} << 32 | b).second) continue;
            if (wire.segments.size() == kMaxCollisionWireSegments) {
                wire.truncated = true;
                return;
            }
            wire.segments.push_back(std::array<Vec3, 2>{Vec3(mesh.vertices[a]), Vec3(mesh.vertices[b])});
        }
}

} // namespace

Result<CollisionWire> model_collision_wire(const level::Entity& entity) {
    CollisionWire wire;
    const auto* props = entity.try_as<level::ModelProps>();
    if (!props || props->collision.value == "none") return wire;
    if (props->collision.value == "mesh") {
        Result<std::optional<level::CollisionMesh>> mesh = level::model_mesh_collision(entity);
        if (!mesh) return mesh.error();
        if (*mesh) mesh_edges(**mesh, wire);
        return wire;
    }
    // "box", "hull" or "hulls": the brushes the game collides with.
    Result<std::vector<brush::Brush>> hulls = level::model_collision(entity);
    if (!hulls) return hulls.error();
    for (const brush::Brush& hull : *hulls) {
        const std::vector<DVec3>& corners = hull.vertices();
        for (const brush::Edge& edge : hull.edges())
            wire.segments.push_back(std::array<Vec3, 2>{Vec3(corners[static_cast<std::size_t>(edge.v0)]),
                                                        Vec3(corners[static_cast<std::size_t>(edge.v1)])});
    }
    return wire;
}

} // namespace ks::editor
