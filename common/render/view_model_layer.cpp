#include "render/view_model_layer.h"

#include "geometry/convex_hull_2d.h"
#include "render/gpu_mesh.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

namespace ks::render {

void view_model_footprint(const std::vector<MeshInstance>& instances, const Mat4& projection, int width,
                          int height, ScreenFootprint& out) {
    constexpr float kRim = 1.5f; // pixels around the outline: the edge filter reads one pixel around
    out.rect = {};
    out.hull.clear();
    float lo_x = 1e30f, lo_y = 1e30f, hi_x = -1e30f, hi_y = -1e30f;
    for (const MeshInstance& inst : instances) {
        if (!inst.mesh) continue;
        const Mat4 to_clip = projection * inst.world;
        for (const Vec3& corner : inst.mesh->hull_corners()) {
            const Vec4 clip = to_clip * Vec4(corner, 1.0f);
            // A corner behind the eye projects nowhere useful: the whole target may be covered.
            if (clip.w <= 1e-4f) {
                out.rect = PixelRect{0, 0, width, height};
                out.hull.clear();
                return;
            }
            const float x = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width);
            const float y = (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(height);
            lo_x = std::min(lo_x, x);
            lo_y = std::min(lo_y, y);
            hi_x = std::max(hi_x, x);
            hi_y = std::max(hi_y, y);
            out.hull.push_back(Vec2(x, y));
        }
    }
    if (lo_x > hi_x) {
        out.hull.clear();
        return;
    }
    const int x0 = std::clamp(static_cast<int>(std::floor(lo_x - kRim)), 0, width);
    const int y0 = std::clamp(static_cast<int>(std::floor(lo_y - kRim)), 0, height);
    const int x1 = std::clamp(static_cast<int>(std::ceil(hi_x + kRim)), 0, width);
    const int y1 = std::clamp(static_cast<int>(std::ceil(hi_y + kRim)), 0, height);
    out.rect = PixelRect{x0, y0, x1 - x0, y1 - y0};
    // The outline widened by the rim: the hull of each outline corner's rim square (the hull of a sum of
    // convex sets is the sum of their hulls), in place from the back.
    geometry::convex_hull_2d(out.hull);
    const std::size_t n = out.hull.size();
    out.hull.resize(4 * n);
    for (std::size_t i = n; i-- > 0;) {
        const Vec2 p = out.hull[i];
        out.hull[4 * i + 0] = p + Vec2(-kRim, -kRim);
        out.hull[4 * i + 1] = p + Vec2(kRim, -kRim);
        out.hull[4 * i + 2] = p + Vec2(kRim, kRim);
        out.hull[4 * i + 3] = p + Vec2(-kRim, kRim);
    }
    geometry::convex_hull_2d(out.hull);
    if (out.hull.size() >= 3)
        geometry::clip_convex_polygon(out.hull, Vec2(static_cast<float>(x0), static_cast<float>(y0)),
                                      Vec2(static_cast<float>(x1), static_cast<float>(y1)));
    else
        out.hull.clear();
}

ViewModelLayer::ViewModelLayer() {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vertex_buffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vec2), nullptr);
    glBindVertexArray(0);
}

ViewModelLayer::~ViewModelLayer() {
    glDeleteBuffers(1, &vertex_buffer_);
    glDeleteVertexArrays(1, &vao_);
}

Result<void> ViewModelLayer::begin(int width, int height, int samples, const PixelRect& rect) {
    samples_ = samples;
    resolved_this_frame_ = false;
    if (samples > 1) {
        if (!multisampled_ || multisampled_->format().samples != samples)
            multisampled_ =
                std::make_unique<RenderTarget>(RenderTargetFormat{ColourStorage::Renderbuffer, samples});
        if (auto made = multisampled_->ensure(width, height); !made) return made;
    }
    if (auto made = resolved_.ensure(width, height); !made) return made;
    width_ = width;
    height_ = height;
    if (samples > 1)
        multisampled_->bind();
    else
        resolved_.bind();
    glViewport(0, 0, width, height);
    glEnable(GL_SCISSOR_TEST);
    // Two pixels wider than the composited rectangle: the edge filter reads one pixel around each of its
    // pixels, and texels outside the cleared area hold an earlier frame.
    const int x0 = std::max(0, rect.x - 2), y0 = std::max(0, rect.y - 2);
    glScissor(x0, y0, std::min(width, rect.x + rect.width + 2) - x0,
              std::min(height, rect.y + rect.height + 2) - y0);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glScissor(rect.x, rect.y, rect.width, rect.height);
    return ok();
}

void ViewModelLayer::resolve(const PixelRect& rect) {
    if (resolved_this_frame_) return;
    resolved_this_frame_ = true;
    if (samples_ <= 1) return;
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_->framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_.framebuffer());
    const int x1 = rect.x + rect.width, y1 = rect.y + rect.height;
    glBlitFramebuffer(rect.x, rect.y, x1, y1, rect.x, rect.y, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void ViewModelLayer::draw_footprint(const ScreenFootprint& where) {
    const PixelRect& rect = where.rect;
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x, rect.y, rect.width, rect.height);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, resolved_.texture());
    glBindSampler(0, 0);
    // The hull (or the rectangle) as a triangle fan in clip space.
    fan_.clear();
    auto to_clip = [&](float x, float y) {
        fan_.push_back(Vec2(x / static_cast<float>(width_) * 2.0f - 1.0f,
                            y / static_cast<float>(height_) * 2.0f - 1.0f));
    };
    if (!where.hull.empty())
        for (const Vec2& p : where.hull) to_clip(p.x, p.y);
    else {
        const float x0 = static_cast<float>(rect.x), y0 = static_cast<float>(rect.y);
        const float x1 = x0 + static_cast<float>(rect.width), y1 = y0 + static_cast<float>(rect.height);
        to_clip(x0, y0), to_clip(x1, y0), to_clip(x1, y1), to_clip(x0, y1);
    }
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(fan_.size() * sizeof(Vec2)), fan_.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(fan_.size()));
    glDisable(GL_SCISSOR_TEST);
}

void ViewModelLayer::write_depth_mask(unsigned target_framebuffer, const ScreenFootprint& where) {
    resolve(where.rect);
    glBindFramebuffer(GL_FRAMEBUFFER, target_framebuffer);
    glViewport(0, 0, width_, height_);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    mask_.use();
    draw_footprint(where);
    glDepthFunc(GL_LESS);
}

void ViewModelLayer::composite(unsigned target_framebuffer, const ScreenFootprint& where, bool masked) {
    resolve(where.rect);
    glBindFramebuffer(GL_FRAMEBUFFER, target_framebuffer);
    glViewport(0, 0, width_, height_);
    glDepthMask(GL_FALSE);
    if (masked) {
        glEnable(GL_DEPTH_TEST); // the opaque pixels (depth 0) hold the layer already
        glDepthFunc(GL_LESS);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    composite_.use();
    glUniform1i(composite_.location("u_edge_filter"), samples_ > 1 ? 0 : 1);
    glUniform2i(composite_.location("u_last_texel"), width_ - 1, height_ - 1);
    draw_footprint(where);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

} // namespace ks::render
