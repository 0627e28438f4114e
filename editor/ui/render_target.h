#pragma once
// The viewport's and the dojo preview's target, shown with ImGui::Image: render::RenderTarget with a
// sampled colour texture, resized lazily to the panel's size. The GL is all in common/render/.
#include "core/log.h"
#include "render/render_target.h"
#include "render/window_target.h"

namespace ks::editor::ui {

class RenderTarget {
  public:
    // (Re)creates the attachments when the size changed; false (logged) if the framebuffer is incomplete.
    bool ensure(int width, int height) {
        auto made = target_.ensure(width, height);
        if (!made) log::warn(made.error().str());
        return made.ok();
    }
    void bind() const { target_.bind(); } // draw target for the next render
    // Binds the window, clears it (behind the panels) and sets the full viewport for ImGui.
    static void clear_window(int width, int height) {
        render::clear_window_target(width, height, Vec3(0.09f, 0.1f, 0.12f));
    }
    unsigned texture() const { return target_.texture(); }
    int width() const { return target_.width(); }
    int height() const { return target_.height(); }

  private:
    render::RenderTarget target_{{render::ColourStorage::Texture, 0}};
};

} // namespace ks::editor::ui
