#include "audio/occlusion.h"

#include <algorithm>
#include <cmath>
#include <doctest/doctest.h>
#include <numeric>
#include <vector>

using namespace ks;
using namespace ks::audio;

namespace {
// Counts rays per source and answers "blocked" for sources with x < 0.
struct Walls {
    std::vector<int> rays;
    explicit Walls(int n) : rays(static_cast<std::size_t>(n), 0) {}
    bool operator()(Vec3, Vec3 source) {
        ++rays[static_cast<std::size_t>(std::lround(std::abs(source.z)))];
        return source.x < 0.0f;
    }
};
std::vector<Vec3> positions(int n) {
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) p.emplace_back(i % 2 == 0 ? -1.0f : 1.0f, 0.0f, static_cast<float>(i));
    return p;
}
} // namespace

TEST_CASE("occlusion: the ray budget is respected and every voice is visited round robin") {
    const int n = 20;
    OcclusionScheduler scheduler(n, {4, 0.08f});
    auto pos = positions(n);
    Walls walls(n);
    for (int i = 0; i < n; ++i) scheduler.start(i);
    CHECK(scheduler.tracked_count() == n);
    for (int frame = 0; frame < 50; ++frame) {
        const int rays = scheduler.update(1.0f / 60.0f, Vec3(0.0f), pos, walls);
        CHECK(rays == 4);
    }
    // 200 rays over 20 voices: each voice got 10, none starved, none favoured.
    for (int count : walls.rays) CHECK(count == 10);

    OcclusionScheduler few(n, {8, 0.08f});
    few.start(3);
    few.start(7);
    Walls two(n);
    CHECK(few.update(0.016f, Vec3(0.0f), pos, two) == 2); // never more rays than voices
    few.stop(3);
    CHECK(few.tracked_count() == 1);
    CHECK(few.update(0.016f, Vec3(0.0f), pos, two) == 1);
}

TEST_CASE("occlusion: newly started voices are measured first, their first answer at once") {
    const int n = 12;
    OcclusionScheduler scheduler(n, {2, 0.08f});
    auto pos = positions(n);
    Walls walls(n);
    for (int i = 1; i < 10; ++i) scheduler.start(i);
    for (int frame = 0; frame < 10; ++frame) scheduler.update(0.016f, Vec3(0.0f), pos, walls);
    std::fill(walls.rays.begin(), walls.rays.end(), 0);
    scheduler.start(10); // x < 0: blocked
    scheduler.start(0);  // x < 0: blocked
    CHECK_FALSE(scheduler.measured(10));
    scheduler.update(0.016f, Vec3(0.0f), pos, walls);
    CHECK(walls.rays[10] == 1);
    CHECK(walls.rays[0] == 1);
    CHECK(std::accumulate(walls.rays.begin(), walls.rays.end(), 0) == 2); // the budget went to the new ones
    CHECK(scheduler.amount(10) == 1.0f);                                  // not heard yet: no fade in
    CHECK(scheduler.amount(0) == 1.0f);

    // More new voices than the budget: the ones left over start clear and fade like the others.
    OcclusionScheduler busy(n, {1, 0.08f});
    busy.start(0);
    busy.start(2);
    busy.update(0.016f, Vec3(0.0f), pos, walls);
    CHECK(busy.amount(0) == 1.0f);
    CHECK_FALSE(busy.measured(2));
    busy.update(0.016f, Vec3(0.0f), pos, walls);
    CHECK(busy.target(2) == 1.0f);
    CHECK(busy.amount(2) == 0.0f); // follows from the next update on
    busy.update(0.016f, Vec3(0.0f), pos, walls);
    CHECK(busy.amount(2) > 0.0f);
    CHECK(busy.amount(2) < 0.25f);
}

TEST_CASE("occlusion: the amount reaches its target smoothly, with no jump above the per-update bound") {
    OcclusionScheduler scheduler(1, {8, 0.08f});
    std::vector<Vec3> pos{Vec3(1.0f, 0.0f, 0.0f)};
    bool wall = false;
    auto blocked = [&](Vec3, Vec3) { return wall; };
    scheduler.start(0);
    const float dt = 1.0f / 60.0f;
    scheduler.update(dt, Vec3(0.0f), pos, blocked);
    CHECK(scheduler.amount(0) == 0.0f);

    // The bound: one update moves the amount by at most 1 - exp(-dt / 0.08) = 0.188 of the way.
    const float bound = 1.0f - std::exp(-dt / 0.08f);
    wall = true;
    float previous = scheduler.amount(0);
    float max_jump = 0.0f;
    int frames_to_90 = -1;
    for (int frame = 0; frame < 60; ++frame) {
        scheduler.update(dt, Vec3(0.0f), pos, blocked);
        max_jump = std::max(max_jump, std::abs(scheduler.amount(0) - previous));
        previous = scheduler.amount(0);
        if (frames_to_90 < 0 && previous >= 0.9f) frames_to_90 = frame + 1;
    }
    CHECK(max_jump <= bound + 1e-6f);
    CHECK(max_jump > 0.5f * bound);
    CHECK(scheduler.amount(0) == doctest::Approx(1.0f).epsilon(1e-3));
    // 90% after about 2.3 time constants (184 ms = 11 frames), plus the frame of measurement delay.
    CHECK(frames_to_90 >= 11);
    CHECK(frames_to_90 <= 13);

    wall = false;
    for (int frame = 0; frame < 60; ++frame) {
        scheduler.update(dt, Vec3(0.0f), pos, blocked);
        CHECK(std::abs(scheduler.amount(0) - previous) <= bound + 1e-6f);
        previous = scheduler.amount(0);
    }
    CHECK(scheduler.amount(0) < 1e-3f);

    // A zero or broken dt moves nothing.
    wall = true;
    scheduler.update(0.0f, Vec3(0.0f), pos, blocked);
    scheduler.update(std::nanf(""), Vec3(0.0f), pos, blocked);
    CHECK(scheduler.amount(0) == previous);
}
