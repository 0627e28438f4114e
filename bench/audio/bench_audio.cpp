// ks_bench audio: the sound engine's CPU per 60 Hz frame (update + loopback mix of one frame, 800 samples at
// 48 kHz) with 8, 32 and 128 playing 3D sources, and the occlusion ray budget against its error on
// levels/main.json (occlusion_budget.h). Writes docs/bench/audio_cpu.csv and audio_occlusion.csv; --quick
// runs a short version and leaves docs/bench/ as it is.
#include "audio/occlusion_budget.h"
#include "bench_registry.h"
#include "physics/bench_util.h"

#include "audio/audio_engine.h"
#include "core/random.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace ks::bench {
namespace {

using physics::bench::fmt;

constexpr int kRate = 48000;
constexpr int kFrameSamples = kRate / 60;

struct CpuRow {
    int sources = 0;
    double cpu_us = 0.0;    // thread CPU per frame (the loopback mix runs on this thread)
    double median_us = 0.0; // wall time per frame (includes time other processes took from this one)
    double p99_us = 0.0;
    int active = 0;
};

audio::SoundBank bench_sounds() {
    audio::SoundBank bank;
    Rng rng(3);
    for (const char* name : {"motor", "hum", "vent"}) {
        audio::SoundData sound; // two seconds of filtered noise, different for each name
        float low = 0.0f;
        for (int i = 0; i < 2 * kRate; ++i) {
            low += 0.1f * (rng.uniform(-1.0f, 1.0f) - low);
            sound.samples.push_back(static_cast<std::int16_t>(low * 60000.0f));
        }
        bank.add(name, std::move(sound));
    }
    return bank;
}

CpuRow measure_cpu(int sources, int frames) {
    audio::EngineSettings settings;
    settings.voices = std::max(sources, audio::VoicePool::kDefaultVoices);
    auto opened = audio::AudioEngine::open_loopback(bench_sounds(), kRate, settings);
    if (!opened) {
        std::printf("%s\n", opened.error().str().c_str());
        return {};
    }
    audio::AudioEngine engine = std::move(*opened);
    Rng rng(11);
    std::vector<audio::VoiceHandle> voices;
    std::vector<Vec3> home;
    for (int i = 0; i < sources; ++i) {
        const float angle = rng.uniform(0.0f, 2.0f * kPi), distance = rng.uniform(2.0f, 60.0f);
        home.emplace_back(std::cos(angle) * distance, rng.uniform(0.0f, 6.0f), std::sin(angle) * distance);
        audio::PlayParams p;
        p.sound = i % 3 == 0 ? "motor" : i % 3 == 1 ? "hum" : "vent";
        p.position = home.back();
        p.loop = true;
        p.max_distance = 100.0f;
        p.pitch = rng.uniform(0.8f, 1.25f); // resampling, as robots' motors at different speeds
        voices.push_back(engine.play(p));
    }
    std::vector<std::int16_t> mix(2 * kFrameSamples);
    std::vector<double> wall;
    double cpu = 0.0;
    const int warmup = 30;
    for (int f = 0; f < warmup + frames; ++f) {
        const float t = static_cast<float>(f) / 60.0f;
        const double w0 = physics::bench::now_seconds(), c0 = physics::bench::cpu_seconds();
        engine.set_listener(Vec3(0.0f, 3.0f, 0.0f), Vec3(std::sin(t), 0.0f, -std::cos(t)),
                            Vec3(0.0f, 1.0f, 0.0f));
        for (std::size_t i = 0; i < voices.size(); i += 2) // half the sources move, as robots do
            engine.set_position(voices[i],
                                home[i] + Vec3(std::sin(t + static_cast<float>(i)) * 4.0f, 0.0f, 0.0f));
        // A wall between the listener and every source on its left: half the voices filtered.
        engine.update(1.0f / 60.0f, [](Vec3, Vec3 source) { return source.x < 0.0f; });
        engine.render(mix.data(), kFrameSamples);
        if (f >= warmup) {
            cpu += physics::bench::cpu_seconds() - c0;
            wall.push_back(physics::bench::now_seconds() - w0);
        }
    }
    std::sort(wall.begin(), wall.end());
    CpuRow row;
    row.sources = sources;
    row.cpu_us = cpu * 1e6 / frames;
    row.median_us = wall[wall.size() / 2] * 1e6;
    row.p99_us = wall[std::min(wall.size() - 1, wall.size() * 99 / 100)] * 1e6;
    row.active = engine.stats().active_voices;
    return row;
}

int run(int argc, const char* const* argv) {
    const std::optional<bool> quick_given = ks::bench::quick_option(argc, argv);
    if (!quick_given) return 2;
    const bool quick = *quick_given;
    std::printf("load average %s\n\naudio CPU per 60 Hz frame (update + loopback mix of %d stereo samples)\n",
                physics::bench::load_average().c_str(), kFrameSamples);
    std::printf("%8s %8s %10s %10s %10s %8s\n", "sources", "active", "cpu µs", "wall µs", "p99 µs", "vs 8");
    std::vector<std::string> cpu_lines;
    double base = 0.0;
    for (int sources : {8, 32, 128}) {
        const CpuRow r = measure_cpu(sources, quick ? 120 : 1200);
        if (r.sources == 0) return 1;
        if (sources == 8) base = r.cpu_us;
        const double ratio = base > 0.0 ? r.cpu_us / base : 0.0;
        std::printf("%8d %8d %10.1f %10.1f %10.1f %7.2fx\n", r.sources, r.active, r.cpu_us, r.median_us,
                    r.p99_us, ratio);
        cpu_lines.push_back(std::to_string(r.sources) + "," + std::to_string(r.active) + "," +
                            fmt("%.1f", r.cpu_us) + "," + fmt("%.1f", r.median_us) + "," +
                            fmt("%.1f", r.p99_us) + "," + fmt("%.2f", ratio));
    }

    const int sources = 32, frames = quick ? 600 : 3600;
    std::printf(
        "\nocclusion rays on levels/main.json: %d sources at random walkable points (half walking), a "
        "listener walking random paths, %d frames at 60 Hz\n",
        sources, frames);
    const auto rows = audio_bench::measure_budgets(sources, {1, 2, 4, 8, 16}, frames);
    if (rows.empty()) return 1;
    std::printf("%8s %10s %10s %14s %16s %10s\n", "budget", "rays/frame", "ray µs", "stale answer %",
                "muffled differs %", "blocked %");
    std::vector<std::string> occlusion_lines;
    for (const auto& r : rows) {
        const std::string budget = r.budget >= r.sources ? "all" : std::to_string(r.budget);
        std::printf("%8s %10.2f %10.1f %14.2f %16.2f %10.1f\n", budget.c_str(), r.rays_per_frame,
                    r.ray_us_per_frame, r.stale_pct, r.decision_pct, r.blocked_pct);
        occlusion_lines.push_back(std::to_string(r.sources) + "," + budget + "," +
                                  fmt("%.2f", r.rays_per_frame) + "," + fmt("%.1f", r.ray_us_per_frame) +
                                  "," + fmt("%.2f", r.stale_pct) + "," + fmt("%.2f", r.decision_pct) + "," +
                                  fmt("%.1f", r.blocked_pct));
    }
    if (quick) {
        std::printf("\n--quick: docs/bench/audio_* left as they are\n");
        return 0;
    }
    physics::bench::write_csv(
        "audio_cpu", "sources,active,cpu_us_per_frame,median_wall_us,p99_wall_us,cpu_ratio_to_8", cpu_lines);
    physics::bench::write_csv("audio_occlusion",
                              "sources,budget,rays_per_frame,ray_us_per_frame,stale_pct,muffled_differs_pct,"
                              "blocked_pct",
                              occlusion_lines);
    std::printf("\nwritten: docs/bench/audio_cpu.csv, docs/bench/audio_occlusion.csv\n");
    return 0;
}

const Registrar registrar({"audio", "sound engine CPU per frame vs sources; occlusion ray budget vs error",
                           run});

} // namespace
} // namespace ks::bench
