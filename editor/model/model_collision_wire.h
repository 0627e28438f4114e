#pragma once
// What a model entity collides with, as line segments for the level viewport's overlay (docs/models.md): the
// edges of its box or hull brush, or every edge of its triangle mesh (each shared edge once), in world space,
// from level/model_entity.h's own collision (so the overlay is what the game collides with).
#include "core/result.h"
#include "level/level.h"

#include <array>
#include <cstddef>
#include <vector>

namespace ks::editor {

// The most segments a triangle-mesh overlay draws: a dense mesh's wire is a solid blur long before this.
inline constexpr std::size_t kMaxCollisionWireSegments = 60'000;

struct CollisionWire {
    std::vector<std::array<Vec3, 2>> segments;
    bool truncated = false; // a mesh with more edges than kMaxCollisionWireSegments: the first ones
};

// The entity's collision as segments: none for "none" and for entities that are not models; an Error when
// the collision cannot be made (the file cannot be read, the hull fails), as level validation says.
Result<CollisionWire> model_collision_wire(const level::Entity& entity);

} // namespace ks::editor
