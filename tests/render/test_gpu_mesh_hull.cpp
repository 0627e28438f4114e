// A GPU mesh's convex-hull corners (GpuMesh::hull_corners), read back from its vertex buffer: the outline the
// view model's screen footprint projects. Exact corners for a box with points inside it, far from the origin
// too; the bounds' corners for vertices that span no volume; every vertex inside the corners' hull.
#include "gl_test_support.h"
#include "render/gpu_mesh.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace ks;
using namespace ks::render;

namespace {

MeshData mesh_of(const std::vector<Vec3>& points) {
    MeshData data;
    for (const Vec3& p : points) {
        Vertex v{};
        v.position = p;
        v.normal = Vec3(0, 1, 0);
        data.vertices.push_back(v);
    }
    for (std::uint32_t i = 0; i + 2 < data.vertices.size(); i += 3)
        data.indices.insert(data.indices.end(), {i, i + 1, i + 2});
    return data;
}

bool holds(const std::vector<Vec3>& corners, const Vec3& p) {
    return std::any_of(corners.begin(), corners.end(), [&](const Vec3& c) { return c == p; });
}

} // namespace

TEST_CASE("gpu mesh: hull corners are the outline's, read back from the vertex buffer") {
    REQUIRE_MESSAGE(test::gl_context(), "no display: run the GL tests under xvfb-run (./run.sh test does)");
    for (const Vec3& offset : {Vec3(0.0f), Vec3(1.0e5f, -2.0e5f, 3.0e5f)}) {
        CAPTURE(offset.x);
        std::vector<Vec3> points;
        for (int corner = 0; corner < 8; ++corner)
            points.push_back(offset + Vec3((corner & 1) ? 2.0f : -2.0f, (corner & 2) ? 1.0f : -1.0f,
                                           (corner & 4) ? 0.5f : -0.5f));
        // Points inside and on the faces (a face's centre, an edge's middle) are no corners.
        for (const Vec3& inside :
             {Vec3(0.0f), Vec3(1.0f, 0.5f, 0.25f), Vec3(2.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.5f)})
            points.push_back(offset + inside);
        const GpuMesh mesh(mesh_of(points));
        const std::vector<Vec3>& corners = mesh.hull_corners();
        CHECK(corners.size() == 8);
        for (int corner = 0; corner < 8; ++corner) CHECK(holds(corners, points[static_cast<size_t>(corner)]));
        CHECK(&mesh.hull_corners() == &corners); // made once
    }
    // A flat quad spans no volume: its bounds' 8 corners (4 distinct) stand in.
    const GpuMesh flat(
        mesh_of({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 1)}));
    CHECK(flat.hull_corners().size() == 8);
    // A mesh with no vertices has no outline.
    const GpuMesh empty(MeshData{});
    CHECK(empty.hull_corners().empty());
}
