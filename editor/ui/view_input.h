#pragma once
// Reads the viewport camera's input (mouse buttons, wheel, fly keys by physical position) from GLFW.
#include "view/view_camera.h"

struct GLFWwindow;

namespace ks::editor::ui {

ViewInput read_view_input(GLFWwindow* window, bool hovered, Vec2 mouse_in_viewport, float wheel);

} // namespace ks::editor::ui
