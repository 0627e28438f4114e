// The shared camera: its closed-form forward agrees with the basis the matrices use (also looking straight
// down and rolled), screen rays and world_to_screen invert each other and agree with the view-projection
// matrix in both projections, and the frustum keeps boxes touching its planes and drops those just outside.
#include "geometry/camera.h"
#include "geometry/frustum.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::geometry;

namespace {
const Vec2 kViewport(960.0f, 540.0f);

struct Pose {
    Vec3 position;
    float yaw, pitch, roll, ortho_height;
};
const Pose kPoses[] = {{{0, 3, 0}, 0.0f, 0.0f, 0.0f, 0.0f},
                       {{12, 30, 40}, 0.35f, -0.7f, 0.0f, 0.0f},
                       {{5, 200, -7}, 0.0f, -1.5707964f, 0.0f, 110.0f}, // the editor's top view
                       {{-300, 8, 0}, 1.5707964f, 0.0f, 0.0f, 40.0f},   // its side view
                       {{1, 2, 3}, -2.0f, 0.4f, 0.3f, 0.0f},            // rolled (the death fall)
                       {{9000, 50, -9000}, 0.8f, -0.3f, 0.0f, 0.0f}};   // far from the origin

Camera camera_at(const Pose& p) {
    Camera c;
    c.position = p.position;
    c.yaw = p.yaw;
    c.pitch = p.pitch;
    c.roll = p.roll;
    c.ortho_height = p.ortho_height;
    if (p.ortho_height > 0.0f) c.far_plane = 2000.0f;
    c.aspect = kViewport.x / kViewport.y;
    return c;
}

// The pixel the view-projection matrix puts `world` at.
Vec2 matrix_pixel(const Camera& c, const Vec3& world) {
    const Vec4 clip = c.view_projection() * Vec4(world, 1.0f);
    const Vec2 ndc = Vec2(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * kViewport.x, (1.0f - ndc.y) * 0.5f * kViewport.y};
}
} // namespace

TEST_CASE("camera: closed-form forward, right and up agree with the basis the view matrix uses") {
    for (const Pose& p : kPoses) {
        const Camera c = camera_at(p);
        CAPTURE(p.yaw);
        CAPTURE(p.pitch);
        const Mat3 b = c.basis();
        CHECK(glm::length(c.forward() + b[2]) < 1e-6f);
        CHECK(c.right() == b[0]);
        CHECK(c.up() == b[1]);
        // The view matrix takes the eye to the origin and forward to -z.
        const Vec3 eye = Vec3(c.view() * Vec4(c.position, 1.0f));
        CHECK(glm::length(eye) < 1e-3f * (1.0f + glm::length(c.position)));
        const Vec3 fwd = Mat3(c.view()) * c.forward();
        CHECK(glm::length(fwd - Vec3(0, 0, -1)) < 1e-5f);
    }
}

TEST_CASE("camera: screen ray and world_to_screen round-trip, and agree with the matrices") {
    const Vec2 pixels[] = {{0, 0}, {480, 270}, {959, 539}, {100.5f, 400.25f}, {900, 20}};
    for (const Pose& p : kPoses) {
        const Camera c = camera_at(p);
        for (const Vec2 px : pixels) {
            CAPTURE(px.x);
            CAPTURE(px.y);
            const Ray r = screen_ray(c, px, kViewport);
            CHECK(glm::length(r.direction) == doctest::Approx(1.0f));
            for (float depth : {0.5f, 10.0f, 300.0f}) {
                const Vec3 world = r.at(depth);
                // Float positions carry a rounding of about |position|·2^-23 per coordinate; in pixels that
                // grows as the picture's world size per pixel at this depth shrinks.
                const float world_per_pixel = c.orthographic()
                                                  ? c.ortho_height / kViewport.y
                                                  : 2.0f * depth * std::tan(c.fov_y * 0.5f) / kViewport.y;
                const float rounding = 4.0f * 1.2e-7f * glm::length(c.position) / world_per_pixel;
                Vec2 back;
                REQUIRE(world_to_screen(c, world, kViewport, back));
                CHECK(glm::length(back - px) < 0.02f + rounding);
                CHECK(glm::length(matrix_pixel(c, world) - px) < 0.05f + 4.0f * rounding);
            }
        }
    }
}

TEST_CASE("camera: points behind the camera do not project; orthographic rays are parallel") {
    Camera c;
    c.position = Vec3(0, 2, 0);
    Vec2 px;
    CHECK_FALSE(world_to_screen(c, Vec3(0, 2, 5), kViewport, px)); // behind (the camera looks along -z)
    CHECK_FALSE(world_to_screen(c, c.position, kViewport, px));    // at the eye
    c.ortho_height = 20.0f;
    const Ray a = screen_ray(c, {0, 0}, kViewport), b = screen_ray(c, {959, 539}, kViewport);
    CHECK(a.direction == b.direction);
    CHECK(glm::length(a.origin - b.origin) > 10.0f);
    CHECK(a.origin.z == c.position.z); // on the camera plane
}

TEST_CASE("frustum: boxes on the planes are kept, boxes just outside are culled") {
    Camera c; // at (0, 3, 0) looking along -z, 60° vertical field of view
    c.near_plane = 0.5f;
    c.far_plane = 100.0f;
    c.aspect = 1.0f;
    const Frustum f(c.view_projection());
    const float h = std::tan(c.fov_y * 0.5f); // the side planes: |x|, |y - 3| = h * depth
    const float z = -20.0f, edge = h * 20.0f;
    CHECK(f.intersects({Vec3(-1, 2, z - 1), Vec3(1, 4, z + 1)})); // in the middle
    // Right plane: a thin box reaching 0.01 past the plane, then the same 0.05 outside it (exactly on the
    // plane, float rounding of the plane decides).
    CHECK(f.intersects({Vec3(edge - 0.01f, 2, z), Vec3(edge + 1, 4, z)}));
    CHECK_FALSE(f.intersects({Vec3(edge + 0.05f, 2, z), Vec3(edge + 1, 4, z)}));
    // Top plane.
    CHECK(f.intersects({Vec3(-1, 3 + edge - 0.01f, z), Vec3(1, 3 + edge + 1, z)}));
    CHECK_FALSE(f.intersects({Vec3(-1, 3 + edge + 0.05f, z), Vec3(1, 3 + edge + 1, z)}));
    // Near and far planes.
    CHECK(f.intersects({Vec3(-0.1f, 2.9f, -0.51f), Vec3(0.1f, 3.1f, 2.0f)}));
    CHECK_FALSE(f.intersects({Vec3(-0.1f, 2.9f, -0.49f), Vec3(0.1f, 3.1f, 2.0f)}));
    CHECK(f.intersects({Vec3(-1, 2, -150), Vec3(1, 4, -99.99f)}));
    CHECK_FALSE(f.intersects({Vec3(-1, 2, -150), Vec3(1, 4, -100.1f)}));
    // Behind the camera, and a floor spanning the whole view.
    CHECK_FALSE(f.intersects({Vec3(-1, 2, 5), Vec3(1, 4, 7)}));
    CHECK(f.intersects({Vec3(-500, -1, -500), Vec3(500, 0, 500)}));
    CHECK(f.intersects_sphere(Vec3(edge + 0.5f, 3, z), 0.5f * std::cos(c.fov_y * 0.5f) + 1e-3f));
    CHECK_FALSE(f.intersects_sphere(Vec3(edge + 1.0f, 3, z), 0.5f));
}
