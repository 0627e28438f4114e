#pragma once
// The boxes the editor reasons with: every entity's oriented bounding box (from its size properties, or the
// model dimensions of the shared asset conventions where it has none), world AABBs for picking and box
// selection, an exact separating-axis overlap test with penetration depth, and the floor/stair surfaces an
// entity can stand on. Used by validation, box select and the UI's selection outlines.
#include "level/level.h"
#include "physics/character.h"

#include <optional>

namespace ks::editor {

struct Aabb {
    Vec3 min{0.0f};
    Vec3 max{0.0f};
    bool intersects(const Aabb& o) const {
        return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y &&
               min.z <= o.max.z && o.min.z <= max.z;
    }
    bool contains(const Vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
    }
};

struct Obb {
    Vec3 center{0.0f};
    Mat3 axes{1.0f}; // columns: the box's local x, y, z in world space (orthonormal)
    Vec3 half{0.0f};
    Aabb aabb() const;
    bool contains(const Vec3& p, float margin = 0.0f) const;
    Vec3 to_local(const Vec3& p) const; // coordinates along the box axes, relative to the centre
};

// The entity's box in world space. Positions are bottom centres (floors: the walking surface).
Obb entity_obb(const level::Entity& entity);
// The player's standing body at the start: radius 1, height 3 (seed facts §5.1), as a box.
Obb player_obb(const level::PlayerStart& start);

struct Overlap {
    bool overlapping = false;
    float depth = 0.0f; // smallest penetration over the separating axes (0 when apart or touching)
    Vec3 axis{0.0f};    // unit axis of that smallest penetration, pointing from b toward a
};
// Separating-axis test of two oriented boxes (15 axes; near-parallel edge pairs are skipped, their face
// axes already decide). Boxes that only touch (depth <= tolerance) do not overlap.
Overlap obb_overlap(const Obb& a, const Obb& b, float tolerance = 1e-3f);

// The walkable top at (x, z) of a floor (not a ceiling) or a stair, if that point is over it.
std::optional<float> surface_height_at(const level::Entity& support, float x, float z);
// The same with the support's box already computed (entity_obb(support)), for loops over many points.
// `stair_as_ramp`: a stair's collision in the game is a wedge (common/physics shapes.h), so walking follows
// the ramp through the tread edges rather than the visible treads.
std::optional<float> surface_height_at(const level::Entity& support, const Obb& box, float x, float z,
                                       bool stair_as_ramp = false);

// The character limits the editor's rules use: the player's body (seed facts §5.1) and the game's own
// character-controller settings (common/physics/character.h), so the editor and the game agree.
struct CharacterLimits {
    float radius = 1.0f;
    float height = 3.0f;
    float max_slope_degrees = physics::CharacterSettings{}.max_slope_degrees;
    float step_height = physics::CharacterSettings{}.step_height;
};

} // namespace ks::editor
