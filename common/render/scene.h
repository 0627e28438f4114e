#pragma once
// What the game and the editor hand the SceneRenderer each frame: mesh instances, lights, the environment
// (ambient, sun, fog) and a camera. Plain data, filled into reused vectors (no per-frame allocation).
#include "geometry/camera.h"

namespace ks::render {

class GpuMesh;
struct Material;

struct MeshInstance {
    const GpuMesh* mesh = nullptr;
    const Material* material = nullptr;
    Mat4 world{1.0f};
    float emissive_scale = 1.0f; // follows a light's on/off state for `light_emissive` lenses
    bool casts_shadow = true;
    // GL texture with this static mesh's baked light (LevelScene's level geometry; the mesh's vertices carry
    // lightmap_uv). 0: none. Only the fast quality path reads it; the full path lights everything per pixel.
    unsigned lightmap = 0;
    // Its world bounds, shrunk by occluder_inset (mesh space, per axis), are a solid, opaque box
    // (LevelScene's axis-aligned walls and floors; closed door leaves, whose bevelled edges need the inset):
    // the fast path skips instances that lie entirely behind one of its faces (SceneRenderer, occlusion
    // culling). Only for a `world` that keeps axes axis-aligned (rotations by multiples of 90 degrees).
    bool occluder = false;
    Vec3 occluder_inset{0.0f};
    // A colour washed over every surface of this instance (a robot just hit flashes red), linear rgb: it
    // is added to the shading, which dims by 0.6 x its largest channel; 0: none. Per instance, so tinted
    // and untinted copies still share one draw.
    Vec3 tint{0.0f};
};

struct Light {
    enum class Type { Point, Spot } type = Type::Point;
    Vec3 position{0.0f};
    Vec3 direction{0.0f, -1.0f, 0.0f}; // spot axis
    Vec3 color{1.0f};                  // linear rgb
    float intensity = 1.0f;
    float range = 24.0f;
    float cos_outer = 0.8f; // spot cone (cosines of half-angles)
    float cos_inner = 0.9f;
    // Not in any light map (a muzzle flash; level lights are baked): the fast path also lights the baked
    // level surfaces it reaches with it, per pixel, with fast_level_lit. Level lights leave it false.
    bool dynamic = false;
};

struct Environment {
    Vec3 sky_color{0.2f};                    // linear, times intensity: the upper hemisphere ambient
    Vec3 ground_color{0.1f};                 // lower hemisphere
    Vec3 sun_direction{-0.3f, -1.0f, -0.2f}; // the direction sunlight travels
    Vec3 sun_color{0.1f};                    // linear, times intensity
    Vec3 fog_color{0.0f};                    // linear
    float fog_density = 0.0f;
    float exposure = 1.0f;
};

struct FrameStats {
    int draw_calls = 0;
    long long triangles = 0;
    int instances_drawn = 0;
    int instances_culled = 0;   // outside the view frustum
    int instances_occluded = 0; // inside it, but hidden behind an occluder box (fast path)
    int lights_in_view = 0;
    bool shadow_rendered = false;
    int contact_shadows = 0;                     // ellipses drawn under movers (contact_shadows.h)
    bool fast_path = false;                      // RenderQuality::Fast drew this frame
    int internal_width = 0, internal_height = 0; // the 3D scene's resolution (render scale)
};

} // namespace ks::render
