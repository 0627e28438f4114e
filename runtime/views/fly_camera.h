#pragma once
// Free-fly camera for looking around a level: WASD moves, Q/E (or Space/C) go down/up, Shift is faster,
// the mouse looks around while the right button is held.
#include "geometry/camera.h"

#include <string>

struct GLFWwindow;

namespace ks::runtime {

class FlyCamera {
  public:
    void update(GLFWwindow* window, double dt, geometry::Camera& camera);

  private:
    double last_x_ = 0, last_y_ = 0;
    bool dragging_ = false;
};

// Parses "x,y,z,yaw,pitch" (yaw/pitch in degrees; yaw 0 looks along -z) into the camera.
bool parse_camera(const std::string& text, geometry::Camera& camera);

} // namespace ks::runtime
