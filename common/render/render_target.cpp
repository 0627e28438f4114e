#include "render/render_target.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

namespace ks::render {

RenderTarget::~RenderTarget() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (colour_) {
        if (format_.colour == ColourStorage::Texture)
            glDeleteTextures(1, &colour_);
        else
            glDeleteRenderbuffers(1, &colour_);
    }
    if (depth_) glDeleteRenderbuffers(1, &depth_);
}

void RenderTarget::allocate_colour(int width, int height) const {
    if (format_.colour == ColourStorage::Texture) {
        glBindTexture(GL_TEXTURE_2D, colour_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);
        return;
    }
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    if (format_.samples > 0)
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, format_.samples, GL_RGBA8, width, height);
    else
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
}

// 32-bit float depth: llvmpipe compares it as it comes from the rasteriser, where 24-bit depth is converted
// per fragment (and 24-bit with stencil also keeps the stencil bits on every write): docs/performance.md,
// "Session 24". GPUs handle either at the same speed.
void RenderTarget::allocate_depth(int width, int height) const {
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    if (format_.samples > 0)
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, format_.samples, GL_DEPTH_COMPONENT32F, width,
                                         height);
    else
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
}

Result<void> RenderTarget::ensure(int width, int height) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    if (framebuffer_ && width == width_ && height == height_) return ok();
    const bool texture = format_.colour == ColourStorage::Texture;
    if (texture && format_.samples > 0)
        return Error("a multisampled render target needs renderbuffer colour", Location{},
                     "use ColourStorage::Renderbuffer and resolve with blit_to");
    if (!framebuffer_) {
        glGenFramebuffers(1, &framebuffer_);
        if (texture)
            glGenTextures(1, &colour_);
        else
            glGenRenderbuffers(1, &colour_);
        glGenRenderbuffers(1, &depth_);
    }
    allocate_colour(width, height);
    allocate_depth(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    if (texture)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
    else
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = width;
    height_ = height;
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return Error("framebuffer " + std::to_string(width) + "x" + std::to_string(height) + " with " +
                         std::to_string(format_.samples) + " samples is incomplete (status " +
                         std::to_string(status) + ")",
                     Location{}, "the driver does not support this format; use fewer samples");
    return ok();
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
}

void RenderTarget::blit_to(unsigned target_framebuffer, int width, int height, bool smooth) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_framebuffer);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                      smooth ? GL_LINEAR : GL_NEAREST);
}

void RenderTarget::read_rgb(std::vector<unsigned char>& rgb) const {
    const size_t stride = static_cast<size_t>(width_) * 3;
    rgb.resize(stride * static_cast<size_t>(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    // GL rows run bottom-up: swap them in place.
    for (int y = 0; y < height_ / 2; ++y)
        std::swap_ranges(rgb.begin() + static_cast<std::ptrdiff_t>(y * stride),
                         rgb.begin() + static_cast<std::ptrdiff_t>((y + 1) * stride),
                         rgb.begin() + static_cast<std::ptrdiff_t>((height_ - 1 - y) * stride));
}

} // namespace ks::render
