// The depth buffers the renderer draws into: its own targets hold 32-bit float depth and the window's has
// no stencil (on llvmpipe a 24-bit depth is converted per fragment and a stencil is kept on every depth
// write: docs/performance.md, "Session 24").
#include "gl_test_support.h"

#include "render/render_target.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>

namespace {

struct DepthAttachment {
    GLint bits = 0, stencil_bits = 0, type = 0;
};

DepthAttachment depth_of(GLuint framebuffer) {
    DepthAttachment d;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    const GLenum depth = framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
    const GLenum stencil = framebuffer == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                          &d.bits);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                          &d.type);
    GLint stencil_type = GL_NONE;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                          &stencil_type);
    if (stencil_type != GL_NONE)
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                                              &d.stencil_bits);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return d;
}

} // namespace

TEST_CASE("the renderer's targets hold 32-bit float depth, plain and multisampled") {
    KS_REQUIRE_GL();
    for (int samples : {0, 4}) {
        CAPTURE(samples);
        ks::render::RenderTargetFormat format;
        format.samples = samples;
        format.colour = samples > 0 ? ks::render::ColourStorage::Renderbuffer : format.colour;
        ks::render::RenderTarget target(format);
        REQUIRE(target.ensure(64, 32));
        const DepthAttachment d = depth_of(target.framebuffer());
        CHECK(d.bits == 32);
        CHECK(d.type == GL_FLOAT);
        CHECK(d.stencil_bits == 0);
        CHECK(glGetError() == GL_NO_ERROR);
    }
}

TEST_CASE("the window's framebuffer has depth and no stencil") {
    KS_REQUIRE_GL();
    if (ks::test::gl_context()->platform() != "window") {
        MESSAGE("headless EGL context: no window framebuffer to check");
        return;
    }
    const DepthAttachment d = depth_of(0);
    CHECK(d.bits >= 24);
    CHECK(d.stencil_bits == 0);
    CHECK(glGetError() == GL_NO_ERROR);
}
