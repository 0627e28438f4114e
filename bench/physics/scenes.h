#pragma once
// Generated test scenes shared by the physics benchmarks and tests (header-only, so the tests need no
// bench objects): a "rooms" level of N boxes (floors, ceilings, walls with doorways, crates, some of them
// rotated) and the origin sampler for rays "from random points inside the rooms".
#include "core/math.h"
#include "core/random.h"
#include "physics/world.h"

#include <cmath>
#include <vector>

namespace ks::physics::scenes {

struct SceneBox {
    Vec3 centre{0.0f};
    Vec3 half{0.5f};
    float yaw = 0.0f; // radians about +y
    Quat rotation() const { return yaw == 0.0f ? Quat(1, 0, 0, 0) : glm::angleAxis(yaw, Vec3(0, 1, 0)); }
};

struct Room {
    Vec3 min{0.0f}, max{0.0f}; // interior air
    std::size_t first_crate = 0, crate_count = 0;
};

struct RoomsScene {
    std::vector<SceneBox> boxes;
    std::vector<Room> rooms;
};

inline constexpr float kRoomSize = 24.0f, kWallHeight = 16.0f, kWallHalfThickness = 0.25f, kDoorWidth = 4.0f,
                       kDoorHeight = 5.0f;

// About `target_boxes` boxes: 20 per room (floor, ceiling, 6 wall pieces, 12 crates) on a square grid.
inline RoomsScene make_rooms(int target_boxes, std::uint64_t seed = 1) {
    RoomsScene s;
    const int room_count = std::max(1, target_boxes / 20);
    const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(room_count)))));
    Rng rng(seed);
    auto wall = [&](Vec3 a, Vec3 b, float y0, float y1) { // axis-aligned slab along a->b
        Vec3 c = (a + b) * 0.5f;
        Vec3 h = glm::abs(b - a) * 0.5f + Vec3(kWallHalfThickness, 0, kWallHalfThickness);
        h.y = (y1 - y0) * 0.5f;
        c.y = (y0 + y1) * 0.5f;
        s.boxes.push_back({c, h, 0.0f});
    };
    // A wall from a to b (along x or z) with a centred doorway.
    auto wall_with_door = [&](Vec3 a, Vec3 b) {
        const Vec3 dir = glm::normalize(b - a);
        const float len = glm::length(b - a);
        const Vec3 d0 = a + dir * ((len - kDoorWidth) * 0.5f), d1 = a + dir * ((len + kDoorWidth) * 0.5f);
        wall(a, d0, 0.0f, kWallHeight);
        wall(d1, b, 0.0f, kWallHeight);
        wall(d0, d1, kDoorHeight, kWallHeight); // lintel
    };
    for (int r = 0; r < room_count; ++r) {
        const float x0 = (r % side) * kRoomSize, z0 = (r / side) * kRoomSize;
        const float x1 = x0 + kRoomSize, z1 = z0 + kRoomSize;
        s.boxes.push_back(
            {{(x0 + x1) * 0.5f, -0.25f, (z0 + z1) * 0.5f}, {kRoomSize * 0.5f, 0.25f, kRoomSize * 0.5f}});
        s.boxes.push_back({{(x0 + x1) * 0.5f, kWallHeight + 0.25f, (z0 + z1) * 0.5f},
                           {kRoomSize * 0.5f, 0.25f, kRoomSize * 0.5f}});
        wall_with_door({x0, 0, z0}, {x1, 0, z0});
        wall_with_door({x0, 0, z0}, {x0, 0, z1});
        if (r % side == side - 1 || r + 1 >= room_count) wall({x1, 0, z0}, {x1, 0, z1}, 0, kWallHeight);
        if (r / side == side - 1 || r + side >= room_count) wall({x0, 0, z1}, {x1, 0, z1}, 0, kWallHeight);
        Room room{{x0 + kWallHalfThickness, 0.0f, z0 + kWallHalfThickness},
                  {x1 - kWallHalfThickness, kWallHeight, z1 - kWallHalfThickness},
                  s.boxes.size(),
                  12};
        for (int c = 0; c < 12; ++c) {
            const Vec3 half(rng.uniform(0.4f, 2.0f), rng.uniform(0.4f, 2.0f), rng.uniform(0.4f, 2.0f));
            const Vec3 centre(rng.uniform(x0 + 3.0f, x1 - 3.0f), half.y, rng.uniform(z0 + 3.0f, z1 - 3.0f));
            const float yaw = rng.chance(0.3f) ? rng.uniform(0.0f, kPi) : 0.0f;
            s.boxes.push_back({centre, half, yaw});
        }
        s.rooms.push_back(room);
    }
    return s;
}

// Is p inside crate `b` (its oriented box)?
inline bool inside(const SceneBox& b, const Vec3& p) {
    const Vec3 l = glm::conjugate(b.rotation()) * (p - b.centre);
    return std::abs(l.x) <= b.half.x && std::abs(l.y) <= b.half.y && std::abs(l.z) <= b.half.z;
}

inline Vec3 random_direction(Rng& rng) {
    for (;;) {
        const Vec3 v(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f));
        const float l2 = glm::dot(v, v);
        if (l2 > 1e-4f && l2 <= 1.0f) return v / std::sqrt(l2);
    }
}

// A random point in the air of a random room (not inside a crate).
inline Vec3 random_origin(const RoomsScene& s, Rng& rng) {
    for (;;) {
        const Room& r = s.rooms[rng.below(static_cast<std::uint32_t>(s.rooms.size()))];
        const Vec3 p(rng.uniform(r.min.x, r.max.x), rng.uniform(0.05f, kWallHeight - 0.05f),
                     rng.uniform(r.min.z, r.max.z));
        bool blocked = false;
        for (std::size_t i = r.first_crate; i < r.first_crate + r.crate_count; ++i)
            blocked |= inside(s.boxes[i], p);
        if (!blocked) return p;
    }
}

inline void add_to_world(const RoomsScene& s, World& world, std::vector<BodyId>* ids = nullptr) {
    for (const SceneBox& b : s.boxes) {
        BodyDesc d;
        d.shape = Shape::box(b.half);
        d.transform = {b.centre, b.rotation()};
        auto id = world.add(d, "generated box");
        if (ids && id) ids->push_back(*id);
    }
    world.build_static();
}

} // namespace ks::physics::scenes
