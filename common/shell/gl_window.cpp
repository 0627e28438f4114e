#include "shell/gl_window.h"

#include "core/log.h"
#include "shell/display.h"
#include "shell/raster_threads.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ks::shell {

namespace {
void glfw_error_callback(int code, const char* description) {
    log::error("GLFW error ", code, ": ", description);
}
} // namespace

Result<GLFWwindow*> open_gl_window(const GlWindowRequest& request) {
    if (!display_available()) return Error(no_display_message(request.title));
    glfwSetErrorCallback(glfw_error_callback);
    configure_software_raster_threads(); // before the context: llvmpipe reads it once
    if (!glfwInit())
        return Error("cannot initialise GLFW (is the X server reachable?)", Location{},
                     no_display_message(request.title));
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    if (request.srgb) glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0); // MSAA is done in the renderer's own framebuffer
    // Depth without stencil (nothing draws with a stencil test): on llvmpipe a depth buffer with stencil
    // keeps the stencil bits on every depth write (docs/performance.md, "Session 24").
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    glfwWindowHint(GLFW_VISIBLE, request.visible ? GLFW_TRUE : GLFW_FALSE);
    GLFWwindow* window =
        glfwCreateWindow(request.width, request.height, request.title.c_str(), nullptr, nullptr);
    if (!window) {
        glfwTerminate();
        return Error("cannot create an OpenGL 3.3 core window", Location{},
                     "the driver must support OpenGL 3.3 core; under Xvfb, Mesa's llvmpipe does");
    }
    glfwMakeContextCurrent(window);
    return window;
}

void close_gl_window(GLFWwindow* window) {
    if (!window) return;
    glfwDestroyWindow(window);
    glfwTerminate();
}

} // namespace ks::shell
