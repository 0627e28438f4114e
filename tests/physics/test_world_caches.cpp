// What makes the world step fast must not change what it does: each character keeps the static bodies
// around it across steps (re-queried when it leaves the cached box or the static set changes), and box
// queries visit leaf slots in ascending order whatever the BVH's width, so the controller sees the same
// obstacles in the same order as a fresh query would give; the movers' grid gives every step exactly what the
// all-pairs reference gives.
#include "physics_scene.h"

#include "bench/physics/scenes.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

TEST_CASE("BVH box queries visit leaf slots in ascending order and find exactly the overlapping items") {
    Rng rng(31);
    for (int n : {1, 3, 9, 64, 500, 3000}) {
        CAPTURE(n);
        std::vector<geometry::Aabb> items;
        for (int i = 0; i < n; ++i) {
            const Vec3 c(rng.uniform(-100, 100), rng.uniform(-10, 10), rng.uniform(-100, 100));
            const Vec3 h(rng.uniform(0.1f, 4), rng.uniform(0.1f, 4), rng.uniform(0.1f, 4));
            items.push_back({c - h, c + h});
        }
        Bvh bvh;
        bvh.build(items);
        const auto order = bvh.item_order();
        for (int q = 0; q < 200; ++q) {
            const Vec3 c(rng.uniform(-110, 110), rng.uniform(-12, 12), rng.uniform(-110, 110));
            const geometry::Aabb box{c - Vec3(rng.uniform(0, 20)), c + Vec3(rng.uniform(0, 20))};
            std::vector<std::uint32_t> visited;
            bvh.aabb_query(box, [&](std::uint32_t slot) {
                if (items[order[slot]].overlaps(box)) visited.push_back(slot);
                return true;
            });
            CHECK(std::is_sorted(visited.begin(), visited.end()));
            CHECK(std::adjacent_find(visited.begin(), visited.end()) == visited.end());
            int expected = 0;
            for (const geometry::Aabb& it : items) expected += it.overlaps(box);
            CHECK(static_cast<int>(visited.size()) == expected);
        }
    }
}

TEST_CASE("a static wall moved or added into a walking character's cached neighbourhood still blocks it") {
    for (int hz : kRates) {
        CAPTURE(hz);
        for (bool add_new : {false, true}) {
            CAPTURE(add_new);
            World w(at_rate(hz));
            add_floor(w);
            // Far away at first: not in the character's cached neighbourhood.
            const BodyId far_wall = add_box(w, {0, 8, -150}, {10, 8, 0.25f});
            const BodyId p = add_player(w, {0, 0, 0});
            for (int i = 0; i < hz / 4; ++i) w.step(1.0f / hz); // stands: its neighbourhood is cached
            const float z = w.transform(p).position.z;
            // A wall 0.3 ahead of the capsule's front (inside the cached box's margin): moved there, or a
            // new one added. A stale cache would let the character walk through it.
            const geometry::Transform ahead{{0, 8, z - 1.0f - 0.3f - 0.25f}, Quat(1, 0, 0, 0)};
            if (add_new)
                add_box(w, ahead.position, {10, 8, 0.25f});
            else
                w.set_transform(far_wall, ahead);
            float min_z = z; // never into the wall, at any step (a stale cache would walk in, then be
                             // pushed back out once it re-queried)
            for (int i = 0; i < hz; ++i) {
                w.character(p).movement.velocity = {0, 0, -10};
                w.step(1.0f / hz);
                min_z = std::min(min_z, w.transform(p).position.z);
            }
            CHECK(min_z >= ahead.position.z + 0.25f + 1.0f - 1e-3f);
            CHECK(w.transform(p).position.z <= ahead.position.z + 0.25f + 1.0f + 0.05f);
            // The floor is still there too (a stale cache would name slots of the old tree).
            CHECK(w.character(p).grounded);
            CHECK(std::abs(feet_y(w, p)) < 0.05f);
        }
    }
}

TEST_CASE("disabling the floor under a cached character drops it; enabling it again catches it") {
    World w;
    const BodyId floor = add_floor(w);
    const BodyId p = add_player(w, {0, 0, 0});
    for (int i = 0; i < 60; ++i) w.step(1.0f / 120.0f);
    CHECK(w.character(p).grounded);
    const float y0 = w.transform(p).position.y;
    w.set_enabled(floor, false);
    for (int i = 0; i < 12; ++i) w.step(1.0f / 120.0f);
    CHECK_FALSE(w.character(p).grounded);
    CHECK(w.transform(p).position.y < y0 - 0.01f);
    // Back on before it has fallen through (it is still overlapping the floor box's top region): it is
    // pushed out or lands, and stands again.
    w.set_enabled(floor, true);
    for (int i = 0; i < 240; ++i) w.step(1.0f / 120.0f);
    CHECK(w.character(p).grounded);
    CHECK(std::abs(feet_y(w, p)) < 0.05f);
}

TEST_CASE("characters running through the 2k-box level: same positions whether the world is stepped "
          "fresh or after its caches have been invalidated every step") {
    // Two worlds built alike; in the second, a far static box is set to its own transform every step, which
    // rebuilds the static set (into the same tree) and forces every character to query the BVH afresh. Both
    // must agree bit for bit: the cached neighbourhood gives exactly what a fresh query gives.
    const auto scene = scenes::make_rooms(600, 3);
    World a, b;
    scenes::add_to_world(scene, a);
    scenes::add_to_world(scene, b);
    BodyDesc far_box;
    far_box.shape = Shape::box({1, 1, 1});
    far_box.transform.position = {-1000, 0, -1000};
    const BodyId toggled = *b.add(far_box, "far box");
    REQUIRE(a.add(far_box, "far box").ok());
    Rng rng(77);
    std::vector<BodyId> ca, cb;
    std::vector<Vec3> start;
    for (int i = 0; i < 40; ++i) {
        BodyDesc d;
        d.shape = Shape::capsule(1.0f, 0.5f);
        d.motion = Motion::Character;
        Vec3 pos = scenes::random_origin(scene, rng);
        pos.y = 1.51f;
        d.transform.position = pos;
        start.push_back(pos);
        ca.push_back(*a.add(d, "character"));
        cb.push_back(*b.add(d, "character"));
    }
    for (int step = 0; step < 600; ++step) {
        if (step % 60 == 0)
            for (std::size_t i = 0; i < ca.size(); ++i) {
                const float ang = rng.uniform(0, 2 * kPi);
                const Vec3 v(15 * std::cos(ang), 0, 15 * std::sin(ang));
                a.character(ca[i]).movement.velocity.x = b.character(cb[i]).movement.velocity.x = v.x;
                a.character(ca[i]).movement.velocity.z = b.character(cb[i]).movement.velocity.z = v.z;
            }
        b.set_transform(toggled, far_box.transform);
        a.step(1.0f / 120.0f);
        b.step(1.0f / 120.0f);
    }
    int moved = 0;
    for (std::size_t i = 0; i < ca.size(); ++i) {
        const Vec3 pa = a.transform(ca[i]).position, pb = b.transform(cb[i]).position;
        CHECK(pa.x == pb.x);
        CHECK(pa.y == pb.y);
        CHECK(pa.z == pb.z);
        moved += glm::length(pa - start[i]) > 1.0f;
    }
    CHECK(moved > static_cast<int>(ca.size()) / 2);
}

TEST_CASE("bodies added while characters hold cached neighbourhoods (the body array grows and moves)") {
    // The cached obstacles point at the static bodies' shapes inside the world's body array; adding
    // hundreds of movers and triggers reallocates it, which must invalidate the caches (AddressSanitizer
    // builds turn a stale pointer into a failure; here the character must also keep standing).
    World w;
    add_floor(w);
    add_box(w, {6, 2, 0}, {1, 2, 1}); // a crate beside the path
    const BodyId p = add_player(w, {0, 0, 0});
    for (int i = 0; i < 30; ++i) w.step(1.0f / 120.0f);
    REQUIRE(w.character(p).grounded);
    for (int round = 0; round < 6; ++round) {
        for (int i = 0; i < 200; ++i) {
            BodyDesc t;
            t.shape = Shape::box({0.5f, 0.5f, 0.5f});
            t.transform.position = {100.0f + static_cast<float>(i), 0.5f, 100.0f + static_cast<float>(round)};
            t.motion = Motion::Kinematic;
            t.trigger = true;
            REQUIRE(w.add(t, "pickup").ok());
        }
        w.character(p).movement.velocity = {10, 0, 0}; // toward the crate
        for (int i = 0; i < 20; ++i) w.step(1.0f / 120.0f);
        CHECK(w.character(p).grounded);
        CHECK(std::abs(feet_y(w, p)) < 0.05f);
    }
    // Stopped by the crate (front face at x = 5, capsule radius 1).
    CHECK(w.transform(p).position.x <= 4.0f + 1e-3f);
    CHECK(w.transform(p).position.x >= 3.9f);
}

TEST_CASE("collision callbacks keep firing through replace, clear, remove and re-register (the dispatch "
          "is skipped only when none is registered)") {
    World w;
    add_floor(w);
    const BodyId a = add_player(w, {0, 0, 0});
    const BodyId b = add_player(w, {10, 0, 0});
    int calls_a = 0, calls_b = 0;
    auto step_and_count = [&]() {
        calls_a = calls_b = 0;
        w.step(1.0f / 120.0f);
    };
    step_and_count(); // no callbacks: nothing to call
    w.set_on_collision(a, [&](World&, const Collision&) { ++calls_a; });
    step_and_count();
    CHECK(calls_a > 0);
    w.set_on_collision(a, [&](World&, const Collision&) { calls_a += 10; }); // replaced
    step_and_count();
    CHECK(calls_a >= 10);
    w.set_on_collision(a, nullptr); // cleared
    step_and_count();
    CHECK(calls_a == 0);
    w.set_on_collision(a, nullptr); // cleared twice: still consistent
    w.set_on_collision(b, [&](World&, const Collision&) { ++calls_b; });
    step_and_count();
    CHECK(calls_b > 0);
    w.remove(b); // removed with its callback registered
    w.set_on_collision(a, [&](World&, const Collision&) { ++calls_a; });
    step_and_count();
    CHECK(calls_a > 0);
    const BodyId c = add_player(w, {-10, 0, 0}); // may reuse b's slot
    w.set_on_collision(c, [&](World&, const Collision&) { ++calls_b; });
    w.set_on_collision(a, nullptr);
    step_and_count();
    CHECK(calls_a == 0);
    CHECK(calls_b > 0);
}

TEST_CASE("a character pushed further than the movers' grid slack in a step is still met by the next one") {
    // No floor, no gravity. A kinematic box (half size 12) is moved onto character A, which is pushed out
    // through the +x face to x = 13.01, 13 units in one step, far beyond the grid's slack (0.5 units here).
    // B stands there; B moves after A in the same step and must find A where it now is (the grid has A in
    // the cells around the origin), so the two report a contact and end apart.
    World w;
    auto character = [&](Vec3 p) {
        BodyDesc d;
        d.shape = Shape::capsule(1.0f, 0.5f);
        d.motion = Motion::Character;
        d.transform.position = p;
        d.movement.gravity = 0.0f;
        return *w.add(d, "character");
    };
    const BodyId a = character({0.5f, 5, 0});
    const BodyId b = character({13.5f, 5, 0});
    BodyDesc door;
    door.shape = Shape::box({12, 12, 12});
    door.motion = Motion::Kinematic;
    door.transform.position = {0, 5, -100};
    const BodyId box = *w.add(door, "door");
    w.step(1.0f / 120.0f); // index the movers once where they are
    w.set_transform(box, {{0, 5, 0}, Quat(1, 0, 0, 0)});
    w.step(1.0f / 120.0f);
    const Vec3 pa = w.transform(a).position, pb = w.transform(b).position;
    CHECK(pa.x > 12.9f); // pushed out through +x
    bool met = false;
    for (const Collision& c : w.collisions()) met |= c.self == b && c.other == a;
    CHECK(met);
    CHECK(glm::length(pa - pb) >= 2.0f - 1e-3f); // and they no longer overlap
}

namespace {

// Characters placed by `place(i)` (capsule centres) with velocities from `rng`, on a floor, among a few
// crates, a kinematic door and two triggers, all shifted by `offset`. Built twice with the same arguments,
// the worlds differ only in their movers' broadphase.
struct CrowdScene {
    World world;
    BodyId door;
    std::vector<BodyId> characters;
    template <class Place>
    CrowdScene(MoverBroadphase movers, int n, Vec3 offset, float speed, std::uint64_t seed, Place&& place)
        : world(settings(movers)) {
        Rng rng(seed);
        add_box(world, offset + Vec3(0, -0.5f, 0), {400, 0.5f, 400});
        for (int i = 0; i < 6; ++i)
            add_box(world, offset + Vec3(rng.uniform(-30, 30), 1, rng.uniform(-30, 30)), Vec3(1.5f),
                    rng.uniform(0, 3));
        BodyDesc leaf;
        leaf.shape = Shape::box({4, 3, 0.25f});
        leaf.transform.position = offset + Vec3(8, 3, 0); // on a cell border
        leaf.motion = Motion::Kinematic;
        auto door_id = world.add(leaf, "door");
        REQUIRE(door_id.ok());
        door = *door_id;
        for (int t = 0; t < 2; ++t) {
            BodyDesc trig;
            trig.shape = Shape::box(Vec3(3));
            trig.transform.position = offset + Vec3(t ? -8.0f : 0.0f, 1, t ? 0.0f : 8.0f);
            trig.trigger = true;
            trig.motion = t ? Motion::Static : Motion::Kinematic;
            REQUIRE(world.add(trig, "trigger").ok());
        }
        for (int i = 0; i < n; ++i) {
            BodyDesc d;
            d.shape = Shape::capsule(kPlayerRadius, kPlayerHalfSegment);
            d.motion = Motion::Character;
            d.transform.position = offset + place(i, rng);
            const float a = rng.uniform(0, 2 * kPi);
            d.movement.velocity = Vec3(std::cos(a), 0, std::sin(a)) * speed * rng.uniform();
            d.movement.max_speed = 40.0f;
            auto id = world.add(d, "character");
            REQUIRE(id.ok());
            characters.push_back(*id);
        }
    }
    static WorldSettings settings(MoverBroadphase movers) {
        WorldSettings s;
        s.movers = movers;
        return s;
    }
};

bool same_bits(const Vec3& a, const Vec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Steps both scenes `steps` times (moving the kinematic door each step), checking after every step that
// both produced the same collision and trigger events, bit for bit and in the same order, and that every
// character is finite and where the other world has it.
void expect_same_steps(CrowdScene& grid, CrowdScene& reference, int steps) {
    long long events = 0;
    for (int s = 0; s < steps; ++s) {
        for (CrowdScene* scene : {&grid, &reference}) {
            geometry::Transform xf = scene->world.transform(scene->door);
            xf.position.x += (s % 20 < 10 ? 0.3f : -0.3f);
            scene->world.set_transform(scene->door, xf);
            scene->world.step(1.0f / 120.0f);
        }
        const auto a = grid.world.collisions(), b = reference.world.collisions();
        REQUIRE(a.size() == b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            REQUIRE(a[i].self == b[i].self);
            REQUIRE(a[i].other == b[i].other);
            REQUIRE(same_bits(a[i].point, b[i].point));
            REQUIRE(same_bits(a[i].normal, b[i].normal));
            REQUIRE(std::memcmp(&a[i].penetration, &b[i].penetration, sizeof(float)) == 0);
        }
        const auto ta = grid.world.trigger_events(), tb = reference.world.trigger_events();
        REQUIRE(ta.size() == tb.size());
        for (std::size_t i = 0; i < ta.size(); ++i)
            REQUIRE(
                (ta[i].kind == tb[i].kind && ta[i].trigger == tb[i].trigger && ta[i].other == tb[i].other));
        events += static_cast<long long>(a.size() + ta.size());
    }
    for (std::size_t i = 0; i < grid.characters.size(); ++i) {
        const Vec3 p = grid.world.transform(grid.characters[i]).position;
        REQUIRE(is_finite(p));
        REQUIRE(same_bits(p, reference.world.transform(reference.characters[i]).position));
    }
    CHECK(events > 0); // the scenes touch: the comparison is not vacuous
}

} // namespace

TEST_CASE("the movers' grid gives every step exactly the all-pairs reference's contacts, in the same order") {
    const int rounds = test::iterations(4, 0.5);
    for (float far : {0.0f, 1e5f, -1e5f})
        for (int round = 0; round < rounds; ++round) {
            const Vec3 offset(far, 0.0f, -far);
            const std::uint64_t seed = 100 + static_cast<std::uint64_t>(round);
            CAPTURE(far);
            CAPTURE(round);
            // Scattered over a few cells, some fast enough to cross a cell within a few steps.
            auto scattered = [](int, Rng& rng) {
                return Vec3(rng.uniform(-24, 24), 1.5f, rng.uniform(-24, 24));
            };
            {
                CrowdScene grid(MoverBroadphase::Grid, 120, offset, 30.0f, seed, scattered);
                CrowdScene reference(MoverBroadphase::AllPairs, 120, offset, 30.0f, seed, scattered);
                expect_same_steps(grid, reference, 30);
            }
            // Rows of capsules exactly touching (centres 2 radii apart), lined up on cell borders (multiples
            // of the 8-unit cell) and straddling them.
            auto touching = [](int i, Rng&) {
                return Vec3(-16.0f + 2.0f * static_cast<float>(i % 16), 1.5f,
                            8.0f * static_cast<float>(i / 16 - 2));
            };
            {
                CrowdScene grid(MoverBroadphase::Grid, 80, offset, 4.0f, seed, touching);
                CrowdScene reference(MoverBroadphase::AllPairs, 80, offset, 4.0f, seed, touching);
                expect_same_steps(grid, reference, 20);
            }
            // A crowd packed into one spot of one cell: depenetration pushes some further in a step than the
            // grid's slack (those are then visited by every later query of the step).
            auto packed = [](int, Rng& rng) {
                return Vec3(rng.uniform(3.5f, 4.5f), rng.uniform(1.5f, 3.0f), rng.uniform(3.5f, 4.5f));
            };
            CrowdScene grid(MoverBroadphase::Grid, 60, offset, 10.0f, seed, packed);
            CrowdScene reference(MoverBroadphase::AllPairs, 60, offset, 10.0f, seed, packed);
            expect_same_steps(grid, reference, 30);
        }
}
