#include "brush/brush_query.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::brush {
namespace {

// The part [t_min, t_max] of the line origin + t * direction inside every face's half-space.
struct Span {
    double t_min = -std::numeric_limits<double>::infinity();
    double t_max = std::numeric_limits<double>::infinity();
    int entry_face = -1; // the face through which the line enters (sets t_min)
    bool empty() const { return !(t_min < t_max); }
};

Span clip_line(const Brush& brush, const DVec3& origin, const DVec3& direction) {
    Span span;
    for (std::size_t i = 0; i < brush.faces().size(); ++i) {
        const Face& face = brush.faces()[i];
        const double along = glm::dot(face.plane.normal, direction);
        const double outside = face.plane.signed_distance(origin); // > 0: origin on the outer side
        if (std::fabs(along) <= std::numeric_limits<double>::min()) {
            // Parallel to the face: inside it everywhere or nowhere (touching counts as outside, so a
            // line along a face's plane misses rather than skims).
            if (outside >= 0.0) return Span{0.0, 0.0};
            continue;
        }
        const double t = -outside / along;
        if (along > 0.0)
            span.t_max = std::min(span.t_max, t); // leaving through this face
        else if (t > span.t_min)
            span.t_min = t, span.entry_face = static_cast<int>(i); // entering through it
        if (span.empty()) return span;
    }
    return span;
}

} // namespace

std::optional<double> top_at(const Brush& brush, double x, double z) {
    // Upward from below the brush, so t is the height above bounds_min().y - 1.
    const double from = brush.bounds_min().y - 1.0;
    const Span span = clip_line(brush, DVec3(x, from, z), DVec3(0.0, 1.0, 0.0));
    if (span.empty() || !std::isfinite(span.t_max)) return std::nullopt;
    return from + span.t_max;
}

std::optional<double> ray_entry(const Brush& brush, const DVec3& origin, const DVec3& direction) {
    if (!(glm::dot(direction, direction) > 0.0)) return std::nullopt;
    Span span = clip_line(brush, origin, direction);
    span.t_min = std::max(span.t_min, 0.0);
    if (span.empty()) return std::nullopt;
    return span.t_min;
}

std::optional<RayEntry> ray_entry_face(const Brush& brush, const DVec3& origin, const DVec3& direction) {
    if (!(glm::dot(direction, direction) > 0.0)) return std::nullopt;
    const Span span = clip_line(brush, origin, direction);
    if (span.empty() || span.t_min < 0.0 || span.entry_face < 0) return std::nullopt;
    return RayEntry{span.t_min, span.entry_face};
}

bool contains(const Brush& brush, const DVec3& point, double tolerance) {
    return std::all_of(brush.faces().begin(), brush.faces().end(),
                       [&](const Face& f) { return f.plane.signed_distance(point) <= tolerance; });
}

} // namespace ks::brush
