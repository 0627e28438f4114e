#pragma once
// A plane in double precision, the unit a brush is stored as: points p with dot(normal, p) == distance;
// the outside of a brush face is where dot(normal, p) > distance. Normals are unit length.
#include "core/math.h"

#include <optional>

namespace ks::brush {

// Tolerances of brush geometry, in world units. Coordinates are limited to +-kMaxCoordinate so that every
// derived vertex keeps about 1e-11 absolute precision (double has 53 bits; 2^16 leaves ~36 for fractions).
inline constexpr double kMaxCoordinate = 65536.0;
// A point closer than this to a plane is on it (classification while deriving, clipping and CSG). Deriving
// loses about 1e-10 at the world's edge, so this is 100 times the noise and 10 000 times below the thinnest
// sliver a brush may have (1e-4 is tested).
inline constexpr double kOnPlaneEpsilon = 1e-8;
// Derived vertices closer than this are one vertex.
inline constexpr double kWeldDistance = 1e-8;
// Two unit normals whose cross product is shorter than this (their angle in radians, about) are parallel:
// planes derived from the same points differ by about 1e-16, and a plane 1e-6 rad off another is not one.
inline constexpr double kSameNormal = 1e-12;

struct Plane {
    DVec3 normal{0.0, 0.0, 1.0};
    double distance = 0.0;

    double signed_distance(const DVec3& p) const { return glm::dot(normal, p) - distance; }
    Plane flipped() const { return {-normal, -distance}; }
    Plane translated(const DVec3& delta) const { return {normal, distance + glm::dot(normal, delta)}; }
    bool operator==(const Plane&) const = default;
};

// The plane through a, b, c whose normal follows the right hand (a->b->c counter-clockwise seen from the
// outside); nullopt when the points are collinear. Computed from the shortest two edges' cross product to
// keep the normal's rounding small.
std::optional<Plane> plane_from_points(const DVec3& a, const DVec3& b, const DVec3& c);

// The point on all three planes, or nullopt when |det| of their normals is below min_det (nearly parallel).
std::optional<DVec3> intersect_planes(const Plane& a, const Plane& b, const Plane& c, double min_det = 1e-12);

bool is_finite(const DVec3& v);

// Unit normals pointing the same way (within kSameNormal).
inline bool same_direction(const DVec3& a, const DVec3& b) {
    return glm::dot(a, b) > 0.0 && glm::length(glm::cross(a, b)) <= kSameNormal;
}
// The same plane: same direction and distances within kOnPlaneEpsilon.
inline bool same_plane(const Plane& a, const Plane& b) {
    return same_direction(a.normal, b.normal) && std::abs(a.distance - b.distance) <= kOnPlaneEpsilon;
}

} // namespace ks::brush
