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
#include "render/dynamic_resolution.h"
#include "render/level_scene.h"
#include "render/model_field.h"
#include "render/scene_renderer.h"
#include "render/texture_cache.h"
#include "render/view_model.h"
#include "shell/offscreen_context.h"

#include <epoxy/gl.h>
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_DUMP_STATS_AT(name)
#endif

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <optional>
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
    render::RenderQuality quality = render::RenderQuality::Auto;
    bool occluded_base = true;
    float render_scale = 0.0f; // 0: the renderer's default for this GL renderer
    bool occlusion_culling = true;
    bool depth_prepass = true;
    bool fast_level_shader = true;
    bool doors_occlude = true;
    bool fast_trilinear = false;
    int view_model_msaa = render::RendererSettings{}.view_model_msaa;
    bool contact_shadows = true;
    bool model_lods = true;        // designers' models drawn at their levels of detail
    bool dynamic = false;          // the render scale picked each frame as the game's Auto does on software
    bool model_shaders = true;     // RendererSettings::fast_model_shaders
    bool prepass_floors = false;   // !RendererSettings::prepass_skips_floors
    bool rifle = true;             // the first-person rifle drawn
    bool cull_single_sided = true; // RendererSettings::cull_single_sided
    bool view_model_mask = true;   // RendererSettings::view_model_depth_mask
};

struct Measurement {
    double median_ms = 0, p99_ms = 0, mean_ms = 0;
    double cpu_ms = 0; // process CPU time per frame (all threads: llvmpipe's rasteriser threads too)
    std::vector<double> times;
    double cpu_total_ms = 0;
    bool fast = false;
    int internal_width = 0, internal_height = 0;
    int draw_calls = 0;
    long long triangles = 0;
    long long occluded = 0;    // instances skipped behind occluder boxes, summed over the timed frames
    double samples_passed = 0; // fragments that passed the depth test, summed over the timed frames
    double overdraw = 0;       // samples_passed per internal pixel per frame (1.0: every pixel shaded once)
    // Variant::dynamic: the game's controller, kept across rounds, and the frames drawn at each of its steps.
    std::optional<render::DynamicResolution> dynamic;
    std::map<float, int> frames_at_scale;
};

double cpu_now_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// The camera path: from the player start down room 1 toward door 1, turning left and right.
geometry::Camera path_camera(const geometry::Camera& start, int frame, int frames) {
    geometry::Camera c = start;
    float t = static_cast<float>(frame) / std::max(frames - 1, 1);
    c.position += Vec3(-std::sin(start.yaw), 0.0f, -std::cos(start.yaw)) * (40.0f * t);
    c.yaw += 0.7f * std::sin(t * 2.0f * kPi);
    c.pitch = -0.1f * std::sin(t * 4.0f * kPi);
    return c;
}

// One round of `frames` frames along the whole path, appended to `m` (the variants take turns, round by
// round, so a change in the machine's load hits them all alike).
void measure(Measurement& m, shell::OffscreenContext& ctx, render::AssetLibrary& assets,
             render::LevelScene& scene, const level::Level& level, const Variant& v, int frames, bool& ok,
             const std::string& shot_path) {
    render::RendererSettings settings;
    settings.msaa_samples = v.msaa;
    settings.shadows = v.shadows;
    settings.surface_detail = v.surface_detail;
    settings.max_lights_per_draw = v.max_lights;
    settings.quality = v.quality;
    settings.fast_occluded_base = v.occluded_base;
    settings.render_scale = v.render_scale;
    settings.occlusion_culling = v.occlusion_culling;
    settings.depth_prepass = v.depth_prepass;
    settings.fast_level_shader = v.fast_level_shader;
    settings.fast_trilinear = v.fast_trilinear;
    settings.view_model_msaa = v.view_model_msaa;
    settings.contact_shadows = v.contact_shadows;
    settings.fast_model_shaders = v.model_shaders;
    // A scratch copy of the shaders, for trying a change without touching assets/shaders/.
    if (const char* dir = std::getenv("KS_SHADER_DIR"); dir && *dir) settings.shader_dir = dir;
    settings.prepass_skips_floors = !v.prepass_floors;
    settings.cull_single_sided = v.cull_single_sided;
    settings.view_model_depth_mask = v.view_model_mask;
    scene.set_doors_occlude(v.doors_occlude);
    scene.set_model_lods(v.model_lods);
    const float default_anisotropy = assets.textures().max_anisotropy();
    if (v.anisotropy > 0.0f) assets.textures().set_max_anisotropy(v.anisotropy);
    const int width = ctx.width() / v.resolution_divisor, height = ctx.height() / v.resolution_divisor;
    auto renderer = render::SceneRenderer::create(assets.textures(), settings);
    if (!renderer) {
        log::error(renderer.error().str());
        ok = false;
        return;
    }
    std::vector<render::MeshInstance> instances;
    std::vector<render::Light> lights;
    std::vector<render::ShadowCaster> casters;
    std::vector<Mat4> scratch;
    render::ViewModel view_model;
    assets.model("rifle").emit(render::rifle_view_transform(0.0f), scratch, view_model.instances);
    const geometry::Camera start = render::player_start_camera(level, static_cast<float>(width) / height);
    std::vector<double>& times = m.times;
    const int warmup = 5;
    double cpu_start = 0;
    GLuint query = 0;
    glGenQueries(1, &query);
    if (v.dynamic && !m.dynamic) m.dynamic.emplace(); // from 0.5 up, holding 60 fps
    for (int i = -warmup; i < frames; ++i) {
        if (m.dynamic) (*renderer)->set_render_scale(m.dynamic->scale());
        if (i == 0) {
            cpu_start = cpu_now_ms();
            // Under `valgrind --tool=callgrind --instr-atstart=no` only the timed frames are counted, one
            // dump per variant and round (instructions do not depend on the machine's load).
            CALLGRIND_START_INSTRUMENTATION;
        }
        auto t0 = std::chrono::steady_clock::now();
        render::SceneFrame frame;
        frame.camera = path_camera(start, std::max(i, 0), frames);
        scene.set_view(frame.camera, height);
        scene.emit(instances, lights, &casters);
        frame.shadow_casters = &casters;
        frame.environment = scene.environment();
        frame.instances = &instances;
        frame.lights = &lights;
        frame.view_model = v.rifle ? &view_model : nullptr;
        frame.width = width;
        frame.height = height;
        if (v.shadow_every_frame) (*renderer)->invalidate_shadows();
        ctx.bind();
        // Fragments that pass the depth test (scene and rifle; Mesa pauses queries during the upscale blit):
        // against the internal pixel count, the overdraw the shaders pay for.
        glBeginQuery(GL_SAMPLES_PASSED, query);
        auto stats = (*renderer)->render(frame);
        glEndQuery(GL_SAMPLES_PASSED);
        ctx.finish();
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (m.dynamic) {
            if (i >= 0) ++m.frames_at_scale[m.dynamic->scale()];
            m.dynamic->update(ms, ms / 1000.0);
        }
        if (i >= 0) {
            GLuint64 samples = 0;
            glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples); // after glFinish: no wait
            m.samples_passed += static_cast<double>(samples);
            m.occluded += stats.instances_occluded;
            times.push_back(ms);
            m.draw_calls = std::max(m.draw_calls, stats.draw_calls);
            m.triangles = std::max(m.triangles, stats.triangles);
            m.fast = stats.fast_path;
            m.internal_width = stats.internal_width;
            m.internal_height = stats.internal_height;
        }
    }
    m.cpu_total_ms += cpu_now_ms() - cpu_start;
    CALLGRIND_STOP_INSTRUMENTATION;
    CALLGRIND_DUMP_STATS_AT(v.name);
    glDeleteQueries(1, &query);
    if (!shot_path.empty()) { // the start view, for side-by-side comparisons of the variants
        render::SceneFrame frame;
        frame.camera = start;
        scene.set_view(start, height); // the props' levels of detail for this view
        scene.emit(instances, lights, &casters);
        frame.shadow_casters = &casters;
        frame.environment = scene.environment();
        frame.instances = &instances;
        frame.lights = &lights;
        frame.view_model = &view_model;
        frame.width = width;
        frame.height = height;
        ctx.bind();
        (*renderer)->render(frame);
        ctx.finish();
        if (auto saved = ctx.save_png(shot_path); !saved) log::error(saved.error().str());
    }
    assets.textures().set_max_anisotropy(default_anisotropy);
}

void finish(Measurement& m) {
    std::vector<double> times = m.times;
    std::sort(times.begin(), times.end());
    m.median_ms = times[times.size() / 2];
    m.p99_ms = times[std::min(times.size() - 1, static_cast<size_t>(times.size() * 0.99))];
    m.mean_ms = 0;
    for (double t : times) m.mean_ms += t / times.size();
    m.cpu_ms = m.cpu_total_ms / static_cast<double>(times.size());
    const double pixels = static_cast<double>(m.internal_width) * m.internal_height;
    m.overdraw = pixels > 0 ? m.samples_passed / static_cast<double>(times.size()) / pixels : 0.0;
}

int run(int argc, const char* const* argv) {
    auto cl = CommandLine::parse(argc, argv, {"json", "quick"});
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    if (auto unknown = cl->unknown(
            {"level", "json", "frames", "width", "height", "quick", "only", "shots", "rounds", "models"});
        !unknown.empty()) {
        log::error(
            "ks_bench render: unknown option --", unknown.front(),
            " (use --level FILE --frames N --width W --height H --json --quick --only TEXT[|TEXT...] (=NAME: "
            "exactly) --shots "
            "DIR --rounds R --models N)");
        return 2;
    }
    auto frames = cl->get_int("frames", 200, 10, 100000);
    auto width = cl->get_int("width", 1280, 64, 8192);
    auto height = cl->get_int("height", 720, 64, 8192);
    auto rounds_option = cl->get_int("rounds", 3, 1, 100);
    for (const auto* r : {&frames, &width, &height, &rounds_option})
        if (!*r) {
            log::error(r->error().str());
            return 2;
        }
    auto path = paths::resolve_user_path(cl->get_or("level", paths::level("main.json").string()));
    auto models = cl->get_int("models", 0, 0, 100000);
    if (!models) {
        log::error(models.error().str());
        return 2;
    }
    const std::filesystem::path scratch = std::filesystem::temp_directory_path() / "ks_bench_model_field";
    if (*models > 0) path = std::to_string(*models) + " models";
    auto level = *models > 0 ? Result<level::Level>(bench::model_field_level(*models, scratch))
                             : level::load_level_file(path);
    if (!level) {
        log::error(level.error().str());
        return 2;
    }
    auto ctx = shell::OffscreenContext::create(*width, *height);
    if (!ctx) {
        log::error(ctx.error().str(),
                   "\n  run it as: xvfb-run -a -s \"-screen 0 1280x720x24\" ks_bench render");
        return 3;
    }
    render::AssetLibrary assets(paths::asset(""));
    auto scene = render::LevelScene::build(*level, assets);
    const render::BakeStats& bake = scene->bake_stats();
    std::printf("light bake: %d faces, %d occluders, %lld texels (%.2f units each), %lld light texels, "
                "%.1f ms CPU\n",
                bake.faces, bake.occluders, bake.texels, bake.texel_size, bake.light_texels, bake.bake_ms);
    const std::string renderer = (*ctx)->renderer();
    const int default_msaa = render::default_msaa_for(renderer);
    using Q = render::RenderQuality;
    std::vector<Variant> variants = {{"default (auto)", default_msaa}};
    auto with = [&](const char* name, auto change) {
        Variant v{name, default_msaa};
        change(v);
        variants.push_back(v);
    };
    // The two paths and what each step of the fast one buys, always measured (ratios in one run).
    with("full, scale 1", [](Variant& v) { v.quality = Q::Full, v.render_scale = 1.0f; });
    with("fast, scale 1", [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f; });
    with("fast, scale 0.875", [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.875f; });
    with("fast, scale 0.75", [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.75f; });
    with("fast, scale 0.625", [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.625f; });
    // The game's Auto on a software rasteriser: render/dynamic_resolution.h fed with the measured frames.
    with("fast, dynamic", [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.dynamic = true; });
    with("fast, scale 0.5", [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f; });
    with("fast, scale 0.5, ORM lookup",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.occluded_base = false; });
    with("fast, scale 0.5, 4 lights",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.max_lights = 4; });
    with("fast, scale 0.5, no shadow",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.shadows = false; });
    with("fast, scale 0.5, no occlusion",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.occlusion_culling = false; });
    // The upscale's price: the same 640x360 scene drawn straight into a 640x360 target (not a usable
    // setting: the image is a quarter of the window).
    with("fast, 640x360, no upscale",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.resolution_divisor = 2; });
    with("fast, scale 0.5, no pre-pass",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.depth_prepass = false; });
    with("fast, scale 1, no pre-pass",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.depth_prepass = false; });
    with("fast, scale 0.5, no door occl.",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.doors_occlude = false; });
    with("fast, scale 0.5, one shader",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.fast_level_shader = false; });
    with("fast, scale 1, floors in pre-pass",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.prepass_floors = true; });
    with("fast, scale 1, no rifle",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.rifle = false; });
    with("fast, scale 1, ORM lookup",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.occluded_base = false; });
    with("fast, scale 1, no back-face culling",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.cull_single_sided = false; });
    with("fast, scale 1, one model shader",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.model_shaders = false; });
    with("fast, scale 0.5, trilinear",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.fast_trilinear = true; });
    // The rifle's own antialiased layer (render/view_model_layer.h) against drawing it into the scene.
    with("fast, scale 0.5, aliased rifle",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.view_model_msaa = 0; });
    with("fast, scale 1, aliased rifle",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.view_model_msaa = 0; });
    with("fast, scale 1, scene under the rifle",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.view_model_mask = false; });
    with("fast, scale 0.5, rifle msaa 4x",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.view_model_msaa = 4; });
    with("fast, scale 0.5, no contact shadows",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.contact_shadows = false; });
    with("fast, scale 1, no contact shadows",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.contact_shadows = false; });
    with("fast, 0.5, session 2", [](Variant& v) {
        v.quality = Q::Fast, v.render_scale = 0.5f, v.occlusion_culling = false, v.depth_prepass = false,
        v.fast_level_shader = false, v.doors_occlude = false;
    });
    with("full, scale 0.5", [](Variant& v) { v.quality = Q::Full, v.render_scale = 0.5f; });
    // Every prop at its levels of detail (the shipped models' from the asset generator, designers' models'
    // from meshoptimizer) against every prop in full at every distance.
    with("fast, scale 0.5, no model LODs",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.model_lods = false; });
    with("fast, scale 1, no model LODs",
         [](Variant& v) { v.quality = Q::Fast, v.render_scale = 1.0f, v.model_lods = false; });
    with("full, scale 1, no model LODs",
         [](Variant& v) { v.quality = Q::Full, v.render_scale = 1.0f, v.model_lods = false; });
    if (!cl->has("quick")) {
        // The full path's features, one at a time (session 1's table).
        auto full = [&](const char* name, auto change) {
            with(name, [&](Variant& v) {
                v.quality = Q::Full;
                v.render_scale = 1.0f;
                change(v);
            });
        };
        full("full: anisotropic 8x", [](Variant& v) { v.anisotropy = 8.0f; });
        full("full: no sun shadows", [](Variant& v) { v.shadows = false; });
        full("full: no normal/bump", [](Variant& v) { v.surface_detail = false; });
        full("full: 1 light/object", [](Variant& v) { v.max_lights = 1; });
        full("full: 4 lights/object", [](Variant& v) { v.max_lights = 4; });
        full("full: msaa 4x", [](Variant& v) { v.msaa = 4; });
        full("full: shadow each frame", [](Variant& v) { v.shadow_every_frame = true; });
        with("fast: shadow each frame",
             [](Variant& v) { v.quality = Q::Fast, v.render_scale = 0.5f, v.shadow_every_frame = true; });
    }
    if (auto only = cl->get("only")) {
        // Alternatives split at '|'; each a part of the row's name, or with a leading '=' the whole name.
        std::vector<std::string> wanted;
        for (std::size_t at = 0; at <= only->size();) {
            const std::size_t bar = std::min(only->find('|', at), only->size());
            wanted.push_back(only->substr(at, bar - at));
            at = bar + 1;
        }
        auto matches = [&](const std::string& name) {
            return std::ranges::any_of(wanted, [&](const std::string& w) {
                return w.starts_with('=') ? name == w.substr(1) : name.find(w) != std::string::npos;
            });
        };
        const std::string first = variants[0].name;
        std::erase_if(variants, [&](const Variant& v) { return !matches(v.name) && v.name != first; });
    }
    std::printf("render benchmark: %s, %dx%d, %d frames on a fixed path, GL renderer: %s (%s), default "
                "anisotropy %.0fx, msaa %dx\n",
                path.string().c_str(), *width, *height, *frames, renderer.c_str(), (*ctx)->platform().c_str(),
                assets.textures().max_anisotropy(), default_msaa);
    std::printf("%-28s %5s %9s %10s %10s %8s %10s %6s %9s %9s %6s %11s\n", "variant", "path", "internal",
                "median ms", "p99 ms", "fps", "cpu ms", "draws", "triangles", "shaded/px", "hidden",
                "vs default");
    std::vector<Measurement> results(variants.size());
    bool ok = true;
    const int rounds = *rounds_option;
    for (int round = 0; round < rounds; ++round)
        for (size_t i = 0; i < variants.size(); ++i) {
            std::string shot;
            if (auto dir = cl->get("shots"); dir && round == 0) {
                shot = variants[i].name;
                for (char& c : shot)
                    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                shot = (std::filesystem::path(*dir) / (shot + ".png")).string();
            }
            measure(results[i], **ctx, assets, *scene, *level, variants[i], std::max(*frames / rounds, 2), ok,
                    shot);
            if (!ok) return 1;
        }
    Measurement base, full;
    for (size_t i = 0; i < variants.size(); ++i) {
        Measurement& m = results[i];
        finish(m);
        if (i == 0) base = m;
        if (std::string(variants[i].name) == "full, scale 1") full = m;
        char internal[32];
        std::snprintf(internal, sizeof(internal), "%dx%d", m.internal_width, m.internal_height);
        std::printf("%-28s %5s %9s %10.2f %10.2f %8.1f %10.2f %6d %9lld %9.2f %6.1f %10.2fx\n",
                    variants[i].name, m.fast ? "fast" : "full", internal, m.median_ms, m.p99_ms,
                    1000.0 / m.median_ms, m.cpu_ms, m.draw_calls, m.triangles, m.overdraw,
                    static_cast<double>(m.occluded) / static_cast<double>(m.times.size()),
                    m.median_ms / base.median_ms);
        std::fflush(stdout);
    }
    for (size_t i = 0; i < variants.size(); ++i)
        if (!results[i].frames_at_scale.empty()) {
            std::printf("%s: frames per render scale:", variants[i].name);
            for (const auto& [scale, count] : results[i].frames_at_scale)
                std::printf(" %.3f %d", scale, count);
            std::printf("\n");
        }
    if (cl->has("json"))
        std::printf("{\"level\":\"%s\",\"width\":%d,\"height\":%d,\"msaa\":%d,\"quality\":\"%s\","
                    "\"internal_width\":%d,\"internal_height\":%d,\"frame_ms_median\":%.3f,"
                    "\"frame_ms_p99\":%.3f,\"fps_median\":%.1f,\"cpu_ms_per_frame\":%.3f,\"draw_calls\":%d,"
                    "\"triangles\":%lld,\"full_frame_ms_median\":%.3f,\"renderer\":\"%s\"}\n",
                    path.filename().string().c_str(), *width, *height, default_msaa,
                    base.fast ? "fast" : "full", base.internal_width, base.internal_height, base.median_ms,
                    base.p99_ms, 1000.0 / base.median_ms, base.cpu_ms, base.draw_calls, base.triangles,
                    full.median_ms, renderer.c_str());
    return 0;
}

const bench::Registrar kRegistrar({"render",
                                   "level frame time at 1280x720 over a fixed camera path (needs a display)",
                                   run, false});
} // namespace
