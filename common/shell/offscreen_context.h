#pragma once
// A GL 3.3 core context without a visible window (a hidden GLFW window, or with no display or
// KS_GL_PLATFORM=egl a headless EGL context: shell/egl_headless.h) and a colour+depth render::RenderTarget of
// a fixed size to draw into: for tests and benchmarks that need GL but not a screen. The shell opens the
// context; the framebuffer and its read-back are render's.
#include "core/result.h"
#include "render/render_target.h"

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ks::shell {

class EglHeadlessContext;

class OffscreenContext {
  public:
    static Result<std::unique_ptr<OffscreenContext>> create(int width, int height);
    ~OffscreenContext();

    void bind() const { target_->bind(); } // the target is the draw framebuffer, viewport = full size
    void finish() const;                   // waits for the GPU (timing)
    // Reads the target as top-down RGB rows.
    std::vector<unsigned char> read_rgb() const;
    Result<void> save_png(const std::string& path) const;
    int width() const { return target_->width(); }
    int height() const { return target_->height(); }
    std::string renderer() const;
    std::string platform() const; // "window" or the EGL platform ("EGL device 0", "EGL surfaceless")

  private:
    OffscreenContext() = default;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<EglHeadlessContext> egl_; // instead of window_
    // Created once the context is current; the destructor frees it before closing the window.
    std::unique_ptr<render::RenderTarget> target_;
};

// KS_GL_PLATFORM's value: "egl" = the headless EGL context, "window" = a hidden window; unset (or anything
// else) = a window when a display is set, else EGL.
bool offscreen_wants_egl(const char* platform_variable, bool display_set);

} // namespace ks::shell
