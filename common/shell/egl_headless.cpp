#include "shell/egl_headless.h"

#include <epoxy/egl.h>

#include <algorithm>
#include <string_view>
#include <vector>

namespace ks::shell {

namespace {
const EGLint kContextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};

bool has_extension(const char* list, std::string_view name) {
    if (!list) return false;
    for (std::string_view rest(list); !rest.empty();) {
        const size_t space = rest.find(' ');
        if (rest.substr(0, space) == name) return true;
        if (space == std::string_view::npos) break;
        rest.remove_prefix(space + 1);
    }
    return false;
}

struct Opened {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
};

// A core 3.3 context on an initialised display, current with no surface (or a 1x1 pbuffer); false leaves the
// display terminated.
bool open_context(EGLDisplay display, Opened& out) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) return false;
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    const bool surfaceless = has_extension(extensions, "EGL_KHR_surfaceless_context");
    const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, config_attributes, &config, 1, &count)) count = 0;
    const bool no_config = has_extension(extensions, "EGL_KHR_no_config_context");
    if (count == 0 && !(no_config && surfaceless)) {
        eglTerminate(display);
        return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        return false;
    }
    EGLContext context =
        eglCreateContext(display, count ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, kContextAttributes);
    if (context == EGL_NO_CONTEXT) {
        eglTerminate(display);
        return false;
    }
    EGLSurface surface = EGL_NO_SURFACE;
    if (!surfaceless) {
        const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
    }
    if ((!surfaceless && surface == EGL_NO_SURFACE) || !eglMakeCurrent(display, surface, surface, context)) {
        if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
        eglDestroyContext(display, context);
        eglTerminate(display);
        return false;
    }
    out = {display, context, surface};
    return true;
}
} // namespace

Result<std::unique_ptr<EglHeadlessContext>> EglHeadlessContext::create() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client)
        return Error("EGL is not available (libEGL.so.1 missing or without client extensions)", Location{},
                     "install libegl1 (Debian), or set DISPLAY / run under xvfb-run for a windowed context");
    Opened opened;
    std::string platform;
    if (has_extension(client, "EGL_EXT_device_enumeration") &&
        has_extension(client, "EGL_EXT_platform_device")) {
        EGLint count = 0;
        eglQueryDevicesEXT(0, nullptr, &count);
        std::vector<EGLDeviceEXT> devices(static_cast<size_t>(std::max(count, 0)));
        if (count > 0 && eglQueryDevicesEXT(count, devices.data(), &count)) {
            for (EGLint i = 0; i < count && opened.display == EGL_NO_DISPLAY; ++i) {
                if (open_context(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
                                 opened))
                    platform = "EGL device " + std::to_string(i);
            }
        }
    }
    if (opened.display == EGL_NO_DISPLAY && has_extension(client, "EGL_MESA_platform_surfaceless") &&
        open_context(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                     opened))
        platform = "EGL surfaceless";
    if (opened.display == EGL_NO_DISPLAY)
        return Error(
            "no EGL device or surfaceless display gave an OpenGL 3.3 core context", Location{},
            "check the GPU driver's EGL vendor file (__EGL_VENDOR_LIBRARY_FILENAMES), or set DISPLAY / "
            "run under xvfb-run for a windowed context");
    std::unique_ptr<EglHeadlessContext> made(new EglHeadlessContext());
    made->display_ = opened.display;
    made->context_ = opened.context;
    made->surface_ = opened.surface;
    made->platform_ = std::move(platform);
    return made;
}

EglHeadlessContext::~EglHeadlessContext() {
    if (!display_) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_) eglDestroySurface(display_, surface_);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

void EglHeadlessContext::make_current() const {
    eglMakeCurrent(display_, surface_, surface_, context_);
}

} // namespace ks::shell
