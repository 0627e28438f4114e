// The convex decomposition (brush/convex_decomposition.h): the hulls hold the whole surface, their count
// keeps to the cap, concave shapes are cut where they bend, convex ones are left whole, and the hard cases
// (slivers, huge coordinates, turned shapes, repetition, bad input) hold.
#include "../../bench/brush/solid_meshes.h"
#include "brush/brush_build.h"
#include "brush/convex_decomposition.h"
#include "brush/convex_hull.h"
#include "brush/decomposition_cache.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace ks::decomposition_test {
namespace {

using namespace ks::brush;
using bench::SolidMesh;

struct Made {
    ConvexDecomposition decomposition;
    std::vector<Brush> hulls;
};

Made decompose(const SolidMesh& m, int max_hulls, int resolution = 48) {
    DecompositionOptions options;
    options.max_hulls = max_hulls;
    options.resolution = resolution;
    Result<ConvexDecomposition> d = decompose_convex(m.vertices, m.triangles, options);
    REQUIRE_MESSAGE(d.ok(), (d.ok() ? std::string() : d.error().str()));
    Made made{*d, {}};
    for (const auto& points : d->hulls) {
        Result<Brush> hull = make_from_points(points);
        REQUIRE_MESSAGE(hull.ok(), (hull.ok() ? std::string() : hull.error().str()));
        made.hulls.push_back(*hull);
    }
    return made;
}

double mesh_size(const SolidMesh& m) {
    DVec3 lo(1e300), hi(-1e300);
    for (const DVec3& v : m.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const DVec3 e = hi - lo;
    return std::max({e.x, e.y, e.z});
}

// Every surface point inside a hull (to 1e-9 of the size), and the hulls' volume within `excess` of the
// solid's.
void check_holds(const SolidMesh& m, const Made& made, double excess) {
    Rng rng(7);
    const double size = mesh_size(m);
    CHECK(bench::surface_outside(m, made.hulls, 4000, rng) <= 1e-9 * size);
    const double volume = m.volume > 0 ? m.volume : std::abs(bench::enclosed_volume(m));
    double total = 0;
    for (const Brush& h : made.hulls) total += h.volume();
    CHECK(total == doctest::Approx(made.decomposition.hull_volume).epsilon(1e-9));
    CHECK(total >= volume * (1 - 1e-9));
    CHECK(total <= volume * (1 + excess));
}

} // namespace

TEST_CASE("convex decomposition: concave shapes are cut where they bend, within the cap") {
    SUBCASE("an L: two hulls, exact") {
        const SolidMesh l = bench::l_shape();
        const Made one = decompose(l, 1);
        CHECK(one.hulls.size() == 1);
        check_holds(l, one, 2.0); // the one hull fills the L's inner corner
        const Made two = decompose(l, 8);
        CHECK(two.hulls.size() == 2);
        check_holds(l, two, 1e-9);
    }
    SUBCASE("an arch: three hulls, the opening free") {
        const SolidMesh a = bench::arch();
        const Made made = decompose(a, 8);
        CHECK(made.hulls.size() == 3);
        check_holds(a, made, 0.01);       // measured 0 %
        for (const Brush& h : made.hulls) // nothing in the opening under the lintel
            CHECK_FALSE((h.bounds_min().x < 2.0 && h.bounds_max().x > 2.0 && h.bounds_min().y < 1.5));
    }
    SUBCASE("a table: top and four legs") {
        const SolidMesh t = bench::table();
        const Made made = decompose(t, 8);
        CHECK(made.hulls.size() == 5);
        check_holds(t, made, 0.01); // measured 0 %
        const Made capped = decompose(t, 3);
        CHECK(capped.hulls.size() == 3);
        check_holds(t, capped, 20.0);
    }
    SUBCASE("a ring: the hole stays open with enough hulls; too few are never worse than one") {
        const SolidMesh r = bench::ring(2.0, 0.5, 48, 16);
        const double one_hull = convex_hull_volume(r.vertices).value();
        for (int cap : {2, 3}) {
            CAPTURE(cap);
            const Made few = decompose(r, cap);
            CHECK(few.decomposition.hull_volume <= one_hull * (1 + 1e-9));
        }
        const Made made = decompose(r, 16);
        CHECK(made.hulls.size() >= 4);
        CHECK(made.hulls.size() <= 16);
        check_holds(r, made, 0.1);          // measured 4.4 % with 16 hulls
        for (const Brush& h : made.hulls) { // no hull reaches the centre
            bool covers_centre = true;
            for (const Face& f : h.faces()) covers_centre &= f.plane.signed_distance(DVec3(0.0)) <= 0;
            CHECK_FALSE(covers_centre);
        }
    }
}

TEST_CASE("convex decomposition: convex shapes stay one hull") {
    const SolidMesh b = bench::ball(16, 32, 1.0);
    const Made ball = decompose(b, 8);
    CHECK(ball.hulls.size() == 1);
    check_holds(b, ball, 1e-9);
    const SolidMesh box = bench::boxes({{{-1, -2, -3}, {1, 2, 3}}});
    const Made one = decompose(box, 8);
    CHECK(one.hulls.size() == 1);
    check_holds(box, one, 1e-9);
}

TEST_CASE("convex decomposition: hard cases") {
    SUBCASE("a sliver: a plate 1e-4 thick stays one hull of its own thickness") {
        const SolidMesh plate = bench::boxes({{{0, 0, 0}, {10, 1e-4, 10}}});
        const Made made = decompose(plate, 8);
        CHECK(made.hulls.size() == 1);
        check_holds(plate, made, 1e-6);
    }
    SUBCASE("an L made of slivers: two thin hulls") {
        const SolidMesh thin = bench::boxes({{{0, 0, 0}, {4, 0.01, 1}}, {{0, 0.01, 0}, {0.01, 4, 1}}});
        const Made made = decompose(thin, 8);
        CHECK(made.hulls.size() == 2);
        check_holds(thin, made, 1e-6);
    }
    SUBCASE("huge coordinates: as good 30 000 units away") {
        // Faces on voxel boundaries fall either side by the rounding of the far grid: the cuts may move by a
        // voxel, the count and the quality may not.
        const SolidMesh near = bench::arch();
        const SolidMesh far = bench::moved(near, glm::dmat3(1.0), DVec3(30000.0, -20000.0, 25000.0));
        const Made a = decompose(near, 8), b = decompose(far, 8);
        CHECK(std::abs(static_cast<int>(a.hulls.size()) - static_cast<int>(b.hulls.size())) <= 1);
        check_holds(near, a, 0.1);
        check_holds(far, b, 0.1);
    }
    SUBCASE("turned: an L at 30 degrees about two axes still holds its surface") {
        const glm::dmat3 turn = glm::mat3_cast(glm::angleAxis(0.52, glm::normalize(DVec3(1, 2, 0.5))));
        const SolidMesh l = bench::moved(bench::l_shape(), turn, DVec3(0.3, -1.1, 2.2));
        const Made made = decompose(l, 8);
        CHECK(made.hulls.size() >= 2);
        CHECK(made.hulls.size() <= 8);
        check_holds(l, made, 0.5);
    }
    SUBCASE("dense: a ring of 24 576 triangles, its pieces' thousands of corners priced by their proxies") {
        // Its hulls have more faces than a brush takes (the model entity snaps those to a coarser grid), so
        // the check goes through Qhull's planes.
        const SolidMesh r = bench::ring(2.0, 0.5, 192, 64);
        DecompositionOptions options;
        options.max_hulls = 8;
        auto made = decompose_convex(r.vertices, r.triangles, options);
        REQUIRE(made.ok());
        CHECK(made->hulls.size() == 8);
        bench::HullPlanes planes;
        for (const auto& points : made->hulls) {
            auto hull = convex_hull(points);
            REQUIRE(hull.ok());
            planes.emplace_back();
            for (const HullFace& f : hull->faces) planes.back().push_back(f.plane);
        }
        Rng rng(5);
        CHECK(bench::surface_outside(r, planes, 4000, rng) <= 1e-9 * 5.0);
        const double volume = std::abs(bench::enclosed_volume(r));
        CHECK(made->hull_volume >= volume);
        CHECK(made->hull_volume <= volume * 1.15); // measured 9 %, as for the coarse ring
    }
    SUBCASE("repetition: the same mesh decomposes the same, bit for bit") {
        const SolidMesh r = bench::table();
        const Made a = decompose(r, 4), b = decompose(r, 4);
        CHECK(a.decomposition.hulls == b.decomposition.hulls);
    }
    SUBCASE("an open mesh (a box without its top) still yields hulls that hold it") {
        SolidMesh open = bench::boxes({{{0, 0, 0}, {2, 1, 2}}});
        open.triangles.erase(open.triangles.begin() + 6, open.triangles.begin() + 8); // the +y face
        const Made made = decompose(open, 4);
        CHECK_FALSE(made.hulls.empty());
        Rng rng(3);
        CHECK(bench::surface_outside(open, made.hulls, 2000, rng) <= 1e-9);
    }
}

TEST_CASE("convex decomposition: bad input is refused, naming what is wrong") {
    const SolidMesh l = bench::l_shape();
    auto message = [](const Result<ConvexDecomposition>& r) {
        return r.ok() ? std::string() : r.error().str();
    };
    CHECK(message(decompose_convex(l.vertices, {})).find("no triangles") != std::string::npos);
    SolidMesh bad = l;
    bad.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
    CHECK(message(decompose_convex(bad.vertices, bad.triangles)).find("vertices[3]") != std::string::npos);
    bad = l;
    bad.triangles[5][1] = 999;
    CHECK(message(decompose_convex(bad.vertices, bad.triangles)).find("triangles[5]") != std::string::npos);
    const std::vector<DVec3> flat{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}};
    const std::vector<std::array<std::uint32_t, 3>> two{{0, 1, 2}, {1, 3, 2}};
    CHECK(message(decompose_convex(flat, two)).find("no volume") != std::string::npos);
    DecompositionOptions options;
    options.max_hulls = 0;
    CHECK(message(decompose_convex(l.vertices, l.triangles, options)).find("out of range") !=
          std::string::npos);
    options = {};
    options.resolution = 100000;
    CHECK(message(decompose_convex(l.vertices, l.triangles, options)).find("out of range") !=
          std::string::npos);
}

TEST_CASE(
    "convex decomposition: the disk cache gives back the same hulls, and a damaged entry is made again") {
    test::ScratchDir dir;
    const disk_cache::Store store(dir.path());
    const SolidMesh t = bench::table();
    DecompositionOptions options;
    options.max_hulls = 8;
    auto first = decompose_convex_cached(t.vertices, t.triangles, options, store);
    REQUIRE(first.ok());
    const auto file = store.file("hulls", decomposition_cache_key(t.vertices, t.triangles, options));
    REQUIRE(std::filesystem::exists(file));
    auto again = decompose_convex_cached(t.vertices, t.triangles, options, store);
    REQUIRE(again.ok());
    CHECK(again->hulls == first->hulls);
    CHECK(again->parts == first->parts);
    CHECK(again->hull_volume == first->hull_volume);
    // Another cap is another entry; a truncated entry is a miss, made and written again.
    options.max_hulls = 2;
    CHECK(decomposition_cache_key(t.vertices, t.triangles, options) !=
          decomposition_cache_key(t.vertices, t.triangles, DecompositionOptions{}));
    options.max_hulls = 8;
    std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    auto repaired = decompose_convex_cached(t.vertices, t.triangles, options, store);
    REQUIRE(repaired.ok());
    CHECK(repaired->hulls == first->hulls);
    CHECK(std::filesystem::file_size(file) > 0);
    auto reread = decompose_convex_cached(t.vertices, t.triangles, options, store);
    REQUIRE(reread.ok());
    CHECK(reread->hulls == first->hulls);
}

} // namespace ks::decomposition_test
