#pragma once
// Character controller used by the player and the robots: an upright capsule moved by swept
// collide-and-slide. Each pass sweeps the capsule along what is left of the step's displacement
// (conservative advancement on exact capsule distances, so a 5 cm wall stops a 50 m/s body), stops a skin
// short of the first contact, and clips the rest of the motion against the contact planes seen so far:
// one plane slides along it, two slide along their crease, a third stops. Then it steps up onto ledges
// up to step_height, snaps down to the ground (not while rising from a jump) and resolves any remaining
// overlap (e.g. a door leaf closing on it) by pushing out along the contact normals.
#include "physics/collide.h"
#include "physics/movement.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::physics {

struct CharacterSettings {
    float step_height = 0.65f;       // climbs the 0.6-unit steps of box-built stairs
    float max_slope_degrees = 50.0f; // the stair ramps are 26.6°
    float skin = 0.01f;              // gap kept to surfaces, so resting contact is stable
    float ground_snap = 0.7f;        // follows downward ramps and steps while walking
    int max_slide_planes = 5;
};

struct CharacterState {
    MovementState movement;
    bool grounded = false;
    bool jumping = false; // set by jump(), cleared on landing; disables ground snap while rising
    Vec3 ground_normal{0.0f, 1.0f, 0.0f};
};

// One obstacle as the controller sees it: a shape placed in the world. `id` is opaque to the controller.
struct Obstacle {
    const Shape* shape = nullptr;
    geometry::Transform transform;
    std::uint32_t id = 0;
    bool yaw_only = false; // the rotation turns about y only (is_yaw_only): boxes take the upright fast path
    geometry::Aabb bounds{Vec3(-3.4e38f),
                          Vec3(3.4e38f)}; // world bounds: lets sweeps skip far obstacles cheaply
    // A triangle mesh comes one triangle per obstacle (each convex, so the sweep's advancement holds):
    // which one; kWholeShape for every other shape.
    static constexpr std::uint32_t kWholeShape = 0xffffffffu;
    std::uint32_t triangle = kWholeShape;
};

// The capsule's contact with one obstacle: collide_capsule_shape, or its one triangle of a mesh.
std::optional<Contact> collide_capsule_obstacle(const Segment& s, float r, const Obstacle& o,
                                                float contact_margin = 0.0f);

// A contact the character made during its move (reported to collision callbacks).
struct CharacterContact {
    std::uint32_t obstacle_id = 0;
    Contact contact; // normal points from the obstacle toward the character
};

// Where obstacles come from: the world gathers those whose bounds overlap a box.
class ObstacleSource {
  public:
    virtual ~ObstacleSource() = default;
    virtual void gather(const geometry::Aabb& region, std::vector<Obstacle>& out) const = 0;
};

struct CharacterScratch { // reused across calls: no allocation per step once warm
    std::vector<Obstacle> obstacles;
    std::vector<CharacterContact> contacts;
};

// Moves a capsule (radius, half segment) at `position` by one step of `dt`. Contacts go to scratch.contacts.
void move_character(const ObstacleSource& world, float radius, float half_segment,
                    const CharacterSettings& cs, CharacterState& state, Vec3& position, float dt,
                    CharacterScratch& scratch);

// Time of impact in [0, 1] of a capsule moving by `motion` against one obstacle, stopping `skin` short;
// returns 1 when it does not hit. `normal` gets the contact normal at impact.
// `surface` (optional) gets the obstacle's own face normal at the contact (see surface_normal).
float sweep_capsule(const Segment& s, float radius, const Vec3& motion, const Obstacle& o, float skin,
                    Vec3& normal, Vec3* surface = nullptr);

// The normal of the obstacle's face at a point on its surface; where faces meet (a step's edge) the most
// upward one (a mesh triangle: its face normal on the contact's side; a whole mesh: the contact normal).
// Ground is judged by this, not by the capsule's contact normal: a capsule resting on the edge of a step
// touches it at an angle, yet stands on the step's flat top.
Vec3 surface_normal(const Shape& shape, const geometry::Transform& xf, const Vec3& point,
                    const Vec3& contact_normal);

} // namespace ks::physics
