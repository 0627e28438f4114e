#pragma once
// A GL 3.3 core context without a visible window (a hidden GLFW window) and a colour+depth
// render::RenderTarget of a fixed size to draw into: for tests and benchmarks that need GL but not a
// screen. The shell opens the context; the framebuffer and its read-back are render's.
#include "core/result.h"
#include "render/render_target.h"

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ks::shell {

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

  private:
    OffscreenContext() = default;
    GLFWwindow* window_ = nullptr;
    // Created once the context is current; the destructor frees it before closing the window.
    std::unique_ptr<render::RenderTarget> target_;
};

} // namespace ks::shell
