#pragma once
// The boxes the editor reasons with: every entity's oriented bounding box (from its size properties, or the
// model dimensions of the shared asset conventions where it has none; the box types and their overlap test
// are geometry/obb.h), and the floor/stair surfaces an entity can stand on. Used by validation, box select
// and the UI's selection outlines.
#include "geometry/obb.h"
#include "level/entity_shapes.h"
#include "level/level.h"
#include "physics/character.h"

#include <memory>
#include <optional>
#include <vector>

namespace ks::editor {

// The entity's box in world space. Positions are bottom centres (floors: the walking surface).
geometry::Obb entity_obb(const level::Entity& entity);
// The world box around the entities' boxes: what F frames, a prefab thumbnail's camera, an entered group's
// outline. geometry::Aabb::empty() (not valid()) when there are none.
geometry::Aabb selection_bounds(const std::vector<const level::Entity*>& entities);
geometry::Aabb selection_bounds(const std::vector<level::Entity>& entities);
// The player's standing body at the start: radius 1, height 3 (seed facts §5.1), as a box.
geometry::Obb player_obb(const level::PlayerStart& start);

// The walkable top at (x, z) of a floor (not a ceiling) or a stair, if that point is over it.
std::optional<float> surface_height_at(const level::Entity& support, float x, float z);
// The same with the support's box already computed (entity_obb(support)), for loops over many points.
// `stair_as_ramp`: a stair's collision in the game is a wedge (common/physics shapes.h), so walking follows
// the ramp through the tread edges rather than the visible treads.
std::optional<float> surface_height_at(const level::Entity& support, const geometry::Obb& box, float x,
                                       float z, bool stair_as_ramp = false);

// Something an entity can stand on, with what its height query needs made once: a floor (not a ceiling), a
// stair, or a brush (the top of its world brush over the point: a platform's top, a ramp's slope).
class SupportSurface {
  public:
    // nullopt when `entity` is none of those (or a brush that cannot be placed in the world).
    static std::optional<SupportSurface> of(const level::Entity& entity);
    // A brush entity's surface from its world brush made already (level::world_brush), so a caller that
    // needs the brush for other questions builds it once.
    static SupportSurface of_brush(const level::Entity& entity, std::shared_ptr<const brush::Brush> world);
    const level::Entity& entity() const { return *entity_; }
    const geometry::Obb& box() const { return box_; }
    // The walkable top at (x, z), if that point is over the surface (surface_height_at's rule for floors
    // and stairs).
    std::optional<float> height_at(float x, float z, bool stair_as_ramp = false) const;

  private:
    SupportSurface(const level::Entity& entity, geometry::Obb box) : entity_(&entity), box_(box) {}
    const level::Entity* entity_;
    geometry::Obb box_;
    std::shared_ptr<const brush::Brush> world_brush_; // brushes only
};

// The character limits the editor's rules use: the player's body (seed facts §5.1) and the game's own
// character-controller settings (common/physics/character.h), so the editor and the game agree.
struct CharacterLimits {
    float radius = level::kPlayerRadius;
    float height = level::kPlayerHeight;
    float max_slope_degrees = physics::CharacterSettings{}.max_slope_degrees;
    float step_height = physics::CharacterSettings{}.step_height;
};

} // namespace ks::editor
