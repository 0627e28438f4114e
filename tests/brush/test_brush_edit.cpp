// Vertex, edge and face moves (accepted, and refused when the brush would lose a corner or turn over) and
// snapping to a grid; a vertex added (an edge split) and vertices removed.
#include "brush/brush_build.h"
#include "brush/brush_edit.h"
#include "brush/texture_mapping.h"
#include "brush_checks.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;
using ks::brush_test::grid_distance;
using ks::brush_test::has_vertex;

namespace {

Brush cube() {
    FaceAttributes a;
    a.material = "crate";
    auto b = make_box({0, 0, 0}, {2, 2, 2}, a);
    REQUIRE(b.ok());
    return *b;
}

int vertex_at(const Brush& b, const DVec3& p) {
    for (std::size_t i = 0; i < b.vertices().size(); ++i)
        if (glm::length(b.vertices()[i] - p) < 1e-9) return static_cast<int>(i);
    FAIL("no vertex at the point");
    return -1;
}

} // namespace

TEST_CASE("moving one corner up splits the top into two triangles") {
    const Brush b = cube();
    const int v[] = {vertex_at(b, {2, 2, 2})};
    auto moved = move_vertices(b, v, {0, 1, 0});
    REQUIRE(moved.ok());
    CHECK(audit(*moved).empty());
    CHECK(moved->vertices().size() == 8);
    CHECK(has_vertex(*moved, {2, 3, 2}, 1e-12));
    CHECK(moved->faces().size() == 7); // the top bends into two triangles; +x and +z stay flat
    for (const Face& f : moved->faces()) CHECK(f.attributes.material == "crate");
    CHECK(moved->volume() == doctest::Approx(8.0 + 4.0 / 3.0)); // two roof triangles, 2/3 each
}

TEST_CASE("moving a corner inward is refused: it would go inside") {
    const Brush b = cube();
    const int v[] = {vertex_at(b, {2, 2, 2})};
    CHECK(move_vertices(b, v, {-0.5, -0.5, -0.5}).ok()); // still outside x + y + z = 4: a corner
    auto in = move_vertices(b, v, {-1.5, -1.5, -1.5});
    REQUIRE(!in.ok());
    CHECK(in.error().message.find("corner") != std::string::npos);
    // Onto a face's plane: flat there, no longer a corner.
    auto flat = move_vertices(b, v, {0, 0, -2});
    CHECK(!flat.ok());
}

TEST_CASE("moving an edge and a face") {
    const Brush b = cube();
    int top_edge = -1;
    for (std::size_t e = 0; e < b.edges().size(); ++e) {
        const DVec3 p = b.vertices()[b.edges()[e].v0], q = b.vertices()[b.edges()[e].v1];
        if (p.y == 2 && q.y == 2 && p.x == 2 && q.x == 2) top_edge = static_cast<int>(e);
    }
    REQUIRE(top_edge >= 0);
    auto ridge = move_edge(b, top_edge, {-1, 1, 0}); // the +x top edge up and in: a sloped roof side
    REQUIRE(ridge.ok());
    CHECK(audit(*ridge).empty());
    CHECK(has_vertex(*ridge, {1, 3, 0}, 1e-12));
    int top = -1;
    for (std::size_t f = 0; f < b.faces().size(); ++f)
        if (b.faces()[f].plane.normal.y > 0.5) top = static_cast<int>(f);
    auto taller = move_face(b, top, {0, 3, 0});
    REQUIRE(taller.ok());
    CHECK(taller->faces().size() == 6);
    CHECK(taller->volume() == doctest::Approx(20.0));
    auto sheared = move_face(b, top, {1, 0, 0});
    REQUIRE(sheared.ok());
    CHECK(audit(*sheared).empty());
    CHECK(sheared->volume() == doctest::Approx(8.0)); // a shear keeps the volume
    CHECK(!move_face(b, top, {0, -2, 0}).ok());       // onto the bottom: no volume
    CHECK(!move_face(b, 17, {0, 1, 0}).ok());
    CHECK(!move_edge(b, -1, {0, 1, 0}).ok());
}

TEST_CASE("a face moved along its plane keeps its world mapping") {
    const Brush b = cube();
    int top = -1;
    for (std::size_t f = 0; f < b.faces().size(); ++f)
        if (b.faces()[f].plane.normal.y > 0.5) top = static_cast<int>(f);
    const DVec3 delta(0.5, 1.0, 0.25);
    auto moved = move_face(b, top, delta);
    REQUIRE(moved.ok());
    const int g = moved->find_face(b.faces()[top].plane.translated(delta));
    REQUIRE(g >= 0);
    const DVec3 p(1.2, 2.0, 0.7);
    CHECK(glm::length(texture_coordinates(moved->faces()[g], p + delta) -
                      texture_coordinates(b.faces()[top], p)) < 1e-12);
}

TEST_CASE("a move that turns the brush over is refused") {
    // A wedge (triangular prism); moving its ridge far over the other side reconnects the hull differently.
    auto wedge = make_extrusion(std::vector<DVec3>{{0, 0, 0}, {4, 0, 0}, {2, 1, 0}}, {0, 0, 2});
    REQUIRE(wedge.ok());
    std::vector<int> ridge;
    for (std::size_t i = 0; i < wedge->vertices().size(); ++i)
        if (wedge->vertices()[i].y > 0.5) ridge.push_back(static_cast<int>(i));
    REQUIRE(ridge.size() == 2);
    CHECK(move_vertices(*wedge, ridge, {0, 2, 0}).ok());
    auto over = move_vertices(*wedge, ridge, {0, -2, 0}); // through the base to below it
    REQUIRE(!over.ok());
    CHECK(!move_vertices(*wedge, ridge, {0, -1, 0}).ok()); // onto the base: flat
    const int bad[] = {99};
    CHECK(!move_vertices(*wedge, bad, {0, 1, 0}).ok());
    CHECK(!move_vertices(*wedge, ridge, {0, std::nan(""), 0}).ok());
}

TEST_CASE("snapping puts every vertex on the grid, within 1e-9, even far from the origin") {
    for (double far : {0.0, 1000.0, 9990.0}) {
        auto box = make_box(DVec3(far) + DVec3(0.1, 0.2, 0.3), DVec3(far) + DVec3(4.2, 3.1, 5.05));
        REQUIRE(box.ok());
        auto turned = transformed(*box, glm::mat3_cast(glm::angleAxis(0.3, glm::normalize(DVec3(1, 2, 0.5)))),
                                  DVec3(0.0));
        REQUIRE(turned.ok());
        CHECK(grid_distance(*turned, 0.125) > 1e-3);
        auto snapped = snap_to_grid(*turned, 0.125);
        REQUIRE(snapped.ok());
        CHECK(audit(*snapped).empty());
        CHECK(grid_distance(*snapped, 0.125) <= 1e-9);
        // Snapping again changes nothing.
        auto again = snap_to_grid(*snapped, 0.125);
        REQUIRE(again.ok());
        CHECK(again->vertices().size() == snapped->vertices().size());
        CHECK(again->volume() == doctest::Approx(snapped->volume()).epsilon(1e-12));
    }
}

TEST_CASE("snapping a brush smaller than the grid is refused") {
    auto tiny = make_box({0.01, 0.01, 0.01}, {0.2, 0.2, 0.2});
    REQUIRE(tiny.ok());
    auto snapped = snap_to_grid(*tiny, 1.0);
    REQUIRE(!snapped.ok());
    CHECK(snapped.error().where.path == "grid");
    CHECK(!snap_to_grid(*tiny, 0.0).ok());
}

TEST_CASE("an edge split adds a vertex outside the brush; removing vertices rebuilds the hull of the rest") {
    const Brush b = cube();
    auto split = add_vertex(b, {1, 3, 2}); // above the top front edge's midpoint
    REQUIRE(split.ok());
    CHECK(audit(*split).empty());
    CHECK(split->vertices().size() == 9);
    CHECK(has_vertex(*split, {1, 3, 2}, 1e-12));
    for (const Face& f : split->faces()) CHECK(f.attributes.material == "crate");
    CHECK_FALSE(add_vertex(b, {1, 2, 2}).ok()); // on the edge: not outside
    CHECK_FALSE(add_vertex(b, {1, 1, 1}).ok()); // inside
    CHECK_FALSE(add_vertex(b, {9, 9, 9}).ok()); // swallows the corner (2,2,2)
    const int corner[] = {vertex_at(b, {2, 2, 2})};
    auto removed = remove_vertices(b, corner);
    REQUIRE(removed.ok());
    CHECK(audit(*removed).empty());
    CHECK(removed->vertices().size() == 7);
    CHECK(removed->volume() == doctest::Approx(8.0 - 4.0 / 3.0));
    const int face[] = {vertex_at(b, {0, 0, 0}), vertex_at(b, {2, 0, 0}), vertex_at(b, {0, 2, 0}),
                        vertex_at(b, {2, 2, 0}), vertex_at(b, {0, 0, 2})};
    CHECK_FALSE(remove_vertices(b, face).ok()); // three left: no volume
}
