#include "render/window_target.h"

#include <epoxy/gl.h>
#include "render/png_writer.h"

#include <vector>

namespace ks::render {

void bind_window_target(int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
}

void clear_window_target(int width, int height, const Vec3& colour) {
    bind_window_target(width, height);
    glClearColor(colour.r, colour.g, colour.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

namespace {
std::string gl_string(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "unknown";
}
} // namespace

std::string gl_renderer_name() {
    return gl_string(GL_RENDERER);
}

std::string gl_version_name() {
    return gl_string(GL_VERSION);
}

void finish_gpu() {
    glFinish();
}

Result<void> save_framebuffer_png(const std::string& path, int width, int height) {
    if (width <= 0 || height <= 0) return Error("empty framebuffer", Location{path});
    std::vector<unsigned char> pixels(static_cast<size_t>(width) * height * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows run bottom-up; PNG rows top-down: write with a negative stride from the last row.
    const int stride = width * 3;
    const unsigned char* last_row = pixels.data() + static_cast<size_t>(height - 1) * stride;
    return write_png_rgb(path, width, height, last_row, -stride);
}

} // namespace ks::render
