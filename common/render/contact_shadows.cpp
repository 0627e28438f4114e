#include "render/contact_shadows.h"

#include "geometry/ray.h"
#include "render/gpu_mesh.h"

#include <algorithm>
#include <cmath>

namespace ks::render {

namespace {
// A light's shadow takes its whole share away at the core (the edges are soft).
constexpr float kStrength = 1.0f;
// The share of the sky's ambient light a caster hides from the floor at its feet.
constexpr float kOcclusion = 0.5f;
constexpr float kMinShare = 0.08f;  // a light giving less than this of the floor's light casts nothing
constexpr float kLift = 0.05f;      // rays leave the floor by this much (the floor's own box does not block)
constexpr float kMaxStretch = 3.0f; // a shadow reaches at most this many caster heights from its feet
constexpr int kPerCaster = 2;
constexpr int kMaxSources = 40; // the sun and the lights in view (SceneRenderer keeps at most 32)

float luminance(const Vec3& c) {
    return glm::dot(c, Vec3(0.2126f, 0.7152f, 0.0722f));
}

bool blocked(const std::vector<geometry::Aabb>& boxes, const Vec3& from, const Vec3& dir, float length) {
    const Vec3 inv = geometry::safe_inverse(dir);
    float t = 0.0f;
    for (const auto& b : boxes)
        if (geometry::ray_aabb(from, inv, b.min, b.max, length, t)) return true;
    return false;
}

// A light source as seen from one caster's floor: its irradiance there and where it throws a point of the
// caster at height y above the floor (horizontal offset from the feet).
struct Source {
    float irradiance = 0.0f;
    Vec2 away{0.0f};     // horizontal offset of the shadow per unit of height (sun) or the light's xz (point)
    float height = 0.0f; // the light above the floor (points); 0 for the sun
    bool sun = false;

    Vec2 offset_at(float y, const Vec2& feet, float cap) const {
        if (sun) return away * y;
        const Vec2 d = feet - away;
        const float len = glm::length(d);
        if (len < 1e-4f) return Vec2(0.0f);
        if (height <= y + 1e-3f) return d / len * cap; // the light is below this point: as long as allowed
        const Vec2 off = d * (y / (height - y));
        const float off_len = glm::length(off);
        return off_len > cap ? off * (cap / off_len) : off;
    }
};
} // namespace

float light_reach(const Light& l, const Vec3& p, const Vec3& n) {
    const Vec3 to_light = l.position - p;
    const float dist = glm::length(to_light);
    if (!(dist < l.range) || dist < 1e-4f) return 0.0f;
    const Vec3 dir = to_light / dist;
    const float cosine = glm::dot(n, dir);
    if (cosine <= 0.0f) return 0.0f;
    float atten = 1.0f - dist / l.range;
    if (l.type == Light::Type::Spot) {
        const float inner = std::max(l.cos_inner, l.cos_outer + 1e-3f);
        const float x = std::clamp(
            (glm::dot(-dir, glm::normalize(l.direction)) - l.cos_outer) / (inner - l.cos_outer), 0.0f, 1.0f);
        atten *= x * x * (3.0f - 2.0f * x); // GLSL smoothstep
    }
    return atten > 0.0f ? atten * cosine : 0.0f;
}

ShadowCaster shadow_caster_of(const std::vector<MeshInstance>& instances, std::size_t first, float ground) {
    ShadowCaster c;
    c.bounds = geometry::Aabb::empty();
    c.ground = ground;
    for (std::size_t i = first; i < instances.size(); ++i)
        if (instances[i].mesh && instances[i].casts_shadow)
            c.bounds = geometry::merge(
                c.bounds, geometry::transform_aabb(instances[i].mesh->bounds(), instances[i].world));
    return c;
}

void contact_shadows(const std::vector<ShadowCaster>& casters, const ShadowLights& in,
                     std::vector<ContactShadow>& out) {
    if (!in.environment) return;
    const Environment& env = *in.environment;
    const Vec3 up(0.0f, 1.0f, 0.0f);
    const Vec3 to_sun = -glm::normalize(env.sun_direction);
    const bool sun_on = in.sun && luminance(env.sun_color) > 0.0f && is_finite(to_sun) && to_sun.y > 1e-3f;
    const float ambient = luminance(env.sky_color); // the hemisphere ambient on an upward face
    Source sources[kMaxSources];
    for (const ShadowCaster& c : casters) {
        if (!c.bounds.valid() || !is_finite(c.ground) || !is_finite(c.bounds.min) || !is_finite(c.bounds.max))
            continue;
        const Vec2 feet(c.bounds.center().x, c.bounds.center().z);
        const Vec3 probe(feet.x, c.ground + kLift, feet.y);
        const float bottom = std::max(c.bounds.min.y - c.ground, 0.0f);
        const float top = std::max(c.bounds.max.y - c.ground, bottom + 0.01f);
        const float radius = 0.5f * (c.bounds.extent().x + c.bounds.extent().z);
        if (radius <= 0.0f) continue;
        // The sources that light this floor, and the total (the sun only where the bake sees it).
        int count = 0;
        float total = ambient;
        if (sun_on && !blocked(in.sun_blockers, probe, to_sun, 1e4f)) {
            Source& s = sources[count++];
            s.sun = true;
            s.irradiance = luminance(env.sun_color) * to_sun.y;
            s.away = Vec2(-to_sun.x, -to_sun.z) / to_sun.y;
            total += s.irradiance;
        }
        const std::size_t n = in.lights ? (in.candidates ? in.candidates->size() : in.lights->size()) : 0;
        for (std::size_t k = 0; k < n && count < kMaxSources; ++k) {
            const Light& l = (*in.lights)[in.candidates ? static_cast<std::size_t>((*in.candidates)[k]) : k];
            if (l.dynamic) continue; // a muzzle flash lasts a frame or two: no flicker of shadows
            const float reach = light_reach(l, probe, up);
            if (reach <= 0.0f) continue;
            const Vec3 to_light = l.position - probe;
            const float dist = glm::length(to_light);
            if (blocked(in.blockers, probe, to_light / dist, dist - 0.05f)) continue;
            Source& s = sources[count++];
            s.sun = false;
            s.irradiance = luminance(l.color * l.intensity) * reach;
            s.away = Vec2(l.position.x, l.position.z);
            s.height = l.position.y - c.ground;
            total += s.irradiance;
        }
        if (!(total > 0.0f)) continue;
        std::sort(sources, sources + count,
                  [](const Source& a, const Source& b) { return a.irradiance > b.irradiance; });
        // A floating thing (a pickup, the rifle) casts a fainter shadow than one standing on the floor.
        const float fade = radius / (radius + 0.5f * bottom);
        for (int i = 0; i < std::min(count, kPerCaster); ++i) {
            const float share = sources[i].irradiance / total;
            if (share < kMinShare) break;
            const float cap = kMaxStretch * top;
            const Vec2 near = sources[i].offset_at(bottom, feet, cap);
            const Vec2 far = sources[i].offset_at(top, feet, cap);
            const Vec2 span = far - near;
            const float span_len = glm::length(span);
            ContactShadow s;
            s.axis = span_len > 1e-4f ? span / span_len : Vec2(1.0f, 0.0f);
            s.half_length = 0.5f * span_len + radius;
            s.half_width = radius;
            const Vec2 mid = feet + 0.5f * (near + far);
            s.centre = Vec3(mid.x, c.ground, mid.y);
            s.feet = std::clamp(glm::dot(feet - mid, s.axis) / s.half_length, -1.0f, 1.0f);
            s.darkness = std::clamp(kStrength * share * fade, 0.0f, 1.0f);
            out.push_back(s);
        }
        // The ambient light the caster hides from the floor right under it: a round, direction-free shadow at
        // its feet (the darkening that makes a thing stand on the floor when no lamp is near).
        ContactShadow o;
        o.centre = Vec3(feet.x, c.ground, feet.y);
        o.half_length = o.half_width = 1.25f * radius;
        o.feet = 1.0f; // no fade along an axis
        o.darkness = std::clamp(kOcclusion * ambient / total * fade, 0.0f, 1.0f);
        out.push_back(o);
    }
}

} // namespace ks::render
