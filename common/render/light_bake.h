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
//
// On top of that direct light (light_bake_indirect.cpp): one bounce of indirect light, gathered at every
// `indirect_stride`-th texel by cosine-weighted hemisphere rays against the same solids (the direct sun and
// lights of the texel each ray hits, times that face's albedo; each light's bounce is kept with its share,
// so switching a light switches its bounce too), and ambient occlusion, the fraction of short rays
// (`ao_radius`) that escape, multiplying the hemisphere ambient. Sample patterns are seeded per texel, so
// the result does not depend on the thread count. bake() = layout() + compute(): the editor lays out on
// the UI thread (the meshes' lightmap_uv) and computes a copy on a worker thread.
#include "render/mesh_data.h"
#include "render/scene.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace ks::render {

// The bake's version for its disk cache (light_bake_cache.h): bump it with any change to what bake() computes
// from the same input, so cached atlases of the old bake are not used.
inline constexpr std::uint32_t kLightBakeVersion = 2;

struct BakeSettings {
    float texel_size = 0.5f;        // world units per texel (doubled until the atlas fits max_texels)
    long long max_texels = 1 << 20; // RGB16F: 6 MiB of texture at most
    int atlas_width = 2048;
    // Indirect light: 0 samples = none. Rays per gathering texel; gathered every indirect_stride-th texel
    // along each axis of a face and interpolated between (indirect light varies slowly).
    int bounce_samples = 0;
    int indirect_stride = 4;
    float bounce_distance = 48.0f; // world units a bounce ray looks (three wall heights)
    int ao_samples = 0;            // per texel; 0: no ambient occlusion
    // 2 units: two thirds of the player's height, so the darkening marks where walls meet floors, steps and
    // door recesses without dimming the middle of a 16-high room (the bounce carries that scale).
    float ao_radius = 2.0f;
    std::uint32_t seed = 1; // the sample patterns' seed
    int threads = 2;        // worker threads of compute() (the machine's 2 cores)

    static BakeSettings direct_only() { return {}; }
    static BakeSettings preview(); // the editor's (docs/performance.md, "Light bake quality")
    static BakeSettings full();    // the game's
};

struct BakeSurface {
    MeshData*
        mesh; // world space, made of polygons and solids; its vertices' lightmap_uv are written by bake()
    bool blocks_sun; // ceilings do not (the full path's ceilings cast no sun shadow either)
    // Linear diffuse albedo per polygon (MeshData::polygon_sizes) for the bounce; nullptr or short: 0.5.
    const std::vector<Vec3>* albedo = nullptr;
};

struct BakeStats {
    int faces = 0, occluders = 0;
    long long texels = 0, light_texels = 0; // light_texels: (texel, light) pairs kept for re-combining
    float texel_size = 0.0f;
    double bake_ms = 0.0;   // CPU time of the bake (all threads)
    double wall_ms = 0.0;   // wall time of the bake
    long long rays = 0;     // bounce and occlusion rays cast
    bool cancelled = false; // compute() stopped early (its texels are then incomplete)
};

// One light's part of a texel: atten * cos * visibility, times the light's colour * intensity when
// combined; and its bounce, coloured by the albedo of what it bounced off.
struct BakeShare {
    std::uint32_t texel;
    float amount;
};
struct BakeColorShare {
    std::uint32_t texel;
    Vec3 amount;
};

// What a finished bake keeps to light the level and to switch lights (the disk cache stores it): the atlas
// size, the light-independent texels (ambient, sun, their bounce) and each light's shares and state.
struct BakedAtlas {
    int width = 0, height = 0;
    std::vector<Vec3> base;
    std::vector<std::vector<BakeShare>> shares;
    std::vector<std::vector<BakeColorShare>> bounce_shares;
    std::vector<Vec3> light_color;
    std::vector<char> light_on;
};

// Progress of a compute() running on another thread, and a way to stop it.
struct BakeProgress {
    std::atomic<float> done{0.0f}; // 0..1
    std::atomic<bool> cancel{false};
};

class LightBake {
  public:
    // Lays the faces out, writes their vertices' lightmap_uv, and computes every texel.
    BakeStats bake(const std::vector<BakeSurface>& surfaces, const Environment& environment,
                   const std::vector<Light>& lights, const BakeSettings& settings = {});
    // The two halves of bake(). layout() writes the meshes' lightmap_uv and keeps what compute() needs
    // (the faces' geometry, the solids), so compute() reads no mesh and may run on a copy on another thread.
    BakeStats layout(const std::vector<BakeSurface>& surfaces, const BakeSettings& settings = {});
    BakeStats compute(const Environment& environment, const std::vector<Light>& lights,
                      const BakeSettings& settings = {}, BakeProgress* progress = nullptr);
    bool laid_out() const { return width_ > 0; }

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
    // The faces (one per polygon, in the surfaces' order whatever the texel size), to compare two bakes of
    // the same surfaces: face k's irradiance at (s, t) in 0..1 over its rectangle, bilinear between texels,
    // and its texel count along each axis.
    int face_count() const { return static_cast<int>(faces_.size()); }
    Vec3 face_irradiance(int face, const Vec2& st) const;
    glm::ivec2 face_texels(int face) const;

    // The finished bake, and the same adopted as if baked (update() then combines texels(); the layout's
    // faces are not part of it, so face_count() is 0 after adopting). adopt() refuses, changing nothing, an
    // atlas whose parts disagree (sizes, a texel outside the atlas, a light count that is not `light_count`).
    BakedAtlas atlas() const;
    bool adopt(BakedAtlas atlas, std::size_t light_count);

  private:
    // A polygon and the rectangle of texels over it: the rectangle bounds the polygon in the face's frame
    // (u along its first edge), texel centres on its edges.
    struct Face {
        std::uint32_t first_corner = 0, corner_count = 0; // in corners_
        Vec3 origin, u_dir, v_dir, normal; // origin: the rectangle's corner; u_dir, v_dir: unit, in the plane
        Vec2 extent{0.0f};                 // the rectangle's size along u_dir, v_dir
        int w = 0, h = 0;                  // texels
        int x = 0, y = 0;                  // atlas position
        Vec3 albedo{0.5f};
        bool blocks_sun = true;
    };
    struct Occluder {
        std::uint32_t first_plane = 0, plane_count = 0; // in planes_
        bool blocks_sun = true;
        Vec3 lo, hi; // world bounds
    };
    using Share = BakeShare;
    using ColorShare = BakeColorShare;
    struct Gather; // light_bake_indirect.cpp
    void compute_direct(const Environment& env, const std::vector<Light>& lights, BakeProgress* progress);
    // Ambient occlusion into ambient_, the bounce into base_ and bounce_shares_; the rays it cast.
    long long compute_indirect(const BakeSettings& settings, BakeProgress* progress);
    void gather_face(const Face& face, Gather& scratch) const; // one face's occlusion and bounce
    // The nearest solid a ray meets within `length`: the face it enters (-1: none known, or the ray starts
    // inside a solid) and the distance; false when it escapes.
    bool nearest_hit(const Vec3& from, const Vec3& dir, float length, const std::vector<int>& candidates,
                     int& face, float& t) const;
    // Against every occluder (sun: those that block it) or only `subset` (a light's: the solids touching its
    // range sphere, since both ends of its rays lie inside that sphere).
    bool occluded(const Vec3& from, const Vec3& dir, float length, bool sun,
                  const std::vector<int>* subset = nullptr) const;
    bool hits(const Occluder& o, const Vec3& from, const Vec3& dir, float length) const;
    void add_occluders(const MeshData& mesh, bool blocks_sun);
    // The solids that block the sun and that a ray along `dir` from anywhere on a polygon may meet: the
    // sun's rays from one face are tested against these only.
    void sun_occluders(const Face& face, const Vec3& dir, float length, std::vector<int>& out) const;
    // The solids whose bounds come within `reach` of the face's bounds (a short ray's candidates).
    void near_occluders(const Face& face, float reach, std::vector<int>& out) const;

    int width_ = 0, height_ = 0;
    float texel_size_ = 0.0f;
    std::vector<Face> faces_;
    std::vector<Vec3> corners_; // the faces' corners, world space
    std::vector<Occluder> occluders_;
    std::vector<Vec4> planes_;    // the solids' face planes: outward normal, distance (dot(normal, p) == w)
    std::vector<int> plane_face_; // the face of each plane (-1: a degenerate polygon without texels)
    std::vector<Vec3> points_;    // each texel's sampled point, lifted off its face (layout())
    std::vector<Vec3> ambient_;   // the hemisphere ambient (times the occlusion) of each texel
    std::vector<Vec3> sun_;       // direct sun of each texel
    std::vector<Vec3> base_;      // ambient + sun + their bounce
    std::vector<Vec3> combined_;  // what is uploaded
    std::vector<std::vector<Share>> shares_;
    std::vector<std::vector<ColorShare>> bounce_shares_;
    std::vector<Vec3> light_color_;
    std::vector<char> light_on_;
    bool dirty_ = true;
};

} // namespace ks::render
