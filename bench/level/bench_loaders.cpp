// `ks_bench loaders`: what a load costs against parsing its JSON (issue 30 item 3: "a level load should cost
// little more than parsing its JSON"). For each shipped level: nlohmann's plain parse, the project's
// Document parse (positions, duplicate keys, depth), the whole load, the save, and what one execution of
// the level fuzz target costs (load, save, reload, save). Campaign and clip loaders the same way.
#include "anim/clip_io.h"
#include "bench_registry.h"
#include "core/files.h"
#include "editor/median_time.h"
#include "jsonio/document.h"
#include "level/campaign.h"
#include "level/level_io.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::level::bench {
namespace {

namespace fs = std::filesystem;

fs::path source_dir() {
#ifdef KS_SOURCE_DIR
    return fs::path(KS_SOURCE_DIR);
#else
    return fs::current_path();
#endif
}

// Medians in microseconds over enough repetitions to be steady on a shared machine.
double median_us(int reps, const std::function<void()>& fn) {
    return 1000.0 * ks::bench::median_ms(reps, fn);
}

void print_row(const std::string& file, size_t bytes, double json_us, double document_us, double load_us,
               double save_us, size_t saved_bytes, double reload_us, double fuzz_us) {
    std::printf("| %s | %zu | %.1f | %.1f | %.1f | %.2f× | %.1f | %zu | %.1f | %.1f |\n", file.c_str(), bytes,
                json_us, document_us, load_us, load_us / json_us, save_us, saved_bytes, reload_us, fuzz_us);
}

int bench_levels(int reps, const std::string& only) {
    std::printf(
        "| level | bytes | nlohmann parse µs | Document parse µs | load µs | load ÷ parse | save µs | "
        "fuzz execution µs |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const char* name : {"main.json", "lockdown.json", "archive.json", "dojo.json"}) {
        if (!only.empty() && only != name) continue;
        const fs::path path = source_dir() / "levels" / name;
        auto text = files::read_text(path);
        if (!text) {
            std::fprintf(stderr, "loaders: %s\n", text.error().str().c_str());
            return 1;
        }
        auto level = load_level_string(*text, name);
        if (!level) {
            std::fprintf(stderr, "loaders: %s\n", level.error().str().c_str());
            return 1;
        }
        const double json_us = median_us(reps, [&] {
            auto parsed = nlohmann::ordered_json::parse(*text);
            (void)parsed;
        });
        const double document_us = median_us(reps, [&] {
            (void)jsonio::Document::parse(*text, name, {"level", "{}"});
        });
        const double load_us = median_us(reps, [&] { (void)load_level_string(*text, name); });
        const double save_us = median_us(reps, [&] { (void)save_level_string(*level); });
        const std::string saved = save_level_string(*level);
        const double reload_us = median_us(reps, [&] { (void)load_level_string(saved, "again.json"); });
        const double fuzz_us = median_us(reps, [&] {
            auto first = load_level_string(*text, name);
            const std::string saved = save_level_string(*first);
            auto again = load_level_string(saved, "again.json");
            (void)save_level_string(*again);
        });
        print_row(name, text->size(), json_us, document_us, load_us, save_us, saved.size(), reload_us,
                  fuzz_us);
    }
    return 0;
}

int bench_campaign_and_clips(int reps) {
    const fs::path campaign = source_dir() / "levels" / "campaign.json";
    const fs::path clips = source_dir() / "assets" / "animations" / "robot.json";
    auto campaign_text = files::read_text(campaign);
    auto clip_text = files::read_text(clips);
    if (!campaign_text || !clip_text) {
        std::fprintf(stderr, "loaders: campaign.json or robot.json unreadable\n");
        return 1;
    }
    std::printf(
        "\n| file | bytes | nlohmann parse µs | load µs | load ÷ parse |\n|---|---:|---:|---:|---:|\n");
    const double campaign_json = median_us(reps, [&] {
        auto parsed = nlohmann::ordered_json::parse(*campaign_text);
        (void)parsed;
    });
    const double campaign_load = median_us(
        reps, [&] { (void)load_campaign_string(*campaign_text, "campaign.json", campaign.parent_path()); });
    std::printf("| campaign.json | %zu | %.1f | %.1f | %.2f× |\n", campaign_text->size(), campaign_json,
                campaign_load, campaign_load / campaign_json);
    const double clip_json = median_us(reps, [&] {
        auto parsed = nlohmann::ordered_json::parse(*clip_text);
        (void)parsed;
    });
    const double clip_load =
        median_us(reps, [&] { (void)anim::load_animation_string(*clip_text, "robot.json"); });
    std::printf("| robot.json (clips) | %zu | %.1f | %.1f | %.2f× |\n", clip_text->size(), clip_json,
                clip_load, clip_load / clip_json);
    return 0;
}

int run(int argc, const char* const* argv) {
    int reps = 200;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) {
            reps = 20;
        } else if (std::strcmp(argv[i], "--level") == 0 && i + 1 < argc) {
            only = argv[++i];
        } else {
            std::fprintf(stderr, "loaders: unknown option '%s' (options: --quick, --level NAME.json)\n",
                         argv[i]);
            return 2;
        }
    }
    if (int status = bench_levels(reps, only)) return status;
    if (!only.empty()) return 0;
    return bench_campaign_and_clips(reps);
}

const ks::bench::Registrar registrar({"loaders", "level, campaign and clip loads against parsing their JSON",
                                      run});

} // namespace
} // namespace ks::level::bench
