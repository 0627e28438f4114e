#pragma once
// Picking and placing with viewport rays (view_camera.h), window-free: the entity whose oriented box a ray
// enters first (geometry::ray_obb), and the point a palette click places at (the surface under the
// cursor, snapped).
#include "model/bounds.h"
#include "model/document.h"
#include "view/view_camera.h"

#include <functional>
#include <optional>

namespace ks::editor {

// Which entities the viewport shows (hidden ones and, unless shown, ceilings are not picked).
using ShownFn = std::function<bool(const level::Entity&)>;

struct PickHit {
    int id = 0; // 0: nothing
    float distance = 0.0f;
};
// The nearest shown, unlocked entity the ray enters.
PickHit pick_entity(const Document& doc, const geometry::Ray& ray, const ShownFn& shown);
// What a click selects: pick_entity, or the player start (id kPlayerStartId) when it is shown and its body
// box is nearer.
PickHit pick_selectable(const Document& doc, const geometry::Ray& ray, const ShownFn& shown,
                        bool player_start_shown);

// Where a palette click places: the first floor, stair or wall the ray meets (its top or face), else the
// ground plane y = 0 in front of the camera, else (a level ray in the front and side views) the plane
// through `fallback` facing the ray. x and z snap to the grid; y stays on the surface.
Vec3 place_point(const Document& doc, const geometry::Ray& ray, const ShownFn& shown, const Vec3& fallback);

// How far above the surface a palette click puts a sound emitter: its position is the point the sound
// comes from, so it goes about where a machine's noise would, and its marker clears the floor.
inline constexpr float kSoundPlaceHeight = 2.0f;
// Where a top light goes when nothing is overhead: as high as a default wall (its fixture at the wall's top).
inline constexpr float kTopLightPlaceHeight = 16.0f;
// The height of what is overhead at `surface`: the underside of the nearest ceiling, floor, stair, wall
// (a lintel) or brush straight above it (hidden ones too: the game has them), if any.
std::optional<float> overhead_height(const Document& doc, const Vec3& surface);
// The position an entity of `type` gets for a palette click whose place_point is `surface`: the surface
// point itself (a bottom centre) for the types that stand on it; a sound emitter kSoundPlaceHeight above
// it; a top light (its position is the ceiling fixture's) under what is overhead, else
// kTopLightPlaceHeight above the surface.
Vec3 placement_for(const Document& doc, level::EntityType type, const Vec3& surface);

} // namespace ks::editor
