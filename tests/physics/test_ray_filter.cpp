// Shots: the closest-hit query with a filter (layers, an ignored body, a user-data test) returns exactly the
// first hit that collecting every hit (ray_all) and skipping the filtered ones gives, through stacks of
// static boxes, kinematic boxes and characters, when the nearest bodies are filtered out, and on ties
// (equal distances go to the lower body index in both).
#include "physics_scene.h"

#include "core/random.h"

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

namespace {
constexpr std::uint64_t kRobotTag = 7;

bool not_a_robot(std::uint64_t user) {
    return user != kRobotTag;
}

// The reference: every hit in order, the first one the whole filter accepts.
bool first_accepted(const World& w, const geometry::Ray& ray, const RayFilter& filter, RayHit& out) {
    std::vector<RayHit> all;
    w.ray_all(ray, all, HitOrder::Ascending, RayFilter(filter.layers, filter.ignore));
    for (const RayHit& h : all)
        if (!filter.accept_user_data || filter.accept_user_data(w.user_data(h.body))) {
            out = h;
            return true;
        }
    return false;
}

BodyId add_robot(World& w, Vec3 feet) {
    BodyDesc d;
    d.shape = Shape::capsule(0.8f, 0.7f);
    d.transform.position = feet + Vec3(0, 1.5f, 0);
    d.motion = Motion::Character;
    d.layers = layer::kSolid | layer::kShootable | layer::kCharacter;
    d.user_data = kRobotTag;
    auto id = w.add(d, "robot");
    REQUIRE(id.ok());
    return *id;
}

void check_same(const World& w, const geometry::Ray& ray, const RayFilter& filter) {
    RayHit closest, reference;
    const bool a = w.ray_closest(ray, closest, filter), b = first_accepted(w, ray, filter, reference);
    REQUIRE(a == b);
    CHECK(w.ray_any(ray, filter) == b);
    if (!a) return;
    CHECK(closest.body == reference.body);
    CHECK(closest.distance == reference.distance);
    CHECK(closest.point == reference.point);
    CHECK(closest.normal == reference.normal);
}
} // namespace

TEST_CASE("shots through a stack: the filtered closest hit is ray_all's first accepted hit") {
    World w;
    add_floor(w);
    const BodyId shooter = add_player(w, {0, 0, 0});
    // Along -z from the shooter: a robot, a static crate, a second robot, a kinematic door, a wall.
    const BodyId robot_near = add_robot(w, {0, 0, -4});
    const BodyId crate = add_box(w, {0, 1.5f, -8}, {1, 1, 1});
    const BodyId robot_far = add_robot(w, {0, 0, -12});
    BodyDesc door;
    door.shape = Shape::box({2, 3, 0.1f});
    door.transform.position = {0, 3, -16};
    door.motion = Motion::Kinematic;
    const BodyId door_id = *w.add(door, "door");
    const BodyId wall = add_box(w, {0, 4, -20}, {10, 4, 0.25f});
    const geometry::Ray shot{w.transform(shooter).position + Vec3(0, 0.2f, 0), {0, 0, -1}, 500};

    RayFilter player_shot(layer::kShootable, shooter);
    RayHit h;
    REQUIRE(w.ray_closest(shot, h, player_shot));
    CHECK(h.body == robot_near);
    check_same(w, shot, player_shot);

    // A robot's shot along the same line, starting past the shooter, passes through both robots, its own
    // included.
    geometry::Ray line = shot;
    line.origin.z -= 1.5f;
    RayFilter robot_shot(layer::kShootable, robot_near);
    robot_shot.accept_user_data = not_a_robot;
    REQUIRE(w.ray_closest(line, h, robot_shot));
    CHECK(h.body == crate);
    check_same(w, line, robot_shot);
    check_same(w, line, player_shot);

    // The nearest bodies filtered out one by one: the next one back is hit, as ray_all's order says.
    w.set_enabled(crate, false);
    REQUIRE(w.ray_closest(line, h, robot_shot));
    CHECK(h.body == door_id);
    check_same(w, line, robot_shot);
    w.set_enabled(door_id, false);
    REQUIRE(w.ray_closest(line, h, robot_shot));
    CHECK(h.body == wall);
    check_same(w, line, robot_shot);
    check_same(w, shot, player_shot);
    CHECK(w.ray_closest(shot, h, RayFilter(layer::kShootable, robot_near)));
    CHECK(h.body == shooter); // nothing but the ignored body and the test

    // Nothing accepted at all: no hit, and ray_any agrees.
    RayFilter nothing(layer::kShootable, shooter);
    nothing.accept_user_data = [](std::uint64_t) { return false; };
    CHECK_FALSE(w.ray_closest(shot, h, nothing));
    check_same(w, shot, nothing);
    (void)robot_far;
}

TEST_CASE("shots: equal distances go to the lower body index, as in ray_all's order") {
    World w;
    // Two boxes whose front faces are the same plane, overlapping where the shot enters.
    const BodyId first = add_box(w, {0, 0, -5}, {1, 1, 1});
    const BodyId second = add_box(w, {0.5f, 0, -5}, {1, 1, 1});
    const geometry::Ray shot{{0.5f, 0, 0}, {0, 0, -1}, 100};
    RayHit h;
    REQUIRE(w.ray_closest(shot, h));
    CHECK(h.body == first);
    check_same(w, shot, {});
    RayFilter skip_first(layer::kAll & ~layer::kTrigger, first);
    REQUIRE(w.ray_closest(shot, h, skip_first));
    CHECK(h.body == second);
}

TEST_CASE("shots: random rays through a crowd of boxes and characters agree with ray_all's first hit") {
    World w;
    add_floor(w);
    Rng rng(11);
    std::vector<BodyId> robots;
    for (int i = 0; i < 60; ++i)
        add_box(w, {rng.uniform(-30, 30), rng.uniform(0, 6), rng.uniform(-30, 30)},
                {rng.uniform(0.2f, 2), rng.uniform(0.2f, 2), rng.uniform(0.2f, 2)}, rng.uniform(0, 3));
    for (int i = 0; i < 20; ++i)
        robots.push_back(add_robot(w, {rng.uniform(-30, 30), 0, rng.uniform(-30, 30)}));
    for (int i = 0; i < 2000; ++i) {
        const Vec3 origin(rng.uniform(-30, 30), rng.uniform(0.5f, 5), rng.uniform(-30, 30));
        const Vec3 dir =
            glm::normalize(Vec3(rng.uniform(-1, 1), rng.uniform(-0.3f, 0.3f), rng.uniform(-1, 1)));
        const geometry::Ray shot{origin, dir, rng.uniform(5, 100)};
        RayFilter filter(layer::kShootable, robots[static_cast<std::size_t>(i) % robots.size()]);
        if (i % 2) filter.accept_user_data = not_a_robot;
        check_same(w, shot, filter);
    }
}
