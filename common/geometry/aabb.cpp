#include "geometry/aabb.h"

namespace ks::geometry {

Aabb transform_aabb(const Aabb& box, const Mat4& m) {
    // Arvo's method: the transformed box of a box is centre moved, extent through |M|.
    const Vec3 c = Vec3(m * Vec4(box.center(), 1.0f));
    const Vec3 e = box.extent();
    const Mat3 a(m);
    const Vec3 ext(std::abs(a[0][0]) * e.x + std::abs(a[1][0]) * e.y + std::abs(a[2][0]) * e.z,
                   std::abs(a[0][1]) * e.x + std::abs(a[1][1]) * e.y + std::abs(a[2][1]) * e.z,
                   std::abs(a[0][2]) * e.x + std::abs(a[1][2]) * e.y + std::abs(a[2][2]) * e.z);
    return {c - ext, c + ext};
}

} // namespace ks::geometry
