#pragma once
// Mesh-building helpers: rounded (bevelled) boxes, lathes (cylinders, cones, capsules, tori, any profile
// revolved about y) and extrusions of 2D outlines. Each returns a mesh with normals, uvs and tangents, in
// its own frame; place it with Mesh::append(shape, trs(...)).
#include "mesh.h"

#include <vector>

namespace ks::assetgen {

// How finely the shapes below are tessellated. The default is each model as designed (level 0); a model's
// coarser levels of detail (Output::model_levels) are the same recipe run again under a Detail with a
// tolerance: every shape then takes the fewest segments around its axis, the fewest rounded steps on its
// edges (or sharp edges) and drops the rim bevels that keep it within the tolerance of its full-detail self
// (in its own units), and sets Mesh::deviation to that bound. Parts, nodes, materials and texture mapping
// stay as designed (docs/assets.md, "Levels of detail").
struct Detail {
    float tolerance = 0.0f; // 0: full detail
};
// The coarser levels' tolerances as fractions of the model's bounds' diagonal, finest first: a level is
// drawn while its error covers at most about a pixel, so while the model is under about 200, 60 and 20
// pixels across. kLevelMinSaving: a level is kept only when it has fewer than this fraction of the last
// kept level's triangles.
inline constexpr float kLevelTolerances[] = {0.005f, 0.0167f, 0.05f};
inline constexpr double kLevelMinSaving = 0.85;

// The Detail the shapes read on this thread (the default outside any DetailScope).
const Detail& current_detail();
// Sets the thread's Detail while it lives (scopes nest; the previous one comes back).
class DetailScope {
  public:
    explicit DetailScope(const Detail& detail);
    ~DetailScope();
    DetailScope(const DetailScope&) = delete;
    DetailScope& operator=(const DetailScope&) = delete;

  private:
    Detail previous_;
};

enum class UvMode {
    World,   // planar per face, `uv_scale` repeats per world unit (tiling materials)
    PerFace, // each face spans 0..1 (decals and icons)
};

// A box of `size` centred at the origin whose edges are rounded with `radius` over `segments` steps
// per 45 degrees (radius 0: sharp edges).
Mesh rounded_box(vec3 size, float radius = 0.0f, int segments = 1, float uv_scale = 1.0f,
                 UvMode mode = UvMode::World);

struct LatheOptions {
    int segments = 24;            // around the axis
    float u_repeats = 1.0f;       // texture repeats around the circumference
    float v_scale = 1.0f;         // texture repeats per unit along the profile (or of height)
    bool v_by_height = false;     // v from height (top of image at the highest y) instead of arc length
    float crease_degrees = 35.0f; // profile corners sharper than this get split normals
};
// Revolves `profile` (x = radius >= 0, y = height), listed from the bottom of the axis outward and upward,
// about the y axis. Points on the axis (radius 0) close the surface without degenerate triangles.
Mesh lathe(const std::vector<vec2>& profile, const LatheOptions& options = {});

// Cylinder from y = 0 to height, with caps and an optional bevel on both rims.
Mesh cylinder(float radius, float height, int segments = 24, float bevel = 0.0f, LatheOptions options = {});
// Cylinder without caps (a tube wall), optionally with an inner wall of `inner_radius` and rims.
Mesh tube(float outer_radius, float inner_radius, float height, int segments = 24, LatheOptions options = {});
// A capsule with total height `height` (>= 2 radius), from y = 0.
Mesh capsule(float radius, float height, int segments = 16, int cap_rings = 6);
// A torus around the y axis.
Mesh torus(float major_radius, float minor_radius, int segments = 24, int rings = 12);
// A cone/frustum from radius r0 at y = 0 to r1 at height h, capped.
Mesh frustum(float r0, float r1, float height, int segments = 24, LatheOptions options = {});

// Extrudes a simple polygon (x, y; counter-clockwise seen from +z) from z = -depth/2 to +depth/2, with
// caps and flat-shaded sides.
Mesh extrude(const std::vector<vec2>& outline, float depth, float uv_scale = 1.0f);

} // namespace ks::assetgen
