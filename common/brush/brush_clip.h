#pragma once
// Cutting a brush by a plane. The brush's faces keep their planes and attributes, so their world mapping
// is unchanged (texture lock holds by construction); the cut face gets `cap`.
#include "brush/brush.h"

#include <optional>

namespace ks::brush {

struct Split {
    std::optional<Brush> back;  // behind the plane (where signed_distance < 0)
    std::optional<Brush> front; // in front of it
};

// Both sides; a side is empty when no vertex is more than kOnPlaneEpsilon beyond the plane on that side
// (then the other side is the brush itself). Refused when a side would be a degenerate sliver or the plane
// is not finite.
Result<Split> split(const Brush& brush, const Plane& plane, const FaceAttributes& cap = {});

enum class ClipSide { keep_back, keep_front };

// Where the brush lies against a unit plane: vertices within kOnPlaneEpsilon of it count as on it.
enum class PlaneReach { all_behind, all_in_front, both_sides };
PlaneReach reach(const Brush& brush, const Plane& unit_plane);

// One side; refused when nothing of the brush is on that side.
Result<Brush> clip(const Brush& brush, const Plane& plane, ClipSide side = ClipSide::keep_back,
                   const FaceAttributes& cap = {});

} // namespace ks::brush
