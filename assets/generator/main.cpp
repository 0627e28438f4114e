// ks_assetgen: writes every asset we make ourselves (textures, glTF models, particle sprites, sound
// effects, application icons) into DIR/textures, DIR/models, DIR/sounds and DIR/icons. Deterministic: the
// same binary always writes the same bytes, so the committed assets/ can be checked against a fresh run.
//
//   ks_assetgen --out DIR [--only NAME] [--contact-sheet FILE.png] [--preview FOLDER [--preview-size N]]
//   [--sound-report] [--sound-views FOLDER] [--list]
#include "catalog.h"
#include "contact_sheet.h"
#include "designer_sounds.h"
#include "preview.h"
#include "sound_analysis.h"
#include "sounds.h"

#include "core/cli.h"
#include "core/paths.h"

#include <chrono>
#include <cstdio>

namespace {
using namespace ks;
using namespace ks::assetgen;

int fail(const Error& e) {
    std::fprintf(stderr, "ks_assetgen: %s\n", e.str().c_str());
    return 1;
}

void usage() {
    std::printf("usage: ks_assetgen --out DIR [--only NAME] [--contact-sheet FILE.png] [--preview FOLDER "
                "[--preview-size N]] [--sound-report] [--sound-views FOLDER] [--list]\n"
                "  writes DIR/textures/*.png, DIR/models/*.gltf|.bin, DIR/sounds/*.wav and "
                "DIR/icons/hicolor/*/apps/*.png; "
                "`--out assets` regenerates the committed files\n");
}
} // namespace

int main(int argc, char** argv) {
    auto cl = CommandLine::parse(argc, argv, {"list", "help", "sound-report"});
    if (!cl) return fail(cl.error());
    const std::vector<std::string> known = {"out",  "only", "contact-sheet", "preview",    "preview-size",
                                            "list", "help", "sound-report",  "sound-views"};
    if (auto unknown = cl->unknown(known); !unknown.empty())
        return fail(Error("unknown option " + unknown.front(), Location{"command line"},
                          "known: --out, --only, --contact-sheet, --preview, --preview-size, --sound-report, "
                          "--sound-views, --list"));
    if (cl->has("help")) {
        usage();
        return 0;
    }
    if (cl->has("list")) {
        for (const Recipe& r : catalog()) std::printf("%-18s %s\n", r.name.c_str(), r.what.c_str());
        return 0;
    }
    const auto out_dir = cl->get("out");
    if (!out_dir || out_dir->empty()) {
        usage();
        return fail(Error("--out is required", Location{"command line"}, "e.g. --out assets"));
    }
    const std::string only = cl->get_or("only", "");
    if (!only.empty()) {
        bool found = false;
        for (const Recipe& r : catalog()) found = found || r.name == only;
        if (!found)
            return fail(Error("no asset named '" + only + "'", Location{"command line", 0, 0, "--only"},
                              "run ks_assetgen --list for the names"));
    }

    const auto preview_size = cl->get_int("preview-size", 360, 64, 2048);
    if (!preview_size) return fail(preview_size.error());

    auto font = Font::load(paths::asset("fonts/DejaVuSans-Bold.ttf"));
    if (!font) return fail(font.error());
    Output out(*out_dir, *font, cl->has("contact-sheet") || cl->has("preview"));
    std::vector<std::string> sound_names;
    for (const SoundRecipe& s : sound_recipes()) sound_names.emplace_back(s.name);
    auto designer_sounds =
        load_designer_sounds(std::filesystem::path(*out_dir) / "sounds" / kDesignerSoundsFile, sound_names);
    if (!designer_sounds) return fail(designer_sounds.error());
    out.keep_designer_sounds(std::move(*designer_sounds));
    const auto start = std::chrono::steady_clock::now();
    for (const Recipe& r : catalog()) {
        if (!only.empty() && r.name != only) continue;
        const auto t0 = std::chrono::steady_clock::now();
        if (auto made = r.make(out); !made) return fail(made.error());
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        std::printf("%-18s %7.0f ms\n", r.name.c_str(), ms);
    }
    for (const Model& m : out.models()) {
        const auto [lo, hi] = m.bounds();
        std::printf("model %-14s %6zu triangles, %2zu nodes, bounds x %.2f..%.2f y %.2f..%.2f z %.2f..%.2f\n",
                    m.name().c_str(), m.triangle_count(), m.nodes().size(), lo.x, hi.x, lo.y, hi.y, lo.z,
                    hi.z);
    }
    for (const std::string& name : out.kept_sounds())
        std::printf("kept the designer's sounds/%s.wav (listed in sounds/%s)\n", name.c_str(),
                    kDesignerSoundsFile);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %zu files to %s in %.1f s\n", out.written().size(), out_dir->c_str(), total);

    if (auto sheet = cl->get("contact-sheet"))
        if (auto r = write_contact_sheet(out, *sheet); !r) return fail(r.error());
    if (auto folder = cl->get("preview"))
        if (auto r = write_previews(out, *folder, *preview_size); !r) return fail(r.error());
    if (cl->has("sound-report")) std::printf("%s", sound_report(out).c_str());
    if (auto folder = cl->get("sound-views"))
        if (auto r = write_sound_views(out, *folder); !r) return fail(r.error());
    return 0;
}
