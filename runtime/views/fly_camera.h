#pragma once
// Free-fly camera for looking around a level: WASD moves, Q/E (or Space/C) go down/up, Shift is faster,
// the mouse looks around while the right button is held.
#include "geometry/camera.h"

struct GLFWwindow;

namespace ks::runtime {

class FlyCamera {
  public:
    void update(GLFWwindow* window, double dt, geometry::Camera& camera);

  private:
    double last_x_ = 0, last_y_ = 0;
    bool dragging_ = false;
};

} // namespace ks::runtime
