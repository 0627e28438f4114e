#pragma once
// The area ids Recast stamps on polygons and the flags Detour filters them by: every walkable polygon is
// Walk; doorway polygons are Door too, and a closed door's polygons lose Walk, so the query filter
// (include Walk) steps around them without a rebuild.
#include <cstdint>

namespace ks::nav {

inline constexpr unsigned char kAreaGround = 63; // RC_WALKABLE_AREA
inline constexpr unsigned char kAreaDoor = 1;

enum PolyFlag : std::uint16_t {
    kFlagWalk = 1u << 0,
    kFlagDoor = 1u << 1,
};

} // namespace ks::nav
