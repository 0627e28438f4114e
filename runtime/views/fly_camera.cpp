#include "views/fly_camera.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace ks::runtime {

void FlyCamera::update(GLFWwindow* window, double dt, geometry::Camera& camera) {
    auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    const float speed = static_cast<float>(dt) * (down(GLFW_KEY_LEFT_SHIFT) ? 40.0f : 12.0f);
    Vec3 forward(-std::sin(camera.yaw), 0.0f, -std::cos(camera.yaw));
    Vec3 right(std::cos(camera.yaw), 0.0f, -std::sin(camera.yaw));
    if (down(GLFW_KEY_W)) camera.position += forward * speed;
    if (down(GLFW_KEY_S)) camera.position -= forward * speed;
    if (down(GLFW_KEY_D)) camera.position += right * speed;
    if (down(GLFW_KEY_A)) camera.position -= right * speed;
    if (down(GLFW_KEY_E) || down(GLFW_KEY_SPACE)) camera.position.y += speed;
    if (down(GLFW_KEY_Q) || down(GLFW_KEY_C)) camera.position.y -= speed;
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    bool drag = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (drag && dragging_) {
        camera.yaw -= static_cast<float>(x - last_x_) * 0.004f;
        camera.pitch = std::clamp(camera.pitch - static_cast<float>(y - last_y_) * 0.004f, -1.5f, 1.5f);
    }
    dragging_ = drag;
    last_x_ = x;
    last_y_ = y;
}

} // namespace ks::runtime
