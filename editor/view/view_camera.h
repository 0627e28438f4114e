#pragma once
// The viewport's camera, window-free: fly (right mouse + WASD/QE, wheel = speed), orbit (Alt + left drag
// around a pivot), pan (middle drag; right drag in the axis views), focus on a box (F), and true
// orthographic top/front/side views (geometry::Camera::ortho_height) with zoom about the cursor. Screen to
// world rays and world to screen projection are computed in closed form from the camera's basis (no
// matrix inverse), for both projections: in the axis views every ray is parallel to the view direction.
// The ImGui front end only reads the mouse and keys into a ViewInput (ui/view_input.cpp).
#include "geometry/camera.h"

namespace ks::editor {

enum class ViewMode { Perspective, Top, Front, Side };
const char* view_mode_name(ViewMode mode);

// One frame of the user's input as the viewport sees it (pixels, y down).
struct ViewInput {
    bool hovered = false; // the mouse is over the viewport and no other tool owns it
    Vec2 mouse{0.0f};     // inside the viewport
    bool left = false, right = false, middle = false, alt = false;
    float wheel = 0.0f;
    // Fly keys (physical positions): W S D A E Q and Shift.
    bool forward = false, back = false, strafe_right = false, strafe_left = false, up = false, down = false;
    bool boost = false;
};

class ViewCamera {
  public:
    geometry::Camera camera;
    float speed = 12.0f; // fly speed, units/s (wheel while flying changes it)
    Vec3 pivot{0.0f};    // orbit centre
    ViewMode mode = ViewMode::Perspective;

    bool orthographic() const { return camera.orthographic(); }
    // Viewport size in pixels (sets the aspect; pan and zoom need the pixel scale).
    void set_viewport(Vec2 size);
    Vec2 viewport() const { return viewport_; }

    // Returns true while the camera is flown, orbited or panned (the viewport's other tools stay idle).
    bool update(const ViewInput& input, double dt);

    void focus(const Vec3& min, const Vec3& max);
    void set_view(ViewMode view, const Vec3& centre, float extent);
    // Axis views: scale the visible height by 0.85^wheel keeping the world point under `mouse` fixed.
    void zoom_at(float wheel, Vec2 mouse);
    // Moves the camera so the picture follows the mouse by (dx, dy) pixels (at the pivot's depth in
    // perspective).
    void pan_pixels(float dx, float dy);

    Vec3 forward() const;
    Vec3 right() const;
    Vec3 up() const;
    // Pixel (x, y) inside the viewport to a world ray starting on the camera's plane (orthographic) or at
    // the eye (perspective).
    geometry::Ray ray(Vec2 pixel) const;
    // World to viewport pixels; false when the point is behind the camera.
    bool project(const Vec3& world, Vec2& out) const;
    // World units per pixel at `at` (constant in the axis views).
    float world_per_pixel(const Vec3& at) const;
    // The picture's view-projection, the same matrix the renderer uses.
    Mat4 view_projection() const;

  private:
    void leave_axis_view(); // to perspective, keeping what the view looks at and how big it is
    Vec2 viewport_{640.0f, 360.0f};
    bool flying_ = false, orbiting_ = false, panning_ = false;
    Vec2 last_{0.0f};
};

// Grid lines of an axis view: the world plane it shows, and for each of the plane's two axes the line
// coordinates that are visible, `step` apart (a power of two times the base step, at least `min_pixels`
// apart on screen). Majors every 16 units (a wall), the axis itself at 0.
struct GridPlan {
    int u_axis = 0, v_axis = 2; // world axes along the screen's horizontal and vertical lines
    float step = 1.0f;
    float u_first = 0.0f, v_first = 0.0f; // first line coordinates (multiples of step)
    int u_count = 0, v_count = 0;
};
GridPlan plan_axis_grid(const ViewCamera& view, float base_step, float min_pixels);

} // namespace ks::editor
