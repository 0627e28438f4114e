#pragma once
// An OpenGL 3.3 core context with no window system, through EGL: a GPU's own EGL device
// (EGL_EXT_platform_device, as NVIDIA's driver offers on a headless server) or else Mesa's surfaceless
// platform (llvmpipe). Used by OffscreenContext when no display is set or KS_GL_PLATFORM=egl: benchmarks and
// GL tests on a machine without an X server need no Xvfb. libepoxy loads libEGL.so.1 when first called, so
// nothing links EGL.
#include "core/result.h"

#include <memory>
#include <string>

namespace ks::shell {

class EglHeadlessContext {
  public:
    // Tries each EGL device, then the surfaceless platform; the context is current on return.
    static Result<std::unique_ptr<EglHeadlessContext>> create();
    ~EglHeadlessContext();
    EglHeadlessContext(const EglHeadlessContext&) = delete;
    EglHeadlessContext& operator=(const EglHeadlessContext&) = delete;

    void make_current() const;
    const std::string& platform() const { return platform_; } // "EGL device 0", "EGL surfaceless"

  private:
    EglHeadlessContext() = default;
    void* display_ = nullptr; // EGLDisplay, EGLContext, EGLSurface: opaque here so the header needs no EGL
    void* context_ = nullptr;
    void* surface_ = nullptr; // a 1x1 pbuffer where the driver lacks EGL_KHR_surfaceless_context
    std::string platform_;
};

} // namespace ks::shell
