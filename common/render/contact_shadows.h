#pragma once
// Contact shadows: what moving things (robots, gas cylinders, pickups, the player's rifle) cast on the floor
// under them. The fast path's level shadows are baked and its shadow map holds only the level, so movers cast
// nothing there, and no path's point or spot lights cast shadows; a mover looked as if it floated. Each
// caster gets one soft ellipse on its floor per light that gives a fair share of the floor's light there,
// stretched away from that light as far as the caster's height projects, as dark as that light's share of
// the floor's irradiance in the light bake's units (hemisphere ambient, the sun, each light's falloff and
// cone, walls blocking), plus a round one at its feet for the sky's ambient light it hides. So a robot under
// a lamp has a round shadow at its feet, one beside a lamp a long one pointing away from it, and one far
// from any lamp only the faint round one. No GL here (tests run it on the CPU); the
// SceneRenderer draws the ellipses (scene_contact_shadows.cpp) on both paths.
#include "geometry/aabb.h"
#include "render/scene.h"

#include <cstddef>
#include <vector>

namespace ks::render {

struct ShadowCaster {
    geometry::Aabb bounds; // world
    float ground = 0.0f;   // the floor's height under it
};

// The caster that the instances from `first` on make (one model's parts, just emitted), standing over
// `ground`; an empty range gives an invalid box, which casts nothing.
ShadowCaster shadow_caster_of(const std::vector<MeshInstance>& instances, std::size_t first, float ground);

// One ellipse on the floor.
struct ContactShadow {
    Vec3 centre{0.0f};        // on the floor
    Vec2 axis{1.0f, 0.0f};    // unit, in xz: away from its light
    float half_length = 0.0f; // along axis
    float half_width = 0.0f;
    float darkness = 0.0f; // 0..1: the share of the floor's light it takes away at the caster's feet
    float feet = 0.0f;     // -1..1 along axis: where the caster stands (the shadow fades from there)
};

// What lights a caster's floor.
struct ShadowLights {
    const Environment* environment = nullptr;
    bool sun = true; // false: the sun has a shadow map (the full path), no contact shadow
    const std::vector<Light>* lights = nullptr;
    const std::vector<int>* candidates = nullptr; // indices into *lights (nullptr: all)
    std::vector<geometry::Aabb> blockers;         // solid boxes (walls, floors) that block lights
    std::vector<geometry::Aabb> sun_blockers;     // those that block the sun (no ceilings)
};

// Diffuse irradiance factor of `light` at `point` on a surface facing `normal`: the reference's linear
// falloff to zero at its range, times the spot cone's smoothstep, times the cosine (no colour, no occlusion).
// The light bake and the contact shadows share it.
float light_reach(const Light& light, const Vec3& point, const Vec3& normal);

// Appends the ellipses of every caster to `out`: one for each of its two strongest lights (when they give a
// fair share of its floor's light), then the ambient one.
void contact_shadows(const std::vector<ShadowCaster>& casters, const ShadowLights& lights,
                     std::vector<ContactShadow>& out);

} // namespace ks::render
