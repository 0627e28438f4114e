#include "render/offscreen.h"

#include "render/app_shell.h"
#include "render/raster_threads.h"

// epoxy must come before any header that pulls in GL/gl.h.
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <stb_image_write.h>

namespace ks::render {

Result<std::unique_ptr<OffscreenContext>> OffscreenContext::create(int width, int height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        return Error("offscreen size out of range", Location{}, "use 1..16384 pixels per side");
    if (!display_available()) return Error(no_display_message("this program"));
    configure_software_raster_threads(); // what the game's window does, so the benchmarks measure the same
    if (!glfwInit()) return Error("cannot initialise GLFW", Location{}, no_display_message("this program"));
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    std::unique_ptr<OffscreenContext> ctx(new OffscreenContext());
    ctx->window_ = glfwCreateWindow(64, 64, "offscreen", nullptr, nullptr);
    if (!ctx->window_)
        return Error("cannot create an OpenGL 3.3 core context", Location{}, "Mesa's llvmpipe supports it");
    glfwMakeContextCurrent(ctx->window_);
    glfwSwapInterval(0);
    ctx->width_ = width;
    ctx->height_ = height;
    glGenFramebuffers(1, &ctx->fbo_);
    glGenRenderbuffers(1, &ctx->color_);
    glGenRenderbuffers(1, &ctx->depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, ctx->color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, ctx->depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ctx->color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ctx->depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return Error("offscreen framebuffer incomplete");
    ctx->bind();
    return ctx;
}

OffscreenContext::~OffscreenContext() {
    if (window_) {
        glfwMakeContextCurrent(window_);
        glDeleteFramebuffers(1, &fbo_);
        glDeleteRenderbuffers(1, &color_);
        glDeleteRenderbuffers(1, &depth_);
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
}

void OffscreenContext::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

void OffscreenContext::finish() const {
    glFinish();
}

std::vector<unsigned char> OffscreenContext::read_rgb() const {
    std::vector<unsigned char> rows(static_cast<size_t>(width_) * height_ * 3), flipped(rows.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const size_t stride = static_cast<size_t>(width_) * 3;
    for (int y = 0; y < height_; ++y)
        std::copy_n(rows.data() + static_cast<size_t>(height_ - 1 - y) * stride, stride,
                    flipped.data() + y * stride);
    return flipped;
}

Result<void> OffscreenContext::save_png(const std::string& path) const {
    auto rgb = read_rgb();
    if (!stbi_write_png(path.c_str(), width_, height_, 3, rgb.data(), width_ * 3))
        return Error("cannot write PNG", Location{path}, "check that the folder exists and is writable");
    return ok();
}

std::string OffscreenContext::renderer() const {
    const GLubyte* name = glGetString(GL_RENDERER);
    return name ? reinterpret_cast<const char*>(name) : "unknown";
}

} // namespace ks::render
