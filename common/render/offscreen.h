#pragma once
// A GL 3.3 core context without a visible window (a hidden GLFW window) and a colour+depth framebuffer
// of a fixed size to render into: for tests and benchmarks that need GL but not a screen.
#include "core/result.h"

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ks::render {

class OffscreenContext {
  public:
    static Result<std::unique_ptr<OffscreenContext>> create(int width, int height);
    ~OffscreenContext();

    void bind() const;   // makes the framebuffer the draw target, viewport = full size
    void finish() const; // glFinish: waits for the GPU (timing)
    // Reads the framebuffer as top-down RGB rows.
    std::vector<unsigned char> read_rgb() const;
    Result<void> save_png(const std::string& path) const;
    int width() const { return width_; }
    int height() const { return height_; }
    std::string renderer() const;

  private:
    OffscreenContext() = default;
    GLFWwindow* window_ = nullptr;
    unsigned fbo_ = 0, color_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace ks::render
