#pragma once
// The error measure of the brush benchmark and of the brush tests that compare against it: how far a brush's
// vertices lie from the planes of their faces, evaluated in long double so that the measure adds no error of
// its own.
#include "brush/brush.h"

namespace ks::brush::bench {

// The largest distance of a vertex from the plane of a face it belongs to.
inline double off_plane(const Brush& b) {
    long double worst = 0;
    for (std::size_t f = 0; f < b.faces().size(); ++f) {
        const Plane& p = b.faces()[f].plane;
        for (int v : b.polygons()[f]) {
            const DVec3& x = b.vertices()[v];
            const long double d = (long double)p.normal.x * x.x + (long double)p.normal.y * x.y +
                                  (long double)p.normal.z * x.z - (long double)p.distance;
            worst = std::max(worst, d < 0 ? -d : d);
        }
    }
    return static_cast<double>(worst);
}

} // namespace ks::brush::bench
