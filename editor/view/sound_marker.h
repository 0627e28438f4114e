#pragma once
// How the viewport shows a sound emitter, window-free (the renderer draws nothing for it: it is heard, not
// seen): a speaker icon facing the camera inside the emitter's marker box, and the distance it is heard
// within as a wire sphere. The UI draws the lines; the tests check their shape.
#include "core/math.h"

#include <vector>

namespace ks::editor {

struct MarkerLine {
    Vec3 a{0.0f}, b{0.0f};
};

// A speaker (magnet, flared horn, two arcs of sound) in the plane of the camera's `right` and `up` (unit
// vectors), centred on `centre`, no farther than `half_size` from it along either: inside the marker box
// (level::kSoundMarkerHalfSize) from every view.
void speaker_icon(const Vec3& centre, const Vec3& right, const Vec3& up, float half_size,
                  std::vector<MarkerLine>& out);

// Three great circles of `radius` around `centre` (horizontal, and the two upright ones along x and z), each
// of `segments` lines: reads as a sphere from any view, a circle from the top.
void wire_sphere(const Vec3& centre, float radius, int segments, std::vector<MarkerLine>& out);

} // namespace ks::editor
