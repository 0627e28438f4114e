#include "gl_test_support.h"

#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/shaders.h"
#include "render/view_model.h"
#include "shell/app_shell.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>

namespace ks::test {

shell::OffscreenContext* gl_context() {
    static shell::OffscreenContext* context = []() -> shell::OffscreenContext* {
        // With no display the offscreen context is a headless EGL one (KS_GL_PLATFORM, shell/egl_headless.h).
        auto ctx = shell::OffscreenContext::create(kGlWidth, kGlHeight);
        return ctx ? ctx->release() : nullptr; // lives for the whole test run
    }();
    return context;
}

ImageStats image_stats(const std::vector<unsigned char>& rgb, int width, int height, int x0, int y0, int x1,
                       int y1) {
    if (x1 < 0) x1 = width;
    if (y1 < 0) y1 = height;
    ImageStats s;
    double sum = 0, sum2 = 0;
    long n = 0, magenta = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const unsigned char* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
            double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            sum += l;
            sum2 += l * l;
            if (p[0] > 180 && p[2] > 180 && p[1] < 70) ++magenta;
            ++n;
        }
    if (n == 0) return s;
    s.mean_luma = sum / n;
    s.luma_stddev = std::sqrt(std::max(0.0, sum2 / n - s.mean_luma * s.mean_luma));
    s.magenta_fraction = static_cast<double>(magenta) / n;
    return s;
}

double mean_abs_diff(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    if (a.size() != b.size() || a.empty()) return 255.0;
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += std::abs(int(a[i]) - int(b[i]));
    return sum / a.size();
}

OffscreenShot render_frame_offscreen(render::SceneRenderer& renderer, render::SceneFrame frame) {
    auto* ctx = gl_context();
    ctx->bind();
    frame.camera.aspect = static_cast<float>(ctx->width()) / ctx->height();
    frame.width = ctx->width();
    frame.height = ctx->height();
    OffscreenShot shot;
    shot.stats = renderer.render(frame);
    shot.rgb = ctx->read_rgb();
    return shot;
}

std::vector<unsigned char> render_offscreen(render::SceneRenderer& renderer, const geometry::Camera& camera,
                                            const render::Environment& env,
                                            const std::vector<render::MeshInstance>& instances,
                                            const std::vector<render::Light>& lights,
                                            const render::ViewModel* view_model) {
    render::SceneFrame frame;
    frame.camera = camera;
    frame.environment = env;
    frame.instances = &instances;
    frame.lights = &lights;
    frame.view_model = view_model;
    return render_frame_offscreen(renderer, frame).rgb;
}

int check_every_program_builds() {
    int count = 0;
    for (const render::ProgramFiles* p : render::all_programs()) {
        CAPTURE(p->name);
        auto program = render::build_program(*p, render::default_shader_dir());
        CHECK_MESSAGE(program.ok(), (program.ok() ? "" : program.error().str()));
        ++count;
    }
    return count;
}

OffscreenShot render_main_level_start(const render::RendererSettings& settings, float fog_density) {
    using namespace render;
    auto level = level::load_level_file(source_dir() / "levels" / "main.json");
    REQUIRE_MESSAGE(level.ok(), (level.ok() ? "" : level.error().str()));
    AssetLibrary assets(source_dir() / "assets");
    auto renderer = SceneRenderer::create(assets.textures(), settings);
    REQUIRE(renderer);
    LevelSceneOptions options = level_scene_options((*renderer)->settings());
    options.bake = BakeSettings::direct_only();
    auto scene = LevelScene::build(*level, assets, options);
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    scene->emit(instances, lights);
    CHECK(lights.size() >= 8);
    ViewModel vm;
    std::vector<Mat4> scratch;
    assets.model("rifle").emit(rifle_view_transform(0.0f), scratch, vm.instances);
    SceneFrame frame;
    frame.camera = player_start_camera(*level, 16.0f / 9.0f);
    frame.environment = scene->environment();
    if (fog_density >= 0.0f) frame.environment.fog_density = fog_density;
    frame.instances = &instances;
    frame.lights = &lights;
    frame.view_model = &vm;
    return render_frame_offscreen(**renderer, frame);
}

} // namespace ks::test
