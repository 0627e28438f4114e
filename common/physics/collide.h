#pragma once
// Narrowphase: exact overlap tests between the pairs a scene needs.
//   convex–convex   SAT over face normals of both AND edge×edge axes (face-only SAT, the reference's way,
//                   is kept as an option for the benchmark: it reports false contacts for crossed edges)
//   capsule–convex  closest features between the capsule's core segment and the polyhedron
//   capsule–capsule, capsule–cylinder, capsule–box (fast path)  closed-form closest features
// A Contact's normal points from B toward A (push A by normal·penetration to separate); penetration is
// >= 0 and 0 means touching; `point` lies midway between the two surfaces.
#include "physics/shapes.h"

#include <optional>

namespace ks::physics {

struct Contact {
    Vec3 normal{0.0f, 1.0f, 0.0f};
    float penetration = 0.0f;
    Vec3 point{0.0f};
};

enum class SatAxes : std::uint8_t { FacesAndEdges, FacesOnly };

// SAT between two convex polyhedra placed by their transforms. Touching (zero overlap) counts as contact.
std::optional<Contact> collide_convex(const Polyhedron& a, const geometry::Transform& xa, const Polyhedron& b,
                                      const geometry::Transform& xb, SatAxes axes = SatAxes::FacesAndEdges);

// A capsule is the set of points within `radius` of the segment [p0, p1] (world space).
struct Segment {
    Vec3 p0{0.0f};
    Vec3 p1{0.0f};
};
Segment capsule_segment(const Shape& capsule, const Vec3& centre);

// Distance from a world segment to a convex polyhedron (0 when they intersect), with the closest points.
struct SegmentDistance {
    float distance = 0.0f;
    Vec3 on_segment{0.0f};
    Vec3 on_shape{0.0f};
    Vec3 away{
        0.0f}; // on_segment - on_shape, computed in the polyhedron's frame (precise far from the origin)
};
SegmentDistance segment_polyhedron_distance(const Segment& s, const Polyhedron& p, const geometry::Transform& xf);

// Capsule (radius r around segment s) against shapes. `contact_margin` reports contacts up to that gap
// (penetration then is negative: the gap). All return nullopt beyond the margin.
std::optional<Contact> collide_capsule_polyhedron(const Segment& s, float r, const Polyhedron& p,
                                                  const geometry::Transform& xf, float contact_margin = 0.0f);
// Fast path for boxes whose rotation is a pure yaw (every wall, floor and door of a level): the upright
// segment stays axis-aligned in the box frame. Works for any rotation only through the polyhedron path.
std::optional<Contact> collide_capsule_box(const Segment& s, float r, const Vec3& half, const geometry::Transform& xf,
                                           float contact_margin = 0.0f);
std::optional<Contact> collide_capsule_capsule(const Segment& a, float ra, const Segment& b, float rb,
                                               float contact_margin = 0.0f);
// Upright cylinder centred at `centre` with radius/half height.
std::optional<Contact> collide_capsule_cylinder(const Segment& s, float r, const Vec3& centre, float radius,
                                                float half_height, float contact_margin = 0.0f);

// Dispatch for a capsule against any shape (what the character controller uses).
std::optional<Contact> collide_capsule_shape(const Segment& s, float r, const Shape& shape,
                                             const geometry::Transform& xf, float contact_margin = 0.0f);

// True when the rotation is a pure rotation about +y (to 1e-6), so the yaw-only fast paths apply.
bool is_yaw_only(const Quat& q);

// Closest points between segments [p0,p1] and [q0,q1]: parameters s,t in [0,1].
void closest_segment_segment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, float& s,
                             float& t);

} // namespace ks::physics
