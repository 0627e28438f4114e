// What a simplified level does beyond moving the surface (modelio/lod_fidelity.h): the texture sliding along
// it and the shading normals bending, on a flat grid where the answers are known, with the hard cases (a
// texture seam, stacked layers, coordinates far from the origin, NaN) and simplify_triangles' error.
#include "modelio/lod_fidelity.h"
#include "modelio/model_lod.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace ks;
using namespace ks::modelio;

namespace {

// An n x n grid of vertices over the unit square at y = 0, texture coordinates = (x, z), normals up.
struct Grid {
    std::vector<Vec3> positions, normals;
    std::vector<Vec2> uvs;
    std::vector<std::uint32_t> indices;
    int n = 0;
    explicit Grid(int side, Vec3 offset = Vec3(0.0f)) : n(side) {
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) {
                const Vec2 t(static_cast<float>(x) / (n - 1), static_cast<float>(z) / (n - 1));
                positions.push_back(offset + Vec3(t.x, 0.0f, t.y));
                normals.emplace_back(0.0f, 1.0f, 0.0f);
                uvs.push_back(t);
            }
        for (int z = 0; z + 1 < n; ++z)
            for (int x = 0; x + 1 < n; ++x) {
                const auto a = static_cast<std::uint32_t>(z * n + x), b = a + 1,
                           c = a + static_cast<std::uint32_t>(n), d = c + 1;
                indices.insert(indices.end(), {a, c, b, b, c, d});
            }
    }
    VertexStreams streams() const {
        VertexStreams v;
        v.positions = positions.data();
        v.normals = normals.data();
        v.uvs = uvs.data();
        v.count = positions.size();
        return v;
    }
    // The square as two triangles over its corners (a grid simplified as far as it goes).
    std::vector<std::uint32_t> corners() const {
        const auto a = 0u, b = static_cast<std::uint32_t>(n - 1), c = static_cast<std::uint32_t>(n * (n - 1)),
                   d = static_cast<std::uint32_t>(n * n - 1);
        return {a, c, b, b, c, d};
    }
    std::uint32_t centre() const { return static_cast<std::uint32_t>((n / 2) * n + n / 2); }
};

} // namespace

TEST_CASE("lod fidelity: the same triangles, or an affine texture on a plane, move and bend nothing") {
    const Grid grid(5);
    const LevelFidelity same =
        measure_level_fidelity(grid.streams(), grid.indices, grid.indices, 1e-4f, 0.26f);
    CHECK(same.texture_shift < 1e-5f);
    CHECK(same.normal_angle < 1e-3f);
    CHECK(same.normal_extent == 0.0f);
    const LevelFidelity flat =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, 0.26f);
    CHECK(flat.texture_shift < 1e-5f);
    CHECK(flat.normal_angle < 1e-3f);
    CHECK(flat.normal_extent == 0.0f);
}

TEST_CASE("lod fidelity: a texture that bends at a removed vertex slides by that vertex's offset") {
    Grid grid(3);
    grid.uvs[grid.centre()] += Vec2(0.2f, 0.0f); // the texture is pulled sideways at the centre only
    const LevelFidelity f =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, 0.26f);
    // One texture unit per position unit: the centre sample sees 0.2 units of slide.
    CHECK(f.texture_shift == doctest::Approx(0.2f).epsilon(0.05));
    CHECK(f.normal_extent == 0.0f);
    // simplify_triangles counts it: its error is at least the slide, though the surface did not move.
    float error = 0.0f;
    const auto level = simplify_triangles(grid.streams(), grid.indices, 0.25f, error);
    REQUIRE(level.size() < grid.indices.size());
    CHECK(error >= 0.15f);
}

TEST_CASE("lod fidelity: normals that bend count as wide as the triangle they bend over") {
    Grid grid(3);
    grid.normals[grid.centre()] = glm::normalize(Vec3(1.0f, 1.0f, 0.0f)); // 45 degrees at the centre
    const LevelFidelity f =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, 0.26f);
    CHECK(f.normal_angle == doctest::Approx(kPi / 4.0f).epsilon(0.02));
    // Each corner triangle: legs 1, hypotenuse sqrt(2): its smallest altitude is 1 / sqrt(2).
    CHECK(f.normal_extent == doctest::Approx(1.0f / std::sqrt(2.0f)).epsilon(0.01));
    // Under the allowed bend it is not an error at all.
    const LevelFidelity loose =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, kPi / 2.0f);
    CHECK(loose.normal_extent == 0.0f);
}

TEST_CASE("lod fidelity hard cases: a texture seam, a layer facing away, far coordinates, NaN") {
    SUBCASE("seam: the right half's vertices doubled with their own coordinates") {
        Grid grid(5);
        // Vertices of column x = 2 doubled; the right half's triangles use the copies, whose texture
        // coordinates jump by 0.5 (a seam: two coordinates at one position).
        std::vector<std::uint32_t> copy(grid.positions.size());
        for (int z = 0; z < grid.n; ++z) {
            const auto i = static_cast<std::uint32_t>(z * grid.n + 2);
            copy[i] = static_cast<std::uint32_t>(grid.positions.size());
            grid.positions.push_back(grid.positions[i]);
            grid.normals.push_back(grid.normals[i]);
            grid.uvs.push_back(grid.uvs[i] + Vec2(0.5f, 0.0f));
        }
        for (int x = 3; x < grid.n; ++x)
            for (int z = 0; z < grid.n; ++z) grid.uvs[static_cast<size_t>(z * grid.n + x)].x += 0.5f;
        for (std::size_t t = 0; t < grid.indices.size(); t += 3) {
            bool right = false;
            for (int k = 0; k < 3; ++k) right |= grid.indices[t + k] % grid.n > 2;
            if (right)
                for (int k = 0; k < 3; ++k)
                    if (grid.indices[t + k] % grid.n == 2) grid.indices[t + k] = copy[grid.indices[t + k]];
        }
        const LevelFidelity f =
            measure_level_fidelity(grid.streams(), grid.indices, grid.indices, 1e-4f, 0.26f);
        CHECK(f.texture_shift < 1e-5f); // samples on the seam take the side that agrees with them
    }
    SUBCASE("a copy of the plane facing down, on top of it") {
        Grid grid(3);
        const auto base = static_cast<std::uint32_t>(grid.positions.size());
        for (std::size_t i = 0; i < grid.n * grid.n; ++i) {
            grid.positions.push_back(grid.positions[i]);
            grid.normals.emplace_back(0.0f, -1.0f, 0.0f);
            grid.uvs.push_back(Vec2(1.0f) - grid.uvs[i]);
        }
        std::vector<std::uint32_t> both = grid.indices;
        for (std::size_t t = 0; t < grid.indices.size(); t += 3) // reversed winding: faces down
            both.insert(both.end(),
                        {grid.indices[t] + base, grid.indices[t + 2] + base, grid.indices[t + 1] + base});
        const LevelFidelity f = measure_level_fidelity(grid.streams(), both, grid.indices, 1e-4f, 0.26f);
        CHECK(f.texture_shift < 1e-5f); // the upward samples match the upward layer, not the other
        CHECK(f.normal_angle < 1e-3f);
    }
    SUBCASE("10 000 units from the origin") {
        const Grid grid(5, Vec3(1e4f, 0.0f, -1e4f));
        const LevelFidelity f =
            measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-3f, 0.26f);
        CHECK(f.texture_shift < 1e-2f); // float spacing there is about 0.001
        CHECK(f.normal_extent == 0.0f);
    }
    SUBCASE("a NaN position makes the level unusable, without a crash") {
        Grid grid(3);
        grid.positions[1].x = std::numeric_limits<float>::quiet_NaN();
        const LevelFidelity f =
            measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, 0.26f);
        CHECK(std::isinf(f.texture_shift));
        CHECK(std::isinf(f.normal_extent));
    }
    SUBCASE("an index past the vertices likewise") {
        const Grid grid(3);
        std::vector<std::uint32_t> bad = grid.corners();
        bad[0] = 1000;
        CHECK(std::isinf(
            measure_level_fidelity(grid.streams(), grid.indices, bad, 1e-4f, 0.26f).texture_shift));
    }
}

TEST_CASE("lod fidelity: a repeated measure gives the same answer to the bit") {
    const Grid grid(9);
    const LevelFidelity a =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, 0.26f);
    const LevelFidelity b =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-4f, 0.26f);
    CHECK(a.texture_shift == b.texture_shift);
    CHECK(a.normal_angle == b.normal_angle);
}

TEST_CASE("lod fidelity: a slide inside a thin triangle counts only as wide as the triangle") {
    Grid grid(3);
    for (Vec3& p : grid.positions) p.z *= 0.01f; // a strip 1 long and 0.01 wide (a rounded edge, say)
    grid.uvs[grid.centre()] += Vec2(5.0f, 0.0f); // a wild slide at its middle
    const LevelFidelity f =
        measure_level_fidelity(grid.streams(), grid.indices, grid.corners(), 1e-5f, 0.26f);
    // Each corner triangle's smallest altitude: 0.01 / sqrt(1 + 0.0001).
    CHECK(f.texture_shift > 0.005f);
    CHECK(f.texture_shift <= 0.0100001f);
}
