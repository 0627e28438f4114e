#pragma once
// How the viewport shows the logic entities, window-free (the game draws none of them): a spawner as a ring
// on the ground around a robot-sized wire box where its robots appear, a post with a plus on top and an
// arrow the way they face; a message as a speech bubble with lines of text, facing the camera inside its pick
// box; a trigger as its box, whose faces the UI fills translucently. The UI draws the lines; tests check
// them.
#include "geometry/obb.h"
#include "view/sound_marker.h"

#include <array>
#include <vector>

namespace ks::editor {

// `feet` is the spawner's position, `yaw_degrees` its rotation about +y (0 faces -z, as the player start).
void spawner_marker(const Vec3& feet, float yaw_degrees, std::vector<MarkerLine>& out);

// In the plane of the camera's `right` and `up` (unit vectors), centred on `centre`, no farther than
// `half_size` from it along either (level::kLogicMarkerHalfSize: inside the message's pick box).
void message_marker(const Vec3& centre, const Vec3& right, const Vec3& up, float half_size,
                    std::vector<MarkerLine>& out);

// The six faces of a box, each as four corners in order around it.
std::array<std::array<Vec3, 4>, 6> box_faces(const geometry::Obb& box);

} // namespace ks::editor
