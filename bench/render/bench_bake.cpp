// ks_bench bake: the light bake's time against its quality. Each row bakes the level's light map with a
// texel size, a gathering stride and sample counts, and compares it with a reference bake of the same level
// (fine texels, every texel gathering, many samples): RMS and largest luminance difference over the
// reference's texels, all lights on. Wall time on the bake's threads (BakeSettings::threads).
#include "bench_registry.h"
#include "core/cli.h"
#include "core/log.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "render/level_scene.h"
#include "shell/offscreen_context.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ks::bench {
namespace {

struct Row {
    std::string name;
    render::BakeSettings settings;
};

render::BakeSettings quality(float texel, int stride, int bounce, int ao) {
    render::BakeSettings s;
    s.texel_size = texel;
    s.indirect_stride = stride;
    s.bounce_samples = bounce;
    s.ao_samples = ao;
    return s;
}

float luminance(const Vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

struct Baked {
    render::LightBake bake;
    render::BakeStats stats;
};

Baked bake_level(const level::Level& level, render::AssetLibrary& assets,
                 const render::BakeSettings& settings) {
    render::LevelSceneOptions options;
    options.bake = settings;
    options.defer_bake = true; // laid out here, computed below: the compute's time alone
    auto scene = render::LevelScene::build(level, assets, options);
    Baked out;
    out.bake = scene->light_bake();
    out.stats = out.bake.compute(scene->environment(), scene->bake_lights(), settings);
    return out;
}

// RMS and largest luminance difference of `bake` from `reference` over the reference's texels.
void difference(const render::LightBake& bake, const render::LightBake& reference, double& rms, double& max,
                double& mean) {
    double sum = 0.0, ref_sum = 0.0;
    long long n = 0;
    max = 0.0;
    for (int k = 0; k < reference.face_count(); ++k) {
        const glm::ivec2 size = reference.face_texels(k);
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const Vec2 st(static_cast<float>(i) / static_cast<float>(size.x - 1),
                              static_cast<float>(j) / static_cast<float>(size.y - 1));
                const float r = luminance(reference.face_irradiance(k, st));
                const double d = std::abs(static_cast<double>(luminance(bake.face_irradiance(k, st)) - r));
                sum += d * d;
                ref_sum += r;
                max = std::max(max, d);
                ++n;
            }
    }
    rms = n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
    mean = n > 0 ? ref_sum / static_cast<double>(n) : 0.0;
}

int run_bake(int argc, const char* const* argv) {
    auto cl = CommandLine::parse(argc, argv, {"quick"});
    if (!cl) {
        log::error(cl.error().str());
        return 2;
    }
    if (auto unknown = cl->unknown({"level", "quick"}); !unknown.empty()) {
        log::error("ks_bench bake: unknown option --", unknown.front(), " (use --level FILE --quick)");
        return 2;
    }
    auto path = paths::resolve_user_path(cl->get_or("level", paths::level("main.json").string()));
    auto level = level::load_level_file(path);
    if (!level) {
        log::error(level.error().str());
        return 2;
    }
    auto ctx = shell::OffscreenContext::create(64, 64); // the surfaces' textures (albedo) need GL
    if (!ctx) {
        log::error(ctx.error().str(), "\n  run it as: xvfb-run -a ks_bench bake");
        return 3;
    }
    render::AssetLibrary assets(paths::asset(""));
    const bool quick = cl->has("quick");
    std::vector<Row> rows = {
        {"direct only", render::BakeSettings::direct_only()},
        {"preview", render::BakeSettings::preview()},
        {"full", render::BakeSettings::full()},
    };
    if (!quick) {
        rows.push_back({"texel 1, stride 2, 16/8", quality(1.0f, 2, 16, 8)});
        rows.push_back({"texel 0.5, stride 8, 16/8", quality(0.5f, 8, 16, 8)});
        rows.push_back({"texel 0.5, stride 4, 8/4", quality(0.5f, 4, 8, 4)});
        rows.push_back({"texel 0.5, stride 4, 32/16", quality(0.5f, 4, 32, 16)});
        rows.push_back({"texel 0.5, stride 2, 32/16", quality(0.5f, 2, 32, 16)});
        rows.push_back({"texel 0.5, stride 1, 16/8", quality(0.5f, 1, 16, 8)});
        rows.push_back({"texel 0.25, stride 4, 16/8", quality(0.25f, 4, 16, 8)});
    }
    const render::BakeSettings reference_settings = quality(0.5f, 1, quick ? 64 : 256, quick ? 32 : 128);
    const Baked reference = bake_level(*level, assets, reference_settings);
    std::printf(
        "level %s: %d faces, %d solids, %lld atlas texels; reference: texel %.2f, stride 1, %d bounce / "
        "%d AO samples, %.0f ms wall\n\n",
        path.filename().string().c_str(), reference.stats.faces, reference.stats.occluders,
        reference.stats.texels, reference_settings.texel_size, reference_settings.bounce_samples,
        reference_settings.ao_samples, reference.stats.wall_ms);
    std::printf(
        "| quality | texel | stride | bounce | AO | wall ms | CPU ms | rays (M) | RMS lum. | max lum. |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row& row : rows) {
        const Baked b = bake_level(*level, assets, row.settings);
        double rms = 0.0, max = 0.0, mean = 0.0;
        difference(b.bake, reference.bake, rms, max, mean);
        std::printf("| %s | %.2f | %d | %d | %d | %.0f | %.0f | %.1f | %.4f (%.1f %%) | %.3f |\n",
                    row.name.c_str(), b.stats.texel_size, row.settings.indirect_stride,
                    row.settings.bounce_samples, row.settings.ao_samples, b.stats.wall_ms, b.stats.bake_ms,
                    static_cast<double>(b.stats.rays) * 1e-6, rms, mean > 0.0 ? 100.0 * rms / mean : 0.0,
                    max);
        std::fflush(stdout);
    }
    return 0;
}

const Registrar kBake({"bake", "light bake time against quality (texel size, samples) vs a reference bake",
                       run_bake, false});

} // namespace
} // namespace ks::bench
