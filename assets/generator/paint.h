#pragma once
// Anti-aliased 2D shapes painted into Fields through signed distance functions (in pixels). Coverage is the
// exact 1-pixel ramp across the edge, or a wider ramp (`bevel`) that doubles as a bevelled height profile.
// Shapes that cross the texture border wrap around, keeping textures tileable.
#include "image.h"

#include <functional>
#include <vector>

namespace ks::assetgen {

using Vec2f = glm::vec2;

enum class Paint {
    Max, // f = max(f, value * coverage)    (union of masks)
    Set, // f = lerp(f, value, coverage)    (paint over)
    Add, // f += value * coverage
    Min, // f = min(f, lerp(1, value, coverage)) (carve)
};

struct Stroke {
    float value = 1.0f;
    Paint mode = Paint::Max;
    float bevel = 0.0f; // extra ramp width in pixels inside the edge (0: a crisp anti-aliased edge)
};

using Sdf = std::function<float(Vec2f)>;
// Paints the shape whose signed distance (pixels, negative inside) is `sdf`, over the pixel box [lo, hi].
void paint_sdf(Field& field, Vec2f lo, Vec2f hi, const Sdf& sdf, const Stroke& stroke);

float sdf_circle(Vec2f p, Vec2f centre, float radius);
float sdf_rounded_rect(Vec2f p, Vec2f lo, Vec2f hi, float radius);
float sdf_segment(Vec2f p, Vec2f a, Vec2f b, float half_width);
float sdf_polygon(Vec2f p, const std::vector<Vec2f>& points); // any simple polygon

void fill_circle(Field& f, Vec2f centre, float radius, const Stroke& s = {});
void fill_ring(Field& f, Vec2f centre, float outer, float inner, const Stroke& s = {});
void fill_rounded_rect(Field& f, Vec2f lo, Vec2f hi, float radius, const Stroke& s = {});
void draw_line(Field& f, Vec2f a, Vec2f b, float width, const Stroke& s = {});
void fill_polygon(Field& f, const std::vector<Vec2f>& points, const Stroke& s = {});

} // namespace ks::assetgen
