#pragma once
// A colour texture + depth buffer the viewport and the dojo preview render into, shown with ImGui::Image.
// Resized lazily to the panel's size; the only GL the editor front end owns (the renderer draws into it).
namespace ks::editor::ui {

class RenderTarget {
  public:
    RenderTarget() = default;
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    // (Re)creates the attachments when the size changed; false if the framebuffer is incomplete.
    bool ensure(int width, int height);
    void bind() const;    // draw target for the next render
    static void unbind(); // back to the window
    // Binds the window, clears it (behind the panels) and sets the full viewport for ImGui.
    static void clear_window(int width, int height);
    unsigned texture() const { return color_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    unsigned fbo_ = 0, color_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace ks::editor::ui
