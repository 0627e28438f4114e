#pragma once
// The viewport's camera controller: fly (right mouse + WASD/QE, wheel = speed), orbit (Alt + left drag
// around a pivot), focus on a box (F), and top/front/side views. The renderer's Camera is perspective
// only, so the axis views are near-orthographic: a 4-degree lens far away (parallel edges stay within a
// few percent), which keeps picking and the gizmo on the same projection as the picture.
#include "core/math.h"
#include "render/camera.h"

struct GLFWwindow;

namespace ks::editor::ui {

struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, -1.0f}; // unit
};

enum class ViewMode { Perspective, Top, Front, Side };
const char* view_mode_name(ViewMode mode);

class ViewCamera {
  public:
    render::Camera camera;
    float speed = 12.0f; // fly speed, units/s (wheel changes it)
    Vec3 pivot{0.0f};    // orbit centre
    ViewMode mode = ViewMode::Perspective;

    // Keyboard and mouse while the viewport is hovered or a drag that started there is active.
    // Returns true when the camera is being flown or orbited (the viewport's other tools stay idle).
    bool update(GLFWwindow* window, double dt, bool hovered, float wheel);

    void focus(const Vec3& min, const Vec3& max);
    void set_view(ViewMode view, const Vec3& centre, float extent);

    // Screen position (pixels inside a viewport of size w x h, y down) to a world ray.
    Ray ray(float x, float y, float width, float height) const;
    // World to viewport pixels; false when behind the camera.
    bool project(const Vec3& world, float width, float height, Vec2& out) const;

  private:
    bool flying_ = false, orbiting_ = false;
    double last_x_ = 0, last_y_ = 0;
};

} // namespace ks::editor::ui
