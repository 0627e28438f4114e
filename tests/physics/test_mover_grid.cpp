// The movers' grid on its own: every query visits exactly the movers whose current bounds overlap it, each
// once, however far they moved inside the step, however big or far from the origin they are, and whatever
// the query's size (a brute-force check of every box is the reference).
#include "physics/mover_grid.h"

#include "core/random.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace ks;
using namespace ks::physics;

namespace {

std::vector<std::uint32_t> visited(const MoverGrid& grid, const geometry::Aabb& region) {
    std::vector<std::uint32_t> out;
    grid.query(region, [&](std::uint32_t position) { out.push_back(position); });
    return out;
}

std::vector<std::uint32_t> brute_force(const std::vector<geometry::Aabb>& now, const geometry::Aabb& region) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < now.size(); ++i)
        if (now[i].overlaps(region)) out.push_back(i);
    return out;
}

// Each overlapping mover exactly once (the order is the grid's own).
void expect_same(std::vector<std::uint32_t> got, const std::vector<std::uint32_t>& want) {
    std::sort(got.begin(), got.end());
    CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
    CHECK(got == want);
}

geometry::Aabb box_at(const Vec3& centre, const Vec3& half) {
    return {centre - half, centre + half};
}

} // namespace

TEST_CASE("the movers' grid visits exactly the overlapping movers, once each, as they move in a step") {
    for (const float far : {0.0f, 3e4f, -2e6f}) {
        CAPTURE(far);
        Rng rng(7 + static_cast<std::uint64_t>(std::abs(far)));
        for (const int n : {0, 1, 7, 200, 3000}) {
            CAPTURE(n);
            const float spread = n > 500 ? 300.0f : 60.0f;
            std::vector<geometry::Aabb> now;
            for (int i = 0; i < n; ++i) {
                const Vec3 c(far + rng.uniform(-spread, spread), rng.uniform(-5, 5),
                             far + rng.uniform(-spread, spread));
                // Mostly characters; every tenth a door leaf or platform wider than a cell.
                const Vec3 half = i % 10 == 9 ? Vec3(rng.uniform(3, 30), 2, rng.uniform(0.2f, 3))
                                              : Vec3(rng.uniform(0.3f, 1.2f), 2, rng.uniform(0.3f, 1.2f));
                now.push_back(box_at(c, half));
            }
            const float slack = 0.6f;
            MoverGrid grid;
            grid.build(now, slack);
            auto check_queries = [&](int count) {
                for (int q = 0; q < count; ++q) {
                    const Vec3 c(far + rng.uniform(-spread, spread), rng.uniform(-6, 6),
                                 far + rng.uniform(-spread, spread));
                    const float size = q % 7 == 0 ? rng.uniform(10, 200) : rng.uniform(0, 4);
                    const geometry::Aabb region =
                        box_at(c, Vec3(size, rng.uniform(0, 4), size * rng.uniform(0.2f, 1)));
                    expect_same(visited(grid, region), brute_force(now, region));
                }
            };
            check_queries(60);
            // Movers move one by one inside the step: most within the slack, some pushed far (out of a
            // crowd, out of a closing door), some back again; the queries in between see each where it is
            // now.
            for (int i = 0; i < n; ++i) {
                const float push = i % 13 == 0 ? rng.uniform(2, 40) : rng.uniform(0, slack);
                const float angle = rng.uniform(0, 6.2832f);
                const Vec3 by(push * std::cos(angle), rng.uniform(-0.5f, 0.5f), push * std::sin(angle));
                now[i] = {now[i].min + by, now[i].max + by};
                grid.update(static_cast<std::uint32_t>(i), now[i]);
                if (i % 50 == 0) check_queries(4);
            }
            check_queries(60);
            // The next step starts from where they are.
            grid.build(now, slack);
            check_queries(30);
        }
    }
}

TEST_CASE(
    "the movers' grid takes boxes that are not numbers, at the float's limits, and regions of any size") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<geometry::Aabb> now = {
        box_at(Vec3(0, 0, 0), Vec3(1)),
        box_at(Vec3(nan, 0, 0), Vec3(1)),       // never found (overlaps nothing)
        box_at(Vec3(2e9f, 0, -3e9f), Vec3(1)),  // beyond the grid's cells: tested by every query
        box_at(Vec3(3e38f, 0, 0), Vec3(1e38f)), // near the float's limit
        {Vec3(-inf), Vec3(inf)},                // everywhere
        {Vec3(5, 0, 5), Vec3(4, 0, 4)},         // inverted: overlaps nothing
        box_at(Vec3(-8.0f, 0, 8.0f), Vec3(0)),  // a point on a cell corner
    };
    MoverGrid grid;
    grid.build(now, 0.5f);
    const std::vector<geometry::Aabb> regions = {
        box_at(Vec3(0), Vec3(2)),
        box_at(Vec3(-8.0f, 0, 8.0f), Vec3(0)),
        box_at(Vec3(2e9f, 0, -3e9f), Vec3(5)),
        {Vec3(-inf), Vec3(inf)},
        box_at(Vec3(nan), Vec3(1)),
        box_at(Vec3(0), Vec3(1e6f)), // thousands of cells: every mover tested instead
        box_at(Vec3(3e38f, 0, 0), Vec3(1)),
    };
    for (std::size_t r = 0; r < regions.size(); ++r) {
        CAPTURE(r);
        expect_same(visited(grid, regions[r]), brute_force(now, regions[r]));
    }
    // A mover that becomes not a number, or leaps to the limit, mid-step.
    now[0] = box_at(Vec3(nan), Vec3(1));
    grid.update(0, now[0]);
    now[6] = box_at(Vec3(-1e30f, 0, 0), Vec3(1));
    grid.update(6, now[6]);
    for (std::size_t r = 0; r < regions.size(); ++r) {
        CAPTURE(r);
        expect_same(visited(grid, regions[r]), brute_force(now, regions[r]));
    }
}

TEST_CASE("the movers' grid finds a mover whose bounds end exactly at its reach, far from the origin") {
    // The query widens by the largest half-size plus the slack; a mover moved by exactly that much (in
    // float) must still be found, or leave its cell for the always-tested list.
    for (const float far : {0.0f, 1024.0f, 9e5f, -7e7f}) {
        CAPTURE(far);
        const float slack = 0.5f;
        std::vector<geometry::Aabb> now = {box_at(Vec3(far, 0, far), Vec3(1.0f)),
                                           box_at(Vec3(far + 3, 0, far), Vec3(1.0f))};
        MoverGrid grid;
        grid.build(now, slack);
        for (const float step : {0.49f, 0.5f, 0.5000001f, 0.51f, 1.5f, 1.5000001f, 8.0f, 8.000001f}) {
            CAPTURE(step);
            for (const Vec3 dir : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
                now[0] = box_at(Vec3(far, 0, far) + dir * step, Vec3(1.0f));
                grid.update(0, now[0]);
                // Regions that just touch the moved box on each side.
                for (const geometry::Aabb& region : {geometry::Aabb{Vec3(now[0].max.x, -1, now[0].min.z),
                                                                    Vec3(now[0].max.x + 1, 1, now[0].max.z)},
                                                     geometry::Aabb{Vec3(now[0].min.x - 1, -1, now[0].min.z),
                                                                    Vec3(now[0].min.x, 1, now[0].max.z)},
                                                     geometry::Aabb{Vec3(now[0].min.x, -1, now[0].max.z),
                                                                    Vec3(now[0].max.x, 1, now[0].max.z + 1)},
                                                     geometry::Aabb{Vec3(now[0].min.x, -1, now[0].min.z - 1),
                                                                    Vec3(now[0].max.x, 1, now[0].min.z)}})
                    expect_same(visited(grid, region), brute_force(now, region));
            }
        }
    }
}
