#pragma once
// The camera both the game's renderer and the editor's viewport use: its orientation from yaw, pitch and
// roll, view and projection matrices (perspective or orthographic), and the closed-form conversions
// between viewport pixels and world rays or points. Pure math, no GL.
#include "geometry/ray.h"

namespace ks::geometry {

struct Camera {
    Vec3 position{0.0f, 3.0f, 0.0f};
    float yaw = 0.0f;   // radians about +y; 0 looks along -z
    float pitch = 0.0f; // radians, positive looks up (±90° exactly is fine: no look-at singularity)
    float roll = 0.0f;  // radians about the view direction, positive leans the head to the right (a fall
                        // to the right; the world turns anticlockwise on screen)
    float fov_y = radians(60.0f);
    float near_plane = 0.1f;
    float far_plane = 1000.0f;
    float aspect = 16.0f / 9.0f;
    // > 0: an orthographic projection showing this many world units vertically (the editor's top, front
    // and side views); 0: perspective with fov_y.
    float ortho_height = 0.0f;

    // Columns: the image's right, up and back directions in world space (yaw about +y, then pitch, then
    // roll), built from angles rather than with lookAt so that looking straight down and rolling are
    // well defined.
    Mat3 basis() const;
    Vec3 forward() const;
    Vec3 right() const; // the image's +x direction in world space (includes roll)
    Vec3 up() const;    // the image's +y direction in world space (includes roll)
    bool orthographic() const { return ortho_height > 0.0f; }
    Mat4 view() const;
    Mat4 projection() const;
    Mat4 view_projection() const { return projection() * view(); }
};

// Pixel (x, y down) of a `viewport`-sized image to the world ray through it: from the eye (perspective) or
// from the pixel's point on the camera plane along the view direction (orthographic). The aspect is the
// viewport's, not camera.aspect.
Ray screen_ray(const Camera& camera, Vec2 pixel, Vec2 viewport);
// World point to viewport pixels (the inverse of screen_ray); false when it is behind the camera.
bool world_to_screen(const Camera& camera, const Vec3& world, Vec2 viewport, Vec2& pixel);

} // namespace ks::geometry
