#pragma once
// Opening a GLFW window with an OpenGL 3.3 core context current: the one place that initialises GLFW,
// shared by the visible game/editor window and the hidden window of the offscreen context.
#include "core/result.h"

#include <string>

struct GLFWwindow;

namespace ks::shell {

struct GlWindowRequest {
    std::string title = "Killswitch";
    int width = 1280;
    int height = 720;
    bool visible = true;
    bool srgb = false;
};

// Checks the display, sets LP_NUM_THREADS for llvmpipe (shell/raster_threads.h), initialises GLFW and
// opens the window with its context current. Close it with close_gl_window.
Result<GLFWwindow*> open_gl_window(const GlWindowRequest& request);
// Destroys the window and terminates GLFW.
void close_gl_window(GLFWwindow* window);

} // namespace ks::shell
