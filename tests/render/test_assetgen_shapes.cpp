// The asset generator's shapes at coarser levels of detail (assets/generator/shapes.h: Detail): every shape
// stays within the deviation it states of its full-detail self, measured here by sampling both ways, on hard
// cases (slivers, tiny and huge radii, far from the origin, stretched placements), the bound is not idle, the
// tolerance is kept, and the same shape built twice is the same to the bit. Needs no GL context.
#include "shapes.h"

#include "geometry/closest_on_triangle.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace ks::assetgen {
namespace {

// The largest distance from the samples of `from` (vertices, edge midpoints, centres) to the surface of `to`.
double shape_one_sided(const Mesh& from, const Mesh& to) {
    double worst = 0.0;
    for (std::size_t i = 0; i + 2 < from.indices.size(); i += 3) {
        const glm::dvec3 a(from.vertices[from.indices[i]].position),
            b(from.vertices[from.indices[i + 1]].position), c(from.vertices[from.indices[i + 2]].position);
        for (const glm::dvec3& p :
             {a, b, c, (a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5, (a + b + c) / 3.0}) {
            double best = INFINITY;
            for (std::size_t j = 0; j + 2 < to.indices.size(); j += 3) {
                const glm::dvec3 ta(to.vertices[to.indices[j]].position),
                    tb(to.vertices[to.indices[j + 1]].position), tc(to.vertices[to.indices[j + 2]].position);
                best = std::min(best, glm::length(p - geometry::closest_on_triangle(p, ta, tb, tc).point));
            }
            worst = std::max(worst, best);
        }
    }
    return worst;
}

double shape_distance(const Mesh& a, const Mesh& b) {
    return std::max(shape_one_sided(a, b), shape_one_sided(b, a));
}

struct ShapeCase {
    std::string name;
    std::function<Mesh()> build;
    double size; // the shape's extent, for the float rounding allowed in the comparison
};

std::vector<ShapeCase> shape_cases() {
    return {
        {"rounded box", [] { return rounded_box(vec3(1.0f, 0.6f, 0.8f), 0.1f, 2); }, 1.0},
        {"rounded box, one step", [] { return rounded_box(vec3(0.3f), 0.07f, 1); }, 0.3},
        {"sliver box", [] { return rounded_box(vec3(2.0f, 0.002f, 1.0f), 0.05f, 2); }, 2.0},
        {"huge box, tiny rounding", [] { return rounded_box(vec3(4000.0f, 300.0f, 800.0f), 0.02f, 3); },
         4000.0},
        {"cylinder with bevels", [] { return cylinder(0.3f, 0.5f, 24, 0.04f); }, 0.5},
        {"thin tall cylinder", [] { return cylinder(0.004f, 12.0f, 16, 0.001f); }, 12.0},
        {"wide flat cylinder", [] { return cylinder(900.0f, 0.5f, 64, 0.2f); }, 900.0},
        {"tube", [] { return tube(0.3f, 0.2f, 0.4f, 20); }, 0.4},
        {"capsule", [] { return capsule(0.2f, 1.0f, 16, 6); }, 1.0},
        {"torus", [] { return torus(0.5f, 0.1f, 24, 12); }, 0.6},
        {"frustum", [] { return frustum(0.4f, 0.1f, 0.7f, 24); }, 0.7},
        {"lathe profile",
         [] {
             return lathe({{0.0f, -0.2f},
                           {0.16f, -0.2f},
                           {0.2f, -0.14f},
                           {0.22f, 0.12f},
                           {0.25f, 0.2f},
                           {0.0f, 0.2f}});
         },
         0.5},
    };
}

// The most a placement stretches a vector, by power iteration on its Gram matrix (the reference for
// largest_stretch).
float stretch_by_iteration(const glm::mat3& m) {
    const glm::dmat3 g = glm::transpose(glm::dmat3(m)) * glm::dmat3(m);
    glm::dvec3 v(0.6, 0.7, 0.38);
    for (int i = 0; i < 200; ++i) v = glm::normalize(g * v);
    return static_cast<float>(std::sqrt(glm::dot(v, g * v)));
}

} // namespace

TEST_CASE("each shape at a coarser detail stays within its stated deviation of itself in full") {
    int coarser = 0;
    double lowest = INFINITY, highest = 0.0; // measured / stated
    for (const ShapeCase& c : shape_cases()) {
        CAPTURE(c.name);
        const Mesh full = c.build();
        CHECK(full.deviation == 0.0f);
        for (float fraction : {0.002f, 0.005f, 0.02f, 0.05f, 0.2f}) {
            CAPTURE(fraction);
            const float tolerance = fraction * static_cast<float>(c.size);
            Mesh coarse;
            {
                const DetailScope scope(Detail{tolerance});
                coarse = c.build();
            }
            CHECK(current_detail().tolerance == 0.0f); // the scope put the full detail back
            CHECK(coarse.deviation <= tolerance * 1.0001f);
            CHECK(coarse.triangle_count() <= full.triangle_count());
            if (coarse.triangle_count() == full.triangle_count()) continue;
            ++coarser;
            const double measured = shape_distance(coarse, full);
            // Float vertex data: a few units in the last place of the shape's size.
            CHECK(measured <= coarse.deviation + 4e-7 * c.size);
            CHECK(measured >= 0.4 * coarse.deviation); // the bound is not idle
            lowest = std::min(lowest, measured / coarse.deviation);
            highest = std::max(highest, measured / coarse.deviation);
        }
    }
    MESSAGE(coarser << " coarser shapes; measured distance / stated deviation " << lowest << " .. " << highest);
    CHECK(coarser >= 30);
}

TEST_CASE("a deviation is carried through placements by their largest stretch, far from the origin too") {
    Mesh coarse;
    {
        const DetailScope scope(Detail{0.02f});
        coarse = cylinder(0.3f, 0.5f, 24, 0.04f);
    }
    Mesh full = cylinder(0.3f, 0.5f, 24, 0.04f);
    REQUIRE(coarse.deviation > 0.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> angle(-3.0f, 3.0f), scale(0.2f, 5.0f);
    for (int k = 0; k < 12; ++k) {
        CAPTURE(k);
        const bool uniform = k % 2 == 0;
        const vec3 s = uniform ? vec3(scale(rng)) : vec3(scale(rng), scale(rng), scale(rng));
        const mat4 place = trs(vec3(1e4f, -3e3f, 2e4f), vec3(angle(rng), angle(rng), angle(rng)), s);
        const float exact = stretch_by_iteration(glm::mat3(place));
        const float stated = largest_stretch(glm::mat3(place));
        CHECK(stated >= exact * (1.0f - 1e-5f));
        if (uniform) CHECK(stated == doctest::Approx(exact).epsilon(1e-4));
        Mesh placed_coarse, placed_full;
        placed_coarse.append(coarse, place);
        placed_full.append(full, place);
        CHECK(placed_coarse.deviation == doctest::Approx(coarse.deviation * stated));
        CHECK(placed_full.deviation == 0.0f);
        // Measured where the placement put them (2e4 from the origin: float positions step by 2e-3 there).
        const double measured = shape_distance(placed_coarse, placed_full);
        CHECK(measured <= placed_coarse.deviation + 4e-3);
    }
}

TEST_CASE("shapes are the same to the bit when built again, and scopes nest") {
    for (const ShapeCase& c : shape_cases()) {
        CAPTURE(c.name);
        for (float tolerance : {0.0f, 0.01f * static_cast<float>(c.size)}) {
            Mesh a, b;
            {
                const DetailScope outer(Detail{tolerance});
                a = c.build();
                {
                    const DetailScope inner(Detail{0.5f * static_cast<float>(c.size)});
                    (void)c.build();
                }
                CHECK(current_detail().tolerance == tolerance);
                b = c.build();
            }
            REQUIRE(a.vertices.size() == b.vertices.size());
            CHECK(a.indices == b.indices);
            CHECK(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)) == 0);
            CHECK(a.deviation == b.deviation);
        }
    }
}

} // namespace ks::assetgen
