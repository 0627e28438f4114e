#include "geometry/convex_hull_2d.h"

#include <algorithm>
#include <cmath>

namespace ks::geometry {
namespace {
// > 0: o -> a -> b turns left. Products of float differences in double are exact (24-bit mantissas).
double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (static_cast<double>(a.x) - o.x) * (static_cast<double>(b.y) - o.y) -
           (static_cast<double>(a.y) - o.y) * (static_cast<double>(b.x) - o.x);
}
} // namespace

void convex_hull_2d(std::vector<Vec2>& points) {
    std::erase_if(points, [](const Vec2& p) { return !std::isfinite(p.x) || !std::isfinite(p.y); });
    std::sort(points.begin(), points.end(),
              [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const size_t n = points.size();
    if (n < 3) return;
    // Reused between calls (the renderer asks once a frame): no allocation once it has grown.
    static thread_local std::vector<Vec2> hull;
    hull.resize(2 * n);
    size_t k = 0;
    for (size_t i = 0; i < n; ++i) { // lower chain
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    for (size_t i = n - 1, lower = k + 1; i-- > 0;) { // upper chain
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);                                          // the last point is the first
    if (hull.size() < 3) hull = {points.front(), points.back()}; // all collinear: the two extremes
    points.swap(hull);
}

void clip_convex_polygon(std::vector<Vec2>& polygon, const Vec2& lo, const Vec2& hi) {
    std::vector<Vec2> out;
    // Side k keeps points with sign * p[axis] >= sign * bound.
    const struct {
        int axis;
        float sign, bound;
    } sides[4] = {{0, 1.0f, lo.x}, {0, -1.0f, hi.x}, {1, 1.0f, lo.y}, {1, -1.0f, hi.y}};
    for (const auto& side : sides) {
        out.clear();
        const size_t n = polygon.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2& a = polygon[i];
            const Vec2& b = polygon[(i + 1) % n];
            const float da = side.sign * (a[side.axis] - side.bound),
                        db = side.sign * (b[side.axis] - side.bound);
            if (da >= 0.0f) out.push_back(a);
            if ((da >= 0.0f) != (db >= 0.0f)) {
                Vec2 p = a + (b - a) * (da / (da - db));
                p[side.axis] = side.bound; // exactly on the side, whatever the rounding
                out.push_back(p);
            }
        }
        polygon.swap(out);
    }
    if (polygon.size() < 3) polygon.clear();
}

double polygon_area2(const std::vector<Vec2>& polygon) {
    double sum = 0.0;
    for (size_t i = 0, n = polygon.size(); i < n; ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % n];
        sum += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
    }
    return sum;
}

} // namespace ks::geometry
