#pragma once
// The one framebuffer type: a colour attachment (a texture to sample, or a renderbuffer, optionally
// multisampled) plus a 24-bit depth buffer, created lazily and re-created when the size changes. The
// offscreen context, the editor's viewport and dojo preview, and the scene renderer's MSAA and
// reduced-resolution targets are all one of these.
#include "core/result.h"

#include <vector>

namespace ks::render {

enum class ColourStorage {
    Texture,      // sampled afterwards (ImGui::Image in the editor)
    Renderbuffer, // only drawn into, blitted or read back
};

struct RenderTargetFormat {
    ColourStorage colour = ColourStorage::Texture;
    int samples = 0; // > 0: multisampled (Renderbuffer only); resolve it with blit_to
};

class RenderTarget {
  public:
    explicit RenderTarget(RenderTargetFormat format = {}) : format_(format) {}
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    // (Re)creates the attachments when the size changed (sizes below 1 become 1); an error when the driver
    // cannot complete the framebuffer (e.g. an unsupported sample count). Leaves the window bound.
    Result<void> ensure(int width, int height);
    void bind() const; // draw target for the next draws, viewport = the full target
    // Copies the colour into `target_framebuffer` (0: the window) scaled to width x height; `smooth`
    // filters bilinearly (a scale-up), else nearest (an MSAA resolve). Leaves `target_framebuffer` bound.
    void blit_to(unsigned target_framebuffer, int width, int height, bool smooth) const;
    // The colour as top-down RGB rows (width * height * 3 bytes) into `rgb`, reusing its capacity.
    void read_rgb(std::vector<unsigned char>& rgb) const;

    unsigned framebuffer() const { return framebuffer_; }
    unsigned texture() const { return format_.colour == ColourStorage::Texture ? colour_ : 0; }
    int width() const { return width_; }
    int height() const { return height_; }
    const RenderTargetFormat& format() const { return format_; }

  private:
    void allocate_colour(int width, int height) const;
    void allocate_depth(int width, int height) const;

    RenderTargetFormat format_;
    unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace ks::render
