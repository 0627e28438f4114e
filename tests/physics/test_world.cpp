// The world: handles with generations, bad input as errors, collision callbacks with the reference's
// arguments, adding/removing inside callbacks, trigger enter/stay/exit, and ray queries (closest, any, all
// sorted, masks, ignore, disabled) checked against brute force on a generated 2k-box level.
#include "physics_scene.h"

#include "bench/physics/ray_reference.h"
#include "bench/physics/scenes.h"
#include "core/log.h"

#include <cmath>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

TEST_CASE("handles: removed bodies stop resolving, slots are reused with a new generation") {
    World w;
    BodyId a = add_box(w, {0, 0, 0}, {1, 1, 1});
    CHECK(w.valid(a));
    w.remove(a);
    CHECK_FALSE(w.valid(a));
    w.remove(a); // twice: harmless
    BodyId b = add_box(w, {5, 0, 0}, {1, 1, 1});
    CHECK(b.index == a.index);
    CHECK(b.generation != a.generation);
    CHECK_FALSE(w.valid(a));
    CHECK(w.transform(b).position == Vec3(5, 0, 0));
    CHECK(w.body_count() == 1);
}

TEST_CASE("bad bodies are refused with an error naming the body") {
    World w;
    BodyDesc d;
    d.shape = Shape::box({1, 1, 1});
    d.transform.position = {NAN, 0, 0};
    auto r = w.add(d, "entities[4] (crate)");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str().find("entities[4] (crate)") != std::string::npos);
    d.transform.position = {0, 0, 2e7f};
    CHECK_FALSE(w.add(d, "far").ok());
    d.transform.position = {0, 0, 0};
    d.transform.rotation = Quat(0, 0, 0, 0);
    CHECK_FALSE(w.add(d, "rot").ok());
    d.transform.rotation = Quat(1, 0, 0, 0);
    d.motion = Motion::Character;
    CHECK(w.add(d, "robot").error().message.find("capsule") != std::string::npos);
    d.shape = Shape::box({1, 0, 1});
    d.motion = Motion::Static;
    CHECK_FALSE(w.add(d, "flat wall").ok());
    CHECK(w.body_count() == 0);
}

TEST_CASE("collision callbacks get (other, point, normal, penetration, dt) on both bodies") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        BodyId floor = add_floor(w);
        BodyId p = add_player(w, {0, 2, 0});
        std::vector<Collision> on_floor, on_player;
        w.set_on_collision(floor, [&](World&, const Collision& c) { on_floor.push_back(c); });
        w.set_on_collision(p, [&](World&, const Collision& c) { on_player.push_back(c); });
        for (int i = 0; i < hz; ++i) w.step(1.0f / hz);
        REQUIRE_FALSE(on_floor.empty());
        REQUIRE(on_floor.size() == on_player.size());
        const Collision& c = on_player.back();
        CHECK(c.self == p);
        CHECK(c.other == floor);
        CHECK(c.normal.y == doctest::Approx(1.0f)); // from the floor toward the player
        CHECK(c.penetration == doctest::Approx(0.0f));
        CHECK(c.point.y == doctest::Approx(0.005f).epsilon(1e-2)); // midway across the skin gap
        CHECK(c.dt == doctest::Approx(1.0f / hz));
        CHECK(on_floor.back().normal.y == doctest::Approx(-1.0f));
        CHECK(on_floor.back().other == p);
        CHECK(w.collisions().size() == 2); // this step: one contact, reported to both sides
    }
}

TEST_CASE("removing and adding bodies inside callbacks is safe") {
    World w;
    BodyId floor = add_floor(w);
    BodyId p = add_player(w, {0, 0, 0});
    int calls = 0;
    std::vector<BodyId> spawned;
    w.set_on_collision(floor, [&](World& world, const Collision&) {
        ++calls;
        world.remove(floor); // the floor disappears (like a collected pickup)
        for (int i = 0; i < 50; ++i) spawned.push_back(add_box(world, {100.0f + i * 3, 0, 0}, {1, 1, 1}));
    });
    w.set_on_collision(p, [&](World& world, const Collision& c) {
        if (c.other == floor) CHECK(world.valid(c.other) == (calls == 0));
    });
    for (int i = 0; i < 60; ++i) w.step(1.0f / 120.0f);
    CHECK(calls == 1);
    CHECK_FALSE(w.valid(floor));
    CHECK_FALSE(w.character(p).grounded); // falling now
    CHECK(feet_y(w, p) < -0.5f);
    for (BodyId b : spawned) CHECK(w.valid(b));
}

TEST_CASE("triggers fire enter once, stay while inside, exit once; removal inside the callback is safe") {
    for (int hz : kRates) {
        CAPTURE(hz);
        World w(at_rate(hz));
        add_floor(w);
        BodyDesc t;
        t.shape = Shape::box({1, 1, 1});
        t.transform.position = {10, 1, 0};
        t.trigger = true;
        BodyId pickup = *w.add(t, "pickup");
        t.transform.position = {20, 1, 0};
        BodyId mine = *w.add(t, "mine");
        BodyId p = add_player(w, {0, 0, 0});
        int enter = 0, stay = 0, exit = 0, mine_events = 0;
        w.set_on_trigger(pickup, [&](World&, const TriggerEvent& e) {
            CHECK(e.trigger == pickup);
            CHECK(e.other == p);
            if (e.kind == TriggerEvent::Kind::Enter) ++enter;
            if (e.kind == TriggerEvent::Kind::Stay) ++stay;
            if (e.kind == TriggerEvent::Kind::Exit) ++exit;
        });
        w.set_on_trigger(mine, [&](World& world, const TriggerEvent&) {
            ++mine_events;
            world.remove(mine);
        });
        w.character(p).movement.velocity = {15, 0, 0};
        for (int i = 0; i < 2 * hz; ++i) w.step(1.0f / hz);
        CHECK(enter == 1);
        CHECK(exit == 1);
        CHECK(stay > 0);
        CHECK(mine_events == 1);
        CHECK(w.transform(p).position.x > 25.0f); // triggers never block
    }
}

TEST_CASE("disabled bodies are skipped by steps and queries; kinematic doors push characters out") {
    World w;
    add_floor(w);
    BodyDesc door;
    door.shape = Shape::box({2.5f, 2.5f, 0.25f});
    door.transform.position = {0, 2.5f, -5};
    door.motion = Motion::Kinematic;
    BodyId leaf = *w.add(door, "door leaf");
    BodyId p = add_player(w, {0, 0, 0});
    RayHit hit;
    CHECK(w.ray_closest({{0, 2, -10}, {0, 0, 1}, 100}, hit));
    CHECK(hit.body == leaf);
    w.set_enabled(leaf, false);
    CHECK(w.ray_closest({{0, 2, -10}, {0, 0, 1}, 100}, hit));
    CHECK(hit.body == p);
    w.set_enabled(leaf, true);
    // The door slides onto the player: the player is pushed out, not left inside.
    w.set_transform(leaf, {{0, 2.5f, -0.5f}, Quat(1, 0, 0, 0)});
    w.step(1.0f / 120.0f);
    CHECK(std::abs(w.transform(p).position.z - (-0.5f)) >= 1.25f - 1e-3f);
}

TEST_CASE("world rays on a generated 2k-box level match brute force in double precision") {
    const auto scene = scenes::make_rooms(2000, 5);
    World w;
    std::vector<BodyId> ids;
    scenes::add_to_world(scene, w, &ids);
    REQUIRE(ids.size() == scene.boxes.size());
    std::vector<reference::RefBox> ref;
    for (const auto& b : scene.boxes)
        ref.push_back({DVec3(b.centre), glm::dquat(b.rotation()), DVec3(b.half)});
    Rng rng(99);
    int mismatches = 0, hits = 0;
    std::vector<RayHit> all;
    for (int i = 0; i < 20000; ++i) {
        const geometry::Ray r{scenes::random_origin(scene, rng), scenes::random_direction(rng), 100.0f};
        RayHit h;
        const bool hit = w.ray_closest(r, h);
        const auto want = reference::closest(DVec3(r.origin), DVec3(r.direction), ref, r.max_distance);
        if (hit != (want.index >= 0) || (hit && std::abs(h.distance - want.distance) > 1e-3)) ++mismatches;
        hits += hit;
        CHECK(w.ray_any(r) == hit);
        if (i % 50 == 0) {
            all.clear();
            const int n = w.ray_all(r, all, HitOrder::Ascending);
            int expected = 0;
            for (const auto& b : ref)
                expected += reference::ray_box(DVec3(r.origin), DVec3(r.direction), b, 100.0) >= 0.0;
            CHECK(n == expected);
            for (int k = 1; k < n; ++k) CHECK(all[k - 1].distance <= all[k].distance);
            if (n > 0) CHECK(all[0].distance == h.distance); // (ties at shared faces may name either body)
            all.clear();
            w.ray_all(r, all, HitOrder::Descending);
            for (int k = 1; k < n; ++k) CHECK(all[k - 1].distance >= all[k].distance);
        }
    }
    CHECK(mismatches == 0);
    CHECK(hits > 19000);
}

TEST_CASE("world rays (SIMD leaf prefilter) give bit-identical distances to the scalar shape tests") {
    // The BVH leaves test four axis-aligned boxes at once and run the exact scalar test only on the lanes
    // that pass; a lane the prefilter dropped wrongly would change a distance here. Rays aimed exactly at
    // box corners and edge midpoints put the prefilter on its boundary.
    const auto scene = scenes::make_rooms(400, 11);
    World w;
    std::vector<BodyId> ids;
    scenes::add_to_world(scene, w, &ids);
    Rng rng(5);
    int checked = 0, hits = 0;
    for (std::size_t bi = 0; bi < scene.boxes.size(); ++bi) {
        const auto& b = scene.boxes[bi];
        const Quat q = b.rotation();
        for (int k = 0; k < 8; ++k) {
            const Vec3 corner =
                b.centre + q * (b.half * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
            const Vec3 edge = b.centre + q * (b.half * Vec3(k & 1 ? 1 : -1, 0, k & 4 ? 1 : -1));
            for (const Vec3& target : {corner, edge}) {
                const Vec3 o = target + scenes::random_direction(rng) * rng.uniform(0.5f, 10.0f);
                const geometry::Ray r{o, glm::normalize(target - o), 100.0f};
                float want = r.max_distance;
                bool want_hit = false;
                for (BodyId id : ids) {
                    ShapeHit h;
                    geometry::Ray shrunk = r;
                    shrunk.max_distance = want;
                    if (ray_shape(shrunk, w.shape(id), w.transform(id), h) &&
                        (h.distance < want || !want_hit))
                        want = h.distance, want_hit = true;
                }
                RayHit got;
                const bool hit = w.ray_closest(r, got);
                CHECK(hit == want_hit);
                if (hit && want_hit) CHECK(got.distance == want);
                CHECK(w.ray_any(r) == want_hit);
                ++checked;
                hits += hit;
            }
        }
    }
    CHECK(checked == static_cast<int>(scene.boxes.size()) * 16);
    CHECK(hits > checked / 2);
}

TEST_CASE("ray layer masks and ignore: a shot skips the shooter, sight rays skip non-blocking bodies") {
    World w;
    add_floor(w);
    BodyId p = add_player(w, {0, 0, 0});
    BodyDesc glass;
    glass.shape = Shape::box({5, 5, 0.1f});
    glass.transform.position = {0, 2, -5};
    glass.layers = layer::kSolid | layer::kShootable; // does not block sight
    BodyId pane = *w.add(glass, "glass");
    BodyId wall = add_box(w, {0, 2, -10}, {5, 5, 0.25f});
    const geometry::Ray shot{w.transform(p).position + Vec3(0, 1.5f, 0), {0, 0, -1}, 500};
    RayHit h;
    REQUIRE(w.ray_closest(shot, h)); // starts inside its own capsule
    CHECK(h.body == p);
    CHECK(h.distance == 0.0f);
    REQUIRE(w.ray_closest(shot, h, {layer::kAll & ~layer::kTrigger, p}));
    CHECK(h.body == pane);
    REQUIRE(w.ray_closest(shot, h, {layer::kBlocksSight, p}));
    CHECK(h.body == wall);
    CHECK(h.normal.z == doctest::Approx(1.0f));
    CHECK(h.point.z == doctest::Approx(-9.75f));
    CHECK_FALSE(w.ray_any({{0, 2, 5}, {0, 0, 1}, 100}));
    CHECK_FALSE(w.ray_closest({{NAN, 0, 0}, {0, 0, 1}, 100}, h)); // bad ray: no hit, no crash
}

TEST_CASE(
    "triggers never block rays or overlap checks unless asked for; bad character handles do not crash") {
    World w;
    BodyDesc t;
    t.shape = Shape::box({2, 2, 2});
    t.transform.position = {0, 2, -5};
    t.trigger = true;
    BodyId pickup = *w.add(t, "pickup");
    t.motion = Motion::Kinematic;
    t.transform.position = {0, 2, -10};
    BodyId sensor = *w.add(t, "door sensor");
    BodyId wall = add_box(w, {0, 2, -20}, {5, 5, 0.25f});
    RayHit h;
    REQUIRE(w.ray_closest({{0, 2, 0}, {0, 0, -1}, 100}, h));
    CHECK(h.body == wall);
    REQUIRE(w.ray_closest({{0, 2, 0}, {0, 0, -1}, 100}, h, {layer::kTrigger}));
    CHECK(h.body == pickup);
    REQUIRE(w.ray_closest({{0, 2, -7.5f}, {0, 0, -1}, 100}, h, {layer::kTrigger}));
    CHECK(h.body == sensor);
    std::vector<BodyId> overlaps;
    CHECK(w.overlap_capsule({{0, 1.5f, -5}, {0, 2.5f, -5}}, 1.0f, overlaps) == 0);
    CHECK(w.overlap_capsule({{0, 1.5f, -5}, {0, 2.5f, -5}}, 1.0f, overlaps, layer::kTrigger) == 1);
    ks::log::Capture capture;
    w.character(wall).movement.velocity = {1, 2, 3}; // not a character: a warning, no crash
    w.remove(pickup);
    CHECK_FALSE(w.character(pickup).grounded);
    CHECK(capture.text().find("not a live character") != std::string::npos);
}
