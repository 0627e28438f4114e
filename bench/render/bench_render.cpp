// ks_bench render: frame times of a level at 1280x720 over a fixed camera path (offscreen, so the numbers
// do not depend on a window manager or vsync). The default configuration is compared, in the same run,
// with variants that switch one feature at a time (anisotropic filtering, shadows, normal/bump maps, lights
// per object, resolution, MSAA, shadow map every frame), so each feature's cost is read as a ratio.
#include "bench_registry.h"

#include "core/cli.h"
#include "core/log.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "render/asset_library.h"
#include "render/level_scene.h"
#include "render/offscreen.h"
#include "render/scene_renderer.h"
#include "render/texture_cache.h"
#include "render/view_model.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace {
using namespace ks;

struct Variant {
    const char* name;
    int msaa;
    bool shadow_every_frame = false;
    float anisotropy = 0.0f; // 0: the renderer's default for this GL renderer
    bool shadows = true;
    bool surface_detail = true;
    int max_lights = render::kMaxLightsPerDraw;
    int resolution_divisor = 1;
};

struct Measurement {
    double median_ms = 0, p99_ms = 0, mean_ms = 0;
    int draw_calls = 0;
    long long triangles = 0;
};

// The camera path: from the player start down room 1 toward door 1, turning left and right.
render::Camera path_camera(const render::Camera& start, int frame, int frames) {
    render::Camera c = start;
    float t = static_cast<float>(frame) / std::max(frames - 1, 1);
    c.position += Vec3(-std::sin(start.yaw), 0.0f, -std::cos(start.yaw)) * (40.0f * t);
    c.yaw += 0.7f * std::sin(t * 2.0f * kPi);
    c.pitch = -0.1f * std::sin(t * 4.0f * kPi);
    return c;
}

Measurement measure(render::OffscreenContext& ctx, render::AssetLibrary& assets, render::LevelScene& scene,
                    const level::Level& level, const Variant& v, int frames, bool& ok) {
    Measurement m;
    render::RendererSettings settings;
    settings.msaa_samples = v.msaa;
    settings.shadows = v.shadows;
    settings.surface_detail = v.surface_detail;
    settings.max_lights_per_draw = v.max_lights;
    const float default_anisotropy = assets.textures().max_anisotropy();
    if (v.anisotropy > 0.0f) assets.textures().set_max_anisotropy(v.anisotropy);
    const int width = ctx.width() / v.resolution_divisor, height = ctx.height() / v.resolution_divisor;
    auto renderer = render::SceneRenderer::create(assets.textures(), settings);
    if (!renderer) {
        log::error(renderer.error().str());
        ok = false;
        return m;
    }
    std::vector<render::MeshInstance> instances;
    std::vector<render::Light> lights;
    std::vector<Mat4> scratch;
    render::ViewModel view_model;
    assets.model("rifle").emit(render::rifle_view_transform(0.0f), scratch, view_model.instances);
    const render::Camera start = render::player_start_camera(level, static_cast<float>(width) / height);
    std::vector<double> times;
    times.reserve(static_cast<size_t>(frames));
    const int warmup = 10;
    for (int i = -warmup; i < frames; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        scene.emit(instances, lights);
        render::SceneFrame frame;
        frame.camera = path_camera(start, std::max(i, 0), frames);
        frame.environment = scene.environment();
        frame.instances = &instances;
        frame.lights = &lights;
        frame.view_model = &view_model;
        frame.width = width;
        frame.height = height;
        if (v.shadow_every_frame) (*renderer)->invalidate_shadows();
        ctx.bind();
        auto stats = (*renderer)->render(frame);
        ctx.finish();
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (i >= 0) {
            times.push_back(ms);
            m.draw_calls = std::max(m.draw_calls, stats.draw_calls);
            m.triangles = std::max(m.triangles, stats.triangles);
        }
    }
    assets.textures().set_max_anisotropy(default_anisotropy);
    std::sort(times.begin(), times.end());
    m.median_ms = times[times.size() / 2];
    m.p99_ms = times[std::min(times.size() - 1, static_cast<size_t>(times.size() * 0.99))];
    for (double t : times) m.mean_ms += t / times.size();
    return m;
}

int run(int argc, const char* const* argv) {
    auto cl = CommandLine::parse(argc, argv, {"json", "quick"});
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    if (auto unknown = cl->unknown({"level", "json", "frames", "width", "height", "quick"});
        !unknown.empty()) {
        log::error("ks_bench render: unknown option --", unknown.front(),
                   " (use --level FILE --frames N --width W --height H --json --quick)");
        return 2;
    }
    auto frames = cl->get_int("frames", 200, 10, 100000);
    auto width = cl->get_int("width", 1280, 64, 8192);
    auto height = cl->get_int("height", 720, 64, 8192);
    for (const auto* r : {&frames, &width, &height})
        if (!*r) {
            log::error(r->error().str());
            return 2;
        }
    auto path = paths::resolve_user_path(cl->get_or("level", paths::level("main.json").string()));
    auto level = level::load_level_file(path);
    if (!level) {
        log::error(level.error().str());
        return 2;
    }
    auto ctx = render::OffscreenContext::create(*width, *height);
    if (!ctx) {
        log::error(ctx.error().str(),
                   "\n  run it as: xvfb-run -a -s \"-screen 0 1280x720x24\" ks_bench render");
        return 3;
    }
    render::AssetLibrary assets(paths::asset(""));
    auto scene = render::LevelScene::build(*level, assets);
    const std::string renderer = (*ctx)->renderer();
    const int default_msaa = render::default_msaa_for(renderer);
    std::vector<Variant> variants = {{"default", default_msaa}};
    if (!cl->has("quick")) {
        auto with = [&](const char* name, auto change) {
            Variant v{name, default_msaa};
            change(v);
            variants.push_back(v);
        };
        with("anisotropic 8x", [](Variant& v) { v.anisotropy = 8.0f; });
        with("anisotropic off (1x)", [](Variant& v) { v.anisotropy = 1.0f; });
        with("no sun shadows", [](Variant& v) { v.shadows = false; });
        with("no normal/bump maps", [](Variant& v) { v.surface_detail = false; });
        with("1 light per object", [](Variant& v) { v.max_lights = 1; });
        with("4 lights per object", [](Variant& v) { v.max_lights = 4; });
        with("half resolution", [](Variant& v) { v.resolution_divisor = 2; });
        with("msaa 0x", [](Variant& v) { v.msaa = 0; });
        with("msaa 2x", [](Variant& v) { v.msaa = 2; });
        with("msaa 4x", [](Variant& v) { v.msaa = 4; });
        with("shadow map every frame", [](Variant& v) { v.shadow_every_frame = true; });
    }
    std::printf("render benchmark: %s, %dx%d, %d frames on a fixed path, GL renderer: %s, default "
                "anisotropy %.0fx, msaa %dx\n",
                path.string().c_str(), *width, *height, *frames, renderer.c_str(),
                assets.textures().max_anisotropy(), default_msaa);
    std::printf("%-24s %10s %10s %8s %8s %10s %12s\n", "variant", "median ms", "p99 ms", "fps", "draws",
                "triangles", "vs default");
    Measurement base;
    bool ok = true;
    for (size_t i = 0; i < variants.size(); ++i) {
        Measurement m = measure(**ctx, assets, *scene, *level, variants[i], *frames, ok);
        if (!ok) return 1;
        if (i == 0) base = m;
        std::printf("%-24s %10.2f %10.2f %8.1f %8d %10lld %11.2fx\n", variants[i].name, m.median_ms, m.p99_ms,
                    1000.0 / m.median_ms, m.draw_calls, m.triangles, m.median_ms / base.median_ms);
    }
    if (cl->has("json"))
        std::printf("{\"level\":\"%s\",\"width\":%d,\"height\":%d,\"msaa\":%d,\"frame_ms_median\":%.3f,"
                    "\"frame_ms_p99\":%.3f,"
                    "\"fps_median\":%.1f,\"draw_calls\":%d,\"triangles\":%lld,\"renderer\":\"%s\"}\n",
                    path.filename().string().c_str(), *width, *height, default_msaa, base.median_ms,
                    base.p99_ms, 1000.0 / base.median_ms, base.draw_calls, base.triangles, renderer.c_str());
    return 0;
}

const bench::Registrar kRegistrar({"render",
                                   "level frame time at 1280x720 over a fixed camera path (needs a display)",
                                   run, false});
} // namespace
