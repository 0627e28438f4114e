#pragma once
// Light baked into a light map for static level geometry, the fast path's answer to per-pixel lighting
// on software rasterisers. No GL here (testable on the CPU); LightmapTexture uploads the result.
//
// Each polygon of the level's meshes (MeshData::polygon_sizes: a box's faces, a brush's faces) gets the
// rectangle of texels that bounds it in one atlas, texel centres on the rectangle's edges so bilinear
// filtering never reads a neighbour. A texel stores diffuse irradiance in pbr.frag's units (what multiplies
// albedo): the hemisphere ambient, the sun (with shadows: a ray against the level's convex solids,
// MeshData::solid_sizes, ceilings excluded as in the full path) and each point/spot light with its falloff
// and cone, occluded by the solids (so unlike the full path, light does not leak through walls). Every
// light's share is kept per texel, so a light switching on or off re-combines the atlas in a few milliseconds
// instead of re-baking.
#include "render/mesh_data.h"
#include "render/scene.h"

#include <cstdint>
#include <vector>

namespace ks::render {

// The bake's version for its disk cache (light_bake_cache.h): bump it with any change to what bake() computes
// from the same input, so cached atlases of the old bake are not used.
inline constexpr std::uint32_t kLightBakeVersion = 1;

struct BakeSettings {
    float texel_size = 0.5f;        // world units per texel (doubled until the atlas fits max_texels)
    long long max_texels = 1 << 20; // RGB16F: 6 MiB of texture at most
    int atlas_width = 2048;
};

struct BakeSurface {
    MeshData*
        mesh; // world space, made of polygons and solids; its vertices' lightmap_uv are written by bake()
    bool blocks_sun; // ceilings do not (the full path's ceilings cast no sun shadow either)
};

struct BakeStats {
    int faces = 0, occluders = 0;
    long long texels = 0, light_texels = 0; // light_texels: (texel, light) pairs kept for re-combining
    float texel_size = 0.0f;
    double bake_ms = 0.0; // CPU time of bake()
};

class LightBake {
  public:
    // Lays the faces out, writes their vertices' lightmap_uv, and computes every texel.
    BakeStats bake(const std::vector<BakeSurface>& surfaces, const Environment& environment,
                   const std::vector<Light>& lights, const BakeSettings& settings = {});

    // Switching a light (an index into bake()'s `lights`) marks the atlas for re-combining.
    void set_light_on(int light, bool on);
    bool light_on(int light) const;
    // Re-combines ambient + sun + the lights that are on into texels() when something changed; returns
    // whether it did.
    bool update();

    int width() const { return width_; }
    int height() const { return height_; }
    // width() x height() linear RGB, rows bottom-up (GL's order).
    const std::vector<Vec3>& texels() const { return combined_; }
    // The baked irradiance at a light-map coordinate (nearest texel; for tests).
    Vec3 sample(const Vec2& uv) const;

  private:
    friend struct LightBakeCacheAccess; // light_bake_cache.cpp: stores and restores a finished bake
    struct Occluder {
        std::uint32_t first_plane = 0, plane_count = 0; // in planes_
        bool blocks_sun = true;
        Vec3 lo, hi; // world bounds
    };
    struct Share {
        std::uint32_t texel;
        float amount; // atten * cos * visibility, times the light's colour * intensity when combined
    };
    // Against every occluder (sun: those that block it) or only `subset` (a light's: the solids touching its
    // range sphere, since both ends of its rays lie inside that sphere).
    bool occluded(const Vec3& from, const Vec3& dir, float length, bool sun,
                  const std::vector<int>* subset = nullptr) const;
    bool hits(const Occluder& o, const Vec3& from, const Vec3& dir, float length) const;
    void add_occluders(const MeshData& mesh, bool blocks_sun);
    // The solids that block the sun and that a ray along `dir` from anywhere on a polygon may meet: the
    // sun's rays from one face are tested against these only.
    void sun_occluders(const Vertex* corners, std::size_t count, const Vec3& dir, float length,
                       std::vector<int>& out) const;

    int width_ = 0, height_ = 0;
    std::vector<Occluder> occluders_;
    std::vector<Vec4> planes_;   // the solids' face planes: outward normal, distance (dot(normal, p) == w)
    std::vector<Vec3> base_;     // ambient + sun
    std::vector<Vec3> combined_; // what is uploaded
    std::vector<std::vector<Share>> shares_;
    std::vector<Vec3> light_color_;
    std::vector<char> light_on_;
    bool dirty_ = true;
};

} // namespace ks::render
