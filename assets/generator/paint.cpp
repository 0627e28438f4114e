#include "paint.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {

void paint_sdf(Field& field, Vec2f lo, Vec2f hi, const Sdf& sdf, const Stroke& stroke) {
    const int x0 = static_cast<int>(std::floor(lo.x)) - 1, x1 = static_cast<int>(std::ceil(hi.x)) + 1;
    const int y0 = static_cast<int>(std::floor(lo.y)) - 1, y1 = static_cast<int>(std::ceil(hi.y)) + 1;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const float d = sdf(Vec2f(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
            const float coverage = std::clamp((0.5f - d) / (1.0f + stroke.bevel), 0.0f, 1.0f);
            if (coverage <= 0.0f) continue;
            float& v = field.at(x, y);
            switch (stroke.mode) {
            case Paint::Max:
                v = std::max(v, stroke.value * coverage);
                break;
            case Paint::Set:
                v += (stroke.value - v) * coverage;
                break;
            case Paint::Add:
                v += stroke.value * coverage;
                break;
            case Paint::Min:
                v = std::min(v, 1.0f + (stroke.value - 1.0f) * coverage);
                break;
            }
        }
}

float sdf_circle(Vec2f p, Vec2f centre, float radius) {
    return glm::length(p - centre) - radius;
}

float sdf_rounded_rect(Vec2f p, Vec2f lo, Vec2f hi, float radius) {
    const Vec2f centre = (lo + hi) * 0.5f, half = (hi - lo) * 0.5f - Vec2f(radius);
    const Vec2f q = glm::abs(p - centre) - half;
    return glm::length(glm::max(q, Vec2f(0.0f))) + std::min(std::max(q.x, q.y), 0.0f) - radius;
}

float sdf_segment(Vec2f p, Vec2f a, Vec2f b, float half_width) {
    const Vec2f pa = p - a, ba = b - a;
    const float len2 = glm::dot(ba, ba);
    const float h = len2 > 0.0f ? std::clamp(glm::dot(pa, ba) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(pa - ba * h) - half_width;
}

float sdf_polygon(Vec2f p, const std::vector<Vec2f>& v) {
    // Distance to the nearest edge, negative inside by the even-odd crossing rule.
    float d = glm::dot(p - v[0], p - v[0]);
    bool inside = false;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i, ++i) {
        const Vec2f e = v[j] - v[i], w = p - v[i];
        const float len2 = glm::dot(e, e);
        const Vec2f b = w - e * (len2 > 0.0f ? std::clamp(glm::dot(w, e) / len2, 0.0f, 1.0f) : 0.0f);
        d = std::min(d, glm::dot(b, b));
        if ((v[i].y > p.y) != (v[j].y > p.y) &&
            p.x < (v[j].x - v[i].x) * (p.y - v[i].y) / (v[j].y - v[i].y) + v[i].x)
            inside = !inside;
    }
    return inside ? -std::sqrt(d) : std::sqrt(d);
}

void fill_circle(Field& f, Vec2f c, float r, const Stroke& s) {
    paint_sdf(
        f, c - Vec2f(r), c + Vec2f(r), [&](Vec2f p) { return sdf_circle(p, c, r); }, s);
}

void fill_ring(Field& f, Vec2f c, float outer, float inner, const Stroke& s) {
    const float mid = (outer + inner) * 0.5f, half = (outer - inner) * 0.5f;
    paint_sdf(
        f, c - Vec2f(outer), c + Vec2f(outer),
        [&](Vec2f p) { return std::abs(glm::length(p - c) - mid) - half; }, s);
}

void fill_rounded_rect(Field& f, Vec2f lo, Vec2f hi, float radius, const Stroke& s) {
    paint_sdf(
        f, lo, hi, [&](Vec2f p) { return sdf_rounded_rect(p, lo, hi, radius); }, s);
}

void draw_line(Field& f, Vec2f a, Vec2f b, float width, const Stroke& s) {
    const Vec2f pad(width);
    paint_sdf(
        f, glm::min(a, b) - pad, glm::max(a, b) + pad,
        [&](Vec2f p) { return sdf_segment(p, a, b, width * 0.5f); }, s);
}

void fill_polygon(Field& f, const std::vector<Vec2f>& points, const Stroke& s) {
    if (points.size() < 3) return;
    Vec2f lo = points[0], hi = points[0];
    for (const Vec2f& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    paint_sdf(
        f, lo, hi, [&](Vec2f p) { return sdf_polygon(p, points); }, s);
}

} // namespace ks::assetgen
