#pragma once
// The GL side of the window the shell opens: its default framebuffer (bind, clear, read back for
// screenshots), the driver's names, and waiting for the GPU. common/shell/ creates the window and the
// context; every GL call it needs is here, so only common/render/ talks to OpenGL.
#include "core/math.h"
#include "core/result.h"

#include <string>

namespace ks::render {

// Binds the window's framebuffer with the full viewport (after drawing into a RenderTarget).
void bind_window_target(int width, int height);
// Binds the window's framebuffer with the full viewport and clears colour and depth to `colour`.
void clear_window_target(int width, int height, const Vec3& colour);
// The GL_RENDERER and GL_VERSION strings of the current context ("unknown" when the driver gives none).
std::string gl_renderer_name();
std::string gl_version_name();
// glFinish: waits until the GPU has drawn everything (timings, read-backs).
void finish_gpu();
// Reads the window's back buffer (bottom-up GL rows), flips it and writes an RGB PNG.
Result<void> save_framebuffer_png(const std::string& path, int width, int height);

} // namespace ks::render
