#pragma once
// The player start as a viewport object, window-free: the figure drawn for it (a capsule the player's body
// size, an arrow on the floor and a chevron at eye height pointing where the player faces) and picking it
// with a ray. The UI draws the lines; the tests check their shape.
#include "geometry/ray.h"
#include "model/document.h"
#include "view/sound_marker.h"

#include <optional>

namespace ks::editor {

// Where the start's facing arrow ends on the floor and at eye height, and the figure's lines: a capsule of
// level::kPlayerRadius standing level::kPlayerHeight tall on the start (rings and meridians), the floor
// arrow (three units from the centre) and the eye chevron just outside the body.
inline constexpr float kStartArrowLength = 3.0f;
inline constexpr float kStartEyeHeight = 2.6f;
Vec3 player_start_facing(const level::PlayerStart& start); // unit vector; yaw 0 faces -z
void player_start_figure(const level::PlayerStart& start, std::vector<MarkerLine>& out);

// The distance along `ray` to the start's body box (bounds.h, player_obb), or nullopt when it misses.
std::optional<float> pick_player_start(const level::PlayerStart& start, const geometry::Ray& ray);

} // namespace ks::editor
