#pragma once
// Shared GL context for the render tests (one hidden window for the whole run) and image checks.
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "shell/offscreen_context.h"

#include <string>
#include <vector>

// The first line of every GL test case: without a GL context the case stops here with this message.
#define KS_REQUIRE_GL()                                                                                      \
    REQUIRE_MESSAGE(ks::test::gl_context(),                                                                  \
                    "no OpenGL 3.3 context (no display, and EGL failed): run the GL tests under xvfb-run "   \
                    "(./run.sh test does)")

namespace ks::test {

// The shared offscreen context of the given size (created on first use: a hidden window, or headless EGL with
// no display; null when neither works, and the GL tests then fail with KS_REQUIRE_GL's advice).
shell::OffscreenContext* gl_context();
inline constexpr int kGlWidth = 320, kGlHeight = 180;

struct ImageStats {
    double mean_luma = 0; // 0..255
    double luma_stddev = 0;
    double magenta_fraction = 0; // pixels that look like the magenta placeholder checker
};
ImageStats image_stats(const std::vector<unsigned char>& rgb, int width, int height, int x0 = 0, int y0 = 0,
                       int x1 = -1, int y1 = -1);
// Renders `frame` in the shared context at its size (the frame's size and the camera's aspect made the
// context's): the RGB rows (top-down) and the renderer's statistics.
struct OffscreenShot {
    std::vector<unsigned char> rgb;
    render::FrameStats stats;
};
OffscreenShot render_frame_offscreen(render::SceneRenderer& renderer, render::SceneFrame frame);
// The main level's start view with the rifle, drawn in the shared context by a renderer with `settings`, the
// level built as the game builds it for that renderer but with the direct light alone in its bake (the
// bounce and occlusion are test_light_bake.cpp's; the full bake would add seconds to each picture);
// `fog_density` < 0: the level's own fog.
// Builds every shader program in the shared context, checking each links (its error in the message); the
// number built.
int check_every_program_builds();
OffscreenShot render_main_level_start(const render::RendererSettings& settings, float fog_density = -1.0f);
// Renders `instances` in the shared context at its size (the camera's aspect made the context's) and
// returns RGB rows (top-down).
std::vector<unsigned char> render_offscreen(render::SceneRenderer& renderer, const geometry::Camera& camera,
                                            const render::Environment& env,
                                            const std::vector<render::MeshInstance>& instances,
                                            const std::vector<render::Light>& lights,
                                            const render::ViewModel* view_model = nullptr);
// Mean absolute difference per channel (0..255) between two RGB images of the same size.
double mean_abs_diff(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b);

// The light map with the direct light alone: these pictures check the renderer, not the bake's bounce and
// occlusion (test_light_bake.cpp), and the full bake would add seconds of CPU to each.
inline render::LevelSceneOptions direct_light_only() {
    render::LevelSceneOptions options;
    options.bake = render::BakeSettings::direct_only();
    return options;
}

} // namespace ks::test
