// The runtime's options file (runtime/model/options.h, tested without a window):
// round trip, atomic write into a new folder, and every kind of bad file giving defaults plus a warning.
#include "core/files.h"
#include "core/log.h"
#include "jsonio/bad_documents.h"
#include "runtime/model/options.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>

using namespace ks;
using runtime::Options;

TEST_CASE("options: save then load gives the same options, in a folder that did not exist") {
    test::ScratchDir dir;
    const auto path = dir / "deep" / "killswitch" / "options.json";
    Options o;
    o.mouse_sensitivity = 2.5f;
    o.invert_y = true;
    o.fov_degrees = 90.0f;
    o.render_scale = 0.5f;
    o.quality = runtime::QualityOption::Fast;
    o.master_volume = 0.35f;
    o.effects_volume = 0.5f;
    o.ambience_volume = 0.0f;
    o.muted = true;
    o.logic_debugger = true;
    REQUIRE(runtime::save_options(path, o).ok());
    CHECK(runtime::load_options(path) == o);
    // Saving again replaces the file whole (no temporary left beside it).
    o.fov_degrees = 60.0f;
    REQUIRE(runtime::save_options(path, o).ok());
    CHECK(runtime::load_options(path).fov_degrees == doctest::Approx(60.0f));
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(path.parent_path())) {
        (void)entry;
        ++files;
    }
    CHECK(files == 1);
}

TEST_CASE("options: a missing file gives the defaults without a warning") {
    test::ScratchDir dir;
    log::Capture capture;
    CHECK(runtime::load_options(dir / "none.json") == Options{});
    CHECK(capture.text().find("WARN") == std::string::npos);
    CHECK(capture.text().empty());
}

TEST_CASE("options: bad files give defaults (per field) and a warning naming the file and field") {
    test::ScratchDir dir;
    const auto path = dir / "options.json";
    struct Case {
        const char* text;
        const char* expect_in_warning;
    };
    const Case cases[] = {
        {"{ this is not json", "JSON syntax error"},
        {"[1, 2, 3]", "expected the options as a JSON object"},
        {"", "file is empty"},
        {R"({"mouse_sensitivity": "fast"})", "mouse_sensitivity"},
        {R"({"mouse_sensitivity": 1e30})", "mouse_sensitivity"},
        {R"({"mouse_sensitivity": -2})", "mouse_sensitivity"},
        {R"({"fov_degrees": 1000})", "fov_degrees"},
        {R"({"fov_degrees": null})", "fov_degrees"},
        {R"({"invert_y": "yes"})", "invert_y"},
        {R"({"render_scale": 0.1})", "render_scale"},
        {R"({"render_scale": 2})", "render_scale"},
        {R"({"render_scale": "half"})", "render_scale"},
        {R"({"quality": "ultra"})", "quality"},
        {R"({"quality": 1})", "quality"},
        {R"({"master_volume": 1.5})", "master_volume"},
        {R"({"effects_volume": -0.1})", "effects_volume"},
        {R"({"ambience_volume": "loud"})", "ambience_volume"},
        {R"({"muted": 1})", "muted"},
        {R"({"logic_debugger": "on"})", "logic_debugger"},
    };
    for (const auto& c : cases) {
        CAPTURE(c.text);
        REQUIRE(files::write_atomic(path, c.text).ok());
        log::Capture capture;
        const Options o = runtime::load_options(path);
        CHECK(o == Options{});
        CHECK(capture.text().find(c.expect_in_warning) != std::string::npos);
        CHECK(capture.text().find(path.string()) != std::string::npos);
    }
}

TEST_CASE("options: every bad document is reported at its line:column, as in every file kind") {
    for (const test::BadDocument& bad : test::bad_documents()) {
        CAPTURE(bad.name);
        std::vector<std::string> problems;
        const Options o = runtime::options_from_json(bad.text, problems, "options.json");
        CHECK(o == Options{});
        std::string all;
        for (const std::string& problem : problems) all += problem + "\n";
        CAPTURE(all);
        CHECK(all.find("options.json" + bad.place + bad.message) != std::string::npos);
    }
    // An unknown field is a warning with a did-you-mean, and the rest is read.
    std::vector<std::string> problems;
    const Options o = runtime::options_from_json("{\"fov_degres\": 90,\n \"muted\": true}", problems);
    CHECK(o.muted);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].find(
              "options.json:1:2: fov_degres: unknown field \"fov_degres\" is ignored (did you mean "
              "\"fov_degrees\"?") != std::string::npos);
}

TEST_CASE("options: a bad field does not throw away the good ones") {
    std::vector<std::string> problems;
    const Options o = runtime::options_from_json(
        R"({"mouse_sensitivity": 3, "fov_degrees": "wide", "invert_y": true})", problems);
    CHECK(o.mouse_sensitivity == doctest::Approx(3.0f));
    CHECK(o.invert_y);
    CHECK(o.fov_degrees == doctest::Approx(Options{}.fov_degrees));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].find("fov_degrees") != std::string::npos);
}

TEST_CASE("options: render scale 0 means automatic; 0.25..1 are kept; quality by name") {
    std::vector<std::string> problems;
    CHECK(runtime::options_from_json(R"({"render_scale": 0})", problems).render_scale == 0.0f);
    CHECK(runtime::options_from_json(R"({"render_scale": 0.25})", problems).render_scale == 0.25f);
    CHECK(runtime::options_from_json(R"({"render_scale": 1})", problems).render_scale == 1.0f);
    CHECK(runtime::options_from_json(R"({"quality": "full"})", problems).quality ==
          runtime::QualityOption::Full);
    CHECK(runtime::options_from_json(R"({"quality": "auto"})", problems).quality ==
          runtime::QualityOption::Auto);
    CHECK(problems.empty());
    // Files from before these fields existed still read (defaults: automatic).
    const Options old = runtime::options_from_json(R"({"format": "killswitch-options", "version": 1,
        "mouse_sensitivity": 2, "invert_y": false, "fov_degrees": 80})",
                                                   problems);
    CHECK(old.render_scale == 0.0f);
    CHECK(old.quality == runtime::QualityOption::Auto);
    CHECK(problems.empty());
}

TEST_CASE("options: the difficulty saves and loads by name; a bad one is reported and Normal kept") {
    test::ScratchDir dir;
    const auto path = dir / "options.json";
    for (game::Difficulty d : game::kDifficulties) {
        Options o;
        o.difficulty = d;
        REQUIRE(runtime::save_options(path, o).ok());
        CHECK(runtime::load_options(path).difficulty == d);
    }
    CHECK(runtime::options_to_json(Options{}).find("\"difficulty\": \"normal\"") != std::string::npos);
    std::vector<std::string> problems;
    const Options bad = runtime::options_from_json("{\n  \"difficulty\": \"insane\"\n}", problems);
    CHECK(bad.difficulty == game::Difficulty::Normal);
    REQUIRE(problems.size() == 1);
    MESSAGE(problems[0]);
    CHECK(problems[0].find("options.json:2:") != std::string::npos);
    CHECK(problems[0].find("difficulty") != std::string::npos);
    CHECK(problems[0].find("insane") != std::string::npos);
    CHECK(problems[0].find("hard") != std::string::npos); // the valid words
    // Files from before the difficulty existed read as Normal, with nothing to report.
    problems.clear();
    CHECK(runtime::options_from_json(R"({"fov_degrees": 80})", problems).difficulty ==
          game::Difficulty::Normal);
    CHECK(problems.empty());
}

TEST_CASE("options: the file lives under XDG_CONFIG_HOME, else ~/.config") {
    const char* old_xdg = std::getenv("XDG_CONFIG_HOME");
    const std::string saved = old_xdg ? old_xdg : "";
    setenv("XDG_CONFIG_HOME", "/tmp/xdg-test", 1);
    CHECK(runtime::options_path() == std::filesystem::path("/tmp/xdg-test/killswitch/options.json"));
    unsetenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (home && *home)
        CHECK(runtime::options_path() ==
              std::filesystem::path(home) / ".config" / "killswitch" / "options.json");
    if (old_xdg) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
}
