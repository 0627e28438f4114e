#include "shell/offscreen_context.h"

#include "render/png_writer.h"
#include "render/window_target.h"
#include "shell/display.h"
#include "shell/egl_headless.h"
#include "shell/gl_window.h"
#include "shell/raster_threads.h"

#include <cstdlib>
#include <string_view>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ks::shell {

bool offscreen_wants_egl(const char* platform_variable, bool display_set) {
    const std::string_view platform = platform_variable ? platform_variable : "";
    if (platform == "egl") return true;
    if (platform == "window") return false;
    return !display_set;
}

Result<std::unique_ptr<OffscreenContext>> OffscreenContext::create(int width, int height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        return Error("offscreen size out of range", Location{}, "use 1..16384 pixels per side");
    std::unique_ptr<OffscreenContext> ctx(new OffscreenContext());
    if (offscreen_wants_egl(std::getenv("KS_GL_PLATFORM"), display_available())) {
        configure_software_raster_threads(); // as open_gl_window does: the same llvmpipe set-up as the game's
        auto egl = EglHeadlessContext::create();
        if (!egl) return egl.error();
        ctx->egl_ = std::move(*egl);
    } else {
        // The same window set-up as the game's (llvmpipe threads included), so benchmarks measure the same.
        auto window = open_gl_window({"this program", 64, 64, false, false});
        if (!window) return window.error();
        ctx->window_ = *window;
        glfwSwapInterval(0);
    }
    ctx->target_ = std::make_unique<render::RenderTarget>(
        render::RenderTargetFormat{render::ColourStorage::Renderbuffer, 0});
    if (auto made = ctx->target_->ensure(width, height); !made) return made.error();
    ctx->bind();
    return ctx;
}

OffscreenContext::~OffscreenContext() {
    if (egl_) {
        egl_->make_current();
        target_.reset();
        egl_.reset();
        return;
    }
    if (!window_) return;
    glfwMakeContextCurrent(window_);
    target_.reset();
    close_gl_window(window_);
}

void OffscreenContext::finish() const {
    render::finish_gpu();
}

std::vector<unsigned char> OffscreenContext::read_rgb() const {
    std::vector<unsigned char> rgb;
    target_->read_rgb(rgb);
    return rgb;
}

Result<void> OffscreenContext::save_png(const std::string& path) const {
    auto rgb = read_rgb();
    return render::write_png_rgb(path, width(), height(), rgb.data(), width() * 3);
}

std::string OffscreenContext::platform() const {
    return egl_ ? egl_->platform() : std::string("window");
}

std::string OffscreenContext::renderer() const {
    return render::gl_renderer_name();
}

} // namespace ks::shell
