// The brush mesher (render/brush_mesh.h), without GL: triangles per face, normals, texture coordinates and
// tangents, material ranges, and a box brush drawn exactly like a wall box.
#include "brush/brush_build.h"
#include "brush/texture_mapping.h"
#include "level/level.h"
#include "render/brush_mesh.h"
#include "render/level_scene.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>

using namespace ks;
using namespace ks::render;

namespace {
// A ramp: a right-triangle profile in the yz plane (rising toward -z) swept 4 units along +x.
brush::Brush ramp(const brush::FaceAttributes& attributes) {
    const DVec3 profile[] = {{0, 0, 0}, {0, 0, -8}, {0, 4, -8}};
    auto b = brush::make_extrusion(profile, {4, 0, 0}, attributes);
    REQUIRE(b.ok());
    return *b;
}

// Texture coordinates at a point of face `f` of the mesh, interpolated from the triangle holding it.
std::size_t first_vertex(const MeshData& mesh, std::size_t polygon) {
    std::size_t v = 0;
    for (std::size_t i = 0; i < polygon; ++i) v += mesh.polygon_sizes[i];
    return v;
}

float triangle_area(const MeshData& m, std::size_t i) {
    const Vec3 a = m.vertices[m.indices[i]].position, b = m.vertices[m.indices[i + 1]].position,
               c = m.vertices[m.indices[i + 2]].position;
    return 0.5f * glm::length(glm::cross(b - a, c - a));
}
} // namespace

TEST_CASE("brush mesh: a fan per face, normals the face planes', counter-clockwise from outside") {
    brush::FaceAttributes at;
    at.material = "concrete";
    at.scale = {4.0, 4.0};
    const brush::Brush b = ramp(at);
    const BrushMesh out = build_brush_mesh(b);
    REQUIRE(out.mesh.polygon_sizes.size() == b.faces().size());
    REQUIRE(out.mesh.solid_sizes == std::vector<std::uint32_t>{static_cast<std::uint32_t>(b.faces().size())});
    std::size_t triangles = 0;
    for (const auto& poly : b.polygons()) triangles += poly.size() - 2;
    CHECK(triangles == 8); // two triangles (the profile's ends) and three quads
    CHECK(out.mesh.indices.size() == 3 * triangles);
    // Each polygon's vertices carry one face's normal; its triangles wind counter-clockwise around it.
    for (std::size_t p = 0, v = 0; p < out.mesh.polygon_sizes.size(); v += out.mesh.polygon_sizes[p], ++p) {
        const Vec3 n = out.mesh.vertices[v].normal;
        bool found = false;
        for (const auto& f : b.faces()) found = found || glm::length(Vec3(f.plane.normal) - n) < 1e-6f;
        CHECK(found);
        for (std::size_t k = 0; k < out.mesh.polygon_sizes[p]; ++k)
            CHECK(glm::length(out.mesh.vertices[v + k].normal - n) < 1e-6f);
    }
    for (std::size_t i = 0; i < out.mesh.indices.size(); i += 3) {
        const Vertex& a = out.mesh.vertices[out.mesh.indices[i]];
        const Vec3 n = glm::cross(out.mesh.vertices[out.mesh.indices[i + 1]].position - a.position,
                                  out.mesh.vertices[out.mesh.indices[i + 2]].position - a.position);
        CHECK(glm::dot(n, a.normal) > 0.0f);
    }
    float area = 0.0f;
    for (std::size_t i = 0; i < out.mesh.indices.size(); i += 3) area += triangle_area(out.mesh, i);
    // Two 4 x 8 x 4 triangles' ends, the 8 x 4 floor, the 4 x 4 back, the sqrt(80) x 4 slope.
    CHECK(area == doctest::Approx(2 * 16.0 + 32.0 + 16.0 + 4.0 * std::sqrt(80.0)).epsilon(1e-5));
}

TEST_CASE("brush mesh: UVs are the face's mapping, continuous over the face, tangents along +u") {
    brush::FaceAttributes at;
    at.material = "metal";
    at.scale = {2.5, -1.5}; // a negative scale mirrors: the bitangent flips
    at.offset = {0.25, 0.75};
    at.rotation_degrees = 30.0;
    const brush::Brush b = ramp(at);
    const BrushMesh out = build_brush_mesh(b);
    for (std::size_t i = 0; i < out.mesh.indices.size(); i += 3) {
        const Vertex* t[3] = {&out.mesh.vertices[out.mesh.indices[i]],
                              &out.mesh.vertices[out.mesh.indices[i + 1]],
                              &out.mesh.vertices[out.mesh.indices[i + 2]]};
        const int face =
            b.find_face({DVec3(t[0]->normal), glm::dot(DVec3(t[0]->normal), DVec3(t[0]->position))});
        REQUIRE(face >= 0);
        const brush::Face& f = b.faces()[static_cast<std::size_t>(face)];
        // Interpolated anywhere inside the triangle, the UV is the face's mapping there: no seam between a
        // face's triangles, no stretch.
        for (const Vec3 w : {Vec3(1.0f / 3), Vec3(0.6f, 0.3f, 0.1f), Vec3(0.05f, 0.05f, 0.9f)}) {
            const Vec3 p = t[0]->position * w.x + t[1]->position * w.y + t[2]->position * w.z;
            const Vec2 uv = t[0]->uv * w.x + t[1]->uv * w.y + t[2]->uv * w.z;
            const glm::dvec2 expected = brush::texture_coordinates(f, DVec3(p));
            CHECK(std::abs(uv.x - expected.x) < 1e-5);
            CHECK(std::abs(uv.y - expected.y) < 1e-5);
        }
        // The tangent points where u grows, the signed bitangent where v grows.
        const Vec3 tangent(t[0]->tangent), bitangent = glm::cross(t[0]->normal, tangent) * t[0]->tangent.w;
        const glm::dvec2 at_p = brush::texture_coordinates(f, DVec3(t[0]->position));
        const glm::dvec2 along_t = brush::texture_coordinates(f, DVec3(t[0]->position + tangent));
        const glm::dvec2 along_b = brush::texture_coordinates(f, DVec3(t[0]->position + bitangent));
        CHECK(along_t.x - at_p.x == doctest::Approx(1.0 / 2.5).epsilon(1e-5));
        CHECK(std::abs(along_t.y - at_p.y) < 1e-5);
        CHECK(along_b.y - at_p.y == doctest::Approx(1.0 / 1.5).epsilon(1e-5));
        CHECK(std::abs(along_b.x - at_p.x) < 1e-5);
    }
}

TEST_CASE("brush mesh: faces grouped by material, each range a mesh of its own") {
    brush::FaceAttributes a, c;
    a.material = "concrete";
    c.material = "metal";
    auto box = brush::make_box({0, 0, 0}, {2, 3, 4}, a);
    REQUIRE(box.ok());
    std::vector<brush::Face> faces = box->faces();
    faces[1].attributes = c; // +x
    faces[3].attributes = c; // +y
    auto mixed = brush::Brush::from_faces(faces);
    REQUIRE(mixed.ok());
    const BrushMesh out = build_brush_mesh(*mixed);
    REQUIRE(out.materials.size() == 2);
    CHECK(out.materials[0].material == "concrete");
    CHECK(out.materials[0].first_polygon == 0);
    CHECK(out.materials[0].polygon_count == 4);
    CHECK(out.materials[1].material == "metal");
    CHECK(out.materials[1].first_polygon == 4);
    CHECK(out.materials[1].polygon_count == 2);
    const MeshData metal = polygon_range(out.mesh, 4, 2);
    CHECK(metal.vertices.size() == 8);
    CHECK(metal.indices.size() == 12);
    CHECK(metal.solid_sizes.empty());
    for (const Vertex& v : metal.vertices) CHECK((v.normal == Vec3(1, 0, 0) || v.normal == Vec3(0, 1, 0)));
    // The ranges cover the mesh: the same vertices in the same order.
    const MeshData concrete = polygon_range(out.mesh, 0, 4);
    REQUIRE(concrete.vertices.size() + metal.vertices.size() == out.mesh.vertices.size());
    CHECK(concrete.vertices.back().position == out.mesh.vertices[first_vertex(out.mesh, 3) + 3].position);
    CHECK(metal.vertices.front().position == out.mesh.vertices[first_vertex(out.mesh, 4)].position);
}

TEST_CASE("brush mesh: a box brush is a wall's box, to 1e-5 (positions, normals, UVs, tangents, triangles)") {
    // Walls turned by multiples of 90 degrees (the other turns project a wall's UVs on a world axis; the
    // brush projects on the face plane, which is what a brush keeps under texture lock).
    for (int quarter_turns = 0; quarter_turns < 4; ++quarter_turns) {
        const float yaw = 0.5f * kPi * static_cast<float>(quarter_turns);
        const Vec3 position(3.5f, 0.0f, -7.25f), size(12.0f, 16.0f, 0.5f);
        const float texture_scale = 5.0f;
        MeshData wall;
        const Mat4 frame = glm::rotate(glm::translate(Mat4(1.0f), position), yaw, Vec3(0, 1, 0));
        append_box(wall, Vec3(0, size.y * 0.5f, 0), size, frame, texture_scale);

        brush::FaceAttributes at;
        at.scale = {texture_scale, texture_scale};
        auto local = brush::make_box(-DVec3(size) * 0.5 + DVec3(0, size.y * 0.5, 0),
                                     DVec3(size) * 0.5 + DVec3(0, size.y * 0.5, 0), at);
        REQUIRE(local.ok());
        // Placed like the wall, with its faces' attributes as they are (no lock: the mapping is the world's).
        const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), double(yaw), DVec3(0, 1, 0)));
        auto placed = brush::transformed(*local, turn, DVec3(position), brush::TextureLock::off);
        REQUIRE(placed.ok());
        const MeshData brush_mesh = build_brush_mesh(*placed).mesh;

        CHECK(brush_mesh.indices.size() == wall.indices.size());
        REQUIRE(brush_mesh.polygon_sizes.size() == wall.polygon_sizes.size());
        int matched = 0;
        for (std::size_t p = 0; p < wall.polygon_sizes.size(); ++p) {
            const std::size_t wv = first_vertex(wall, p);
            for (std::size_t q = 0; q < brush_mesh.polygon_sizes.size(); ++q) {
                const std::size_t bv = first_vertex(brush_mesh, q);
                if (glm::length(brush_mesh.vertices[bv].normal - wall.vertices[wv].normal) > 1e-5f) continue;
                ++matched;
                // Every corner of the wall's face is a corner of the brush's with the same attributes.
                for (std::size_t i = 0; i < 4; ++i) {
                    const Vertex& w = wall.vertices[wv + i];
                    const Vertex* same = nullptr;
                    for (std::size_t k = 0; k < brush_mesh.polygon_sizes[q]; ++k)
                        if (glm::length(brush_mesh.vertices[bv + k].position - w.position) < 1e-5f)
                            same = &brush_mesh.vertices[bv + k];
                    REQUIRE(same != nullptr);
                    CHECK(glm::length(same->uv - w.uv) < 1e-5f);
                    CHECK(glm::length(same->tangent - w.tangent) < 1e-5f);
                }
            }
        }
        CHECK(matched == 6);
    }
}

TEST_CASE("brush mesh: the level's box walls give the same mesh through the brush mesher") {
    level::Entity e;
    e.position = Vec3(10, 0, -4);
    e.rotation = Vec3(90, 0, 0);
    level::WallProps wall;
    wall.size = Vec3(20, 16, 0.5f);
    wall.texture_scale = 4.0f;
    e.props = wall;
    const MeshData today = build_surface_mesh(e);
    REQUIRE(today.vertices.size() == 24);
    float area_today = 0.0f;
    for (std::size_t i = 0; i < today.indices.size(); i += 3) area_today += triangle_area(today, i);
    // The wall's solid as a box brush with the wall's scale on every face.
    brush::FaceAttributes at;
    at.scale = {4.0, 4.0};
    const geometry::Aabb box = today.bounds();
    auto b = brush::make_box(DVec3(box.min), DVec3(box.max), at);
    REQUIRE(b.ok());
    const MeshData mesh = build_brush_mesh(*b).mesh;
    float area = 0.0f;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) area += triangle_area(mesh, i);
    CHECK(area == doctest::Approx(area_today).epsilon(1e-6));
    for (const Vertex& v : today.vertices) {
        bool same = false;
        for (const Vertex& w : mesh.vertices)
            same = same || (glm::length(w.position - v.position) < 1e-5f &&
                            glm::length(w.normal - v.normal) < 1e-5f && glm::length(w.uv - v.uv) < 1e-5f &&
                            glm::length(w.tangent - v.tangent) < 1e-5f);
        CHECK(same);
    }
}

TEST_CASE("brush mesh: building time per brush") {
    brush::FaceAttributes at;
    at.material = "concrete";
    const brush::Brush b = ramp(at);
    const int n = 2000;
    std::size_t vertices = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) vertices += build_brush_mesh(b).mesh.vertices.size();
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / n;
    MESSAGE("brush mesh of a 5-face ramp: " << us << " us");
    CHECK(vertices == static_cast<std::size_t>(n) * 18);
}
