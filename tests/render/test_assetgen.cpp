// The asset generator (assets/generator, ks_assetgen) as a program: it must reproduce the committed assets
// (textures, models and sounds) byte for byte, write every asset the conventions and the audio plan name,
// refuse bad command lines with a clear message, and write its debug views. The committed models' glTF
// structure is checked in test_assetgen_gltf.cpp, their nodes and dimensions in test_assetgen_models.cpp.
// Needs no GL context.
#include "assetgen_test_support.h"
#include "planned_sounds.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ks::test::assetgen {
namespace {

fs::path generator() {
    return ks::test::bin_dir() / "ks_assetgen";
}

// The generated folders: models/*.gltf|*.bin|*.lods.json, textures/**.png, sounds/*.wav and icons/**.png.
std::set<std::string> generated_files(const fs::path& root) {
    std::set<std::string> out;
    for (const char* folder : {"models", "textures", "sounds", "icons"}) {
        if (!fs::exists(root / folder)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
            if (!entry.is_regular_file()) continue;
            const std::string ext = entry.path().extension().string();
            if (ext == ".gltf" || ext == ".bin" || ext == ".png" || ext == ".wav" || ext == ".json")
                out.insert(fs::relative(entry.path(), root).generic_string());
        }
    }
    return out;
}

// Every file the shared asset conventions promise.
std::vector<std::string> expected_files() {
    std::vector<std::string> files;
    for (const std::string& m : model_names()) {
        files.push_back("models/" + m + ".gltf");
        files.push_back("models/" + m + ".bin");
    }
    for (const char* s : {"concrete", "wood", "tiles", "ceiling", "metal", "dojo_floor"})
        for (const char* map : {"basecolor", "normal", "orm", "height"})
            files.push_back(std::string("textures/") + s + "_" + map + ".png");
    for (const char* p : {"fire", "smoke", "spark"})
        files.push_back(std::string("textures/particles/") + p + ".png");
    for (const auto* names : {&ks::test::planned_one_shots(), &ks::test::planned_loops()})
        for (const std::string& s : *names) files.push_back("sounds/" + s + ".wav");
    // The application icons at the icon theme's sizes (cmake/KsInstall.cmake installs them).
    for (int size : {16, 24, 32, 48, 64, 128, 256})
        for (const char* icon : {"killswitch", "killswitch-editor"})
            files.push_back("icons/hicolor/" + std::to_string(size) + "x" + std::to_string(size) + "/apps/" +
                            icon + ".png");
    return files;
}

std::string shell_quote(const fs::path& p) {
    return "'" + p.string() + "'";
}

} // namespace

TEST_CASE("ks_assetgen regenerates every committed asset byte for byte") {
    REQUIRE_MESSAGE(fs::exists(generator()), "build the ks_assetgen target first: " << generator());
    ks::test::ScratchDir scratch;
    const auto result =
        ks::test::run_command(shell_quote(generator()) + " --out " + shell_quote(scratch.path()));
    INFO(result.output);
    REQUIRE(result.exit_code == 0);

    const std::set<std::string> fresh = generated_files(scratch.path());
    const std::set<std::string> repo = generated_files(committed());
    std::set<std::string> designer_files;
    for (const std::string& name : ks::test::designer_sounds())
        designer_files.insert("sounds/" + name + ".wav");
    for (const std::string& file : expected_files()) {
        CHECK_MESSAGE(fresh.count(file) == 1, "the generator no longer writes " << file);
        CHECK_MESSAGE(repo.count(file) == 1,
                      "assets/" << file << " is not committed; run ks_assetgen --out assets");
    }
    for (const std::string& file : fresh) {
        CAPTURE(file);
        REQUIRE_MESSAGE(repo.count(file) == 1, "generated but not committed; run ks_assetgen --out assets");
        if (designer_files.count(file) > 0) continue; // a designer's replacement, not ours to compare
        // Compared as bytes: the generator must be deterministic, and the committed files current.
        const bool same =
            ks::test::read_file(scratch.path() / file) == ks::test::read_file(committed() / file);
        CHECK_MESSAGE(
            same, "assets/" << file << " differs from a fresh run; run ks_assetgen --out assets and commit");
    }
    for (const std::string& file : repo)
        CHECK_MESSAGE(fresh.count(file) == 1,
                      "assets/" << file << " is committed but no longer generated (stale)");
}

TEST_CASE("ks_assetgen rejects bad command lines with a clear message") {
    REQUIRE_MESSAGE(fs::exists(generator()), "build the ks_assetgen target first: " << generator());
    ks::test::ScratchDir scratch;
    const std::string exe = shell_quote(generator());

    const auto no_out = ks::test::run_command(exe);
    CHECK(no_out.exit_code != 0);
    CHECK(no_out.output.find("--out is required") != std::string::npos);

    const auto unknown =
        ks::test::run_command(exe + " --out " + shell_quote(scratch.path()) + " --only unicorn");
    CHECK(unknown.exit_code != 0);
    CHECK(unknown.output.find("no asset named 'unicorn'") != std::string::npos);
    CHECK(unknown.output.find("--list") != std::string::npos);

    const auto typo = ks::test::run_command(exe + " --out " + shell_quote(scratch.path()) + " --onyl robot");
    CHECK(typo.exit_code != 0);
    CHECK(typo.output.find("unknown option --onyl") != std::string::npos);

    // An output path that is a file, not a folder: a clear error naming it, not a crash.
    ks::test::run_command("touch " + shell_quote(scratch / "blocker"));
    const auto blocked =
        ks::test::run_command(exe + " --out " + shell_quote(scratch / "blocker") + " --only particles");
    CHECK(blocked.exit_code == 1);
    CHECK(blocked.output.find("blocker") != std::string::npos);

    // The label font missing or corrupt: a clear error naming the file and the fix.
    const fs::path data = scratch / "data";
    fs::create_directories(data / "assets" / "fonts");
    fs::create_directories(data / "levels");
    const std::string with_data =
        "KS_DATA_DIR=" + shell_quote(data) + " " + exe + " --out " + shell_quote(scratch / "x");
    const auto no_font = ks::test::run_command(with_data + " --only pickups");
    CHECK(no_font.exit_code == 1);
    CHECK(no_font.output.find("DejaVuSans-Bold.ttf") != std::string::npos);
    CHECK(no_font.output.find("restore it from git") != std::string::npos);
    ks::test::run_command("printf 'not a font' > " +
                          shell_quote(data / "assets" / "fonts" / "DejaVuSans-Bold.ttf"));
    const auto bad_font = ks::test::run_command(with_data + " --only pickups");
    CHECK(bad_font.exit_code == 1);
    CHECK(bad_font.output.find("not a TrueType font") != std::string::npos);

    // --only writes just that asset.
    const auto one =
        ks::test::run_command(exe + " --out " + shell_quote(scratch / "one") + " --only gas_cylinder");
    CHECK(one.exit_code == 0);
    CHECK(fs::exists(scratch / "one" / "models" / "gas_cylinder.gltf"));
    CHECK_FALSE(fs::exists(scratch / "one" / "models" / "robot.gltf"));
}

TEST_CASE("ks_assetgen debug views: contact sheet and model previews") {
    REQUIRE_MESSAGE(fs::exists(generator()), "build the ks_assetgen target first: " << generator());
    ks::test::ScratchDir scratch;
    const auto run =
        ks::test::run_command(shell_quote(generator()) + " --out " + shell_quote(scratch / "out") +
                              " --only pickups --contact-sheet " + shell_quote(scratch / "sheet.png") +
                              " --preview " + shell_quote(scratch / "previews") + " --preview-size 100");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    // PNG width and height from the IHDR chunk (big-endian at bytes 16..23).
    auto png_size = [](const fs::path& file) {
        const std::string bytes = ks::test::read_file(file);
        REQUIRE(bytes.size() > 24);
        CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
        auto be32 = [&](size_t at) {
            return (static_cast<unsigned>(static_cast<unsigned char>(bytes[at])) << 24) |
                   (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 1])) << 16) |
                   (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 2])) << 8) |
                   static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 3]));
        };
        return std::pair<unsigned, unsigned>(be32(16), be32(20));
    };
    // 12 pickup textures: 8 columns of 160 px, 2 rows of 178 px.
    CHECK(png_size(scratch / "sheet.png") == std::pair<unsigned, unsigned>(1280, 356));
    for (const char* model : {"pickup_health", "pickup_ammo", "pickup_shield"})
        CHECK(png_size(scratch / "previews" / (std::string(model) + ".png")) ==
              std::pair<unsigned, unsigned>(400, 100));

    const auto bad =
        ks::test::run_command(shell_quote(generator()) + " --out " + shell_quote(scratch / "out2") +
                              " --preview " + shell_quote(scratch / "p") + " --preview-size 9");
    CHECK(bad.exit_code == 1);
    CHECK(bad.output.find("--preview-size must be a whole number from 64 to 2048") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch / "out2")); // refused before generating anything
}

} // namespace ks::test::assetgen
