#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

namespace ks::render {

Aabb empty_aabb() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    return {Vec3(inf), Vec3(-inf)};
}

Aabb merge(const Aabb& a, const Aabb& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

Aabb transform_aabb(const Aabb& box, const Mat4& m) {
    // Arvo's method: the transformed box of a box is centre moved, extent through |M|.
    Vec3 c = Vec3(m * Vec4(box.center(), 1.0f));
    Vec3 e = box.extent();
    Mat3 a(m);
    Vec3 ext(std::abs(a[0][0]) * e.x + std::abs(a[1][0]) * e.y + std::abs(a[2][0]) * e.z,
             std::abs(a[0][1]) * e.x + std::abs(a[1][1]) * e.y + std::abs(a[2][1]) * e.z,
             std::abs(a[0][2]) * e.x + std::abs(a[1][2]) * e.y + std::abs(a[2][2]) * e.z);
    return {c - ext, c + ext};
}

Vec3 Camera::forward() const {
    return Vec3(-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

namespace {
// The camera's orientation: yaw about world +y, then pitch about the camera's x, then roll about its z.
// Built from angles rather than with lookAt so that looking straight down (the editor's top view) and
// rolling (the death fall) are well defined.
Mat3 camera_basis(float yaw, float pitch, float roll) {
    Mat4 m = glm::rotate(Mat4(1.0f), yaw, Vec3(0, 1, 0));
    m = glm::rotate(m, pitch, Vec3(1, 0, 0));
    m = glm::rotate(m, -roll, Vec3(0, 0, 1));
    return Mat3(m);
}
} // namespace

Vec3 Camera::right() const {
    return camera_basis(yaw, pitch, roll)[0];
}

Vec3 Camera::up() const {
    return camera_basis(yaw, pitch, roll)[1];
}

Mat4 Camera::view() const {
    const Mat3 basis = camera_basis(yaw, pitch, roll); // columns: right, up, back
    Mat4 v(glm::transpose(basis));
    v[3] = Vec4(-(glm::transpose(basis) * position), 1.0f);
    return v;
}

Mat4 Camera::projection() const {
    if (orthographic()) {
        const float half_h = 0.5f * ortho_height, half_w = half_h * aspect;
        return glm::ortho(-half_w, half_w, -half_h, half_h, near_plane, far_plane);
    }
    return glm::perspective(fov_y, aspect, near_plane, far_plane);
}

Frustum::Frustum(const Mat4& m) {
    // Gribb-Hartmann: rows of the matrix combine into the clip planes.
    auto row = [&](int r) { return Vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    planes_ = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
               row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (auto& p : planes_) p /= glm::length(Vec3(p));
}

bool Frustum::intersects(const Aabb& box) const {
    Vec3 c = box.center(), e = box.extent();
    for (const auto& p : planes_) {
        float r = e.x * std::abs(p.x) + e.y * std::abs(p.y) + e.z * std::abs(p.z);
        if (glm::dot(Vec3(p), c) + p.w < -r) return false;
    }
    return true;
}

bool Frustum::intersects_sphere(const Vec3& center, float radius) const {
    for (const auto& p : planes_)
        if (glm::dot(Vec3(p), center) + p.w < -radius) return false;
    return true;
}

void append_occluder_faces(const Aabb& solid, const Vec3& eye, std::vector<OccluderFace>& out) {
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

bool hidden_behind(const Aabb& box, const OccluderFace& face, const Camera& camera) {
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
