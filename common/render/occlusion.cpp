#include "render/occlusion.h"

#include <algorithm>

namespace ks::render {

void append_occluder_faces(const geometry::Aabb& solid, const Vec3& eye, std::vector<OccluderFace>& out) {
    if (!solid.valid()) return;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        OccluderFace f;
        f.axis = a;
        if (eye[a] < solid.min[a])
            f.plane = solid.min[a];
        else if (eye[a] > solid.max[a])
            f.plane = solid.max[a];
        else
            continue; // the eye is level with this slab: neither face on this axis faces it
        f.lo = Vec2(solid.min[b], solid.min[c]);
        f.hi = Vec2(solid.max[b], solid.max[c]);
        out.push_back(f);
    }
}

void merge_occluder_faces(std::vector<OccluderFace>& faces) {
    constexpr float eps = 1e-3f;
    auto same = [](float a, float b) { return std::abs(a - b) < eps; };
    for (size_t i = 0; i < faces.size(); ++i)
        for (size_t j = i + 1; j < faces.size();) {
            OccluderFace& a = faces[i];
            const OccluderFace& b = faces[j];
            bool merged = false;
            if (a.axis == b.axis && same(a.plane, b.plane))
                for (int k = 0; k < 2 && !merged; ++k) {
                    const int o = 1 - k; // k: the axis along which they meet; o: the one they share
                    if (!same(a.lo[o], b.lo[o]) || !same(a.hi[o], b.hi[o])) continue;
                    if (a.hi[k] + eps < b.lo[k] || b.hi[k] + eps < a.lo[k]) continue; // a gap between them
                    a.lo[k] = std::min(a.lo[k], b.lo[k]);
                    a.hi[k] = std::max(a.hi[k], b.hi[k]);
                    a.lo[o] = std::max(a.lo[o], b.lo[o]); // the shared extent, to the safe side
                    a.hi[o] = std::min(a.hi[o], b.hi[o]);
                    merged = true;
                }
            if (merged) {
                faces[j] = faces.back();
                faces.pop_back();
                j = i + 1; // the grown face may now meet one already passed
            } else {
                ++j;
            }
        }
}

bool hidden_behind(const geometry::Aabb& box, const OccluderFace& face, const geometry::Camera& camera) {
    if (camera.orthographic() || !box.valid()) return false;
    const Vec3 eye = camera.position, fwd = camera.forward();
    const int a = face.axis, b = (a + 1) % 3, c = (a + 2) % 3;
    const float to_plane = face.plane - eye[a];
    if (std::abs(to_plane) < 1e-4f) return false;
    // Margins: a hair inside the face's rectangle, beyond its plane, and inside the depth range, so that
    // rounding never culls what a pixel could show.
    const float eps_b = 1e-3f * (face.hi.x - face.lo.x) + 1e-3f;
    const float eps_c = 1e-3f * (face.hi.y - face.lo.y) + 1e-3f;
    const float near = camera.near_plane * 1.01f + 1e-4f, far = camera.far_plane * 0.99f;
    for (int i = 0; i < 8; ++i) {
        const Vec3 p((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                     (i & 4) ? box.max.z : box.min.z);
        const Vec3 d = p - eye;
        // Beyond the plane, seen from the eye: same side and farther along the axis.
        if (to_plane > 0.0f ? d[a] <= to_plane + 1e-3f : d[a] >= to_plane - 1e-3f) return false;
        const float t = to_plane / d[a]; // in (0, 1): where the eye-to-corner segment crosses the plane
        const float qb = eye[b] + t * d[b], qc = eye[c] + t * d[c];
        if (qb < face.lo.x + eps_b || qb > face.hi.x - eps_b || qc < face.lo.y + eps_c ||
            qc > face.hi.y - eps_c)
            return false;
        // The crossing point must be drawn: in front of the near plane, before the far plane (view depth
        // is linear on the face, so the corners' crossings bound every crossing).
        const float depth = t * glm::dot(d, fwd);
        if (depth < near || depth > far) return false;
    }
    return true;
}

} // namespace ks::render
