// The editor's Help > About, driven by real X input (xdotool under Xvfb): the Help menu opens, its About
// item shows the box with the editor's version (the project version) and licence, Close shuts it.
#include "core/version.h"
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <string>

using namespace ks;
using nlohmann::json;

TEST_CASE("editor about: Help > About shows the version and licence, Close shuts it") {
    REQUIRE_MESSAGE((test::have_display() && test::have_xdotool()),
                    "no DISPLAY or xdotool: editor input test cannot run");
    test::ScratchDir dir;
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    test::EditorProcess editor({"--width", "1280", "--height", "720", "--status-file", status.string()},
                               {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    test::EditorSession s(status, editor, display);
    json st = s.wait("the Help menu", [](const json& j) { return test::has_spot(j, "menu.help"); });
    CHECK(st["about"]["open"] == false);
    s.click(st["spots"]["menu.help"]);
    st = s.wait("the About item", [](const json& j) { return test::has_spot(j, "menu.about"); });
    s.click(st["spots"]["menu.about"]);
    st = s.wait("the About box", [](const json& j) { return test::has_spot(j, "about.close"); });
    CHECK(st["about"]["open"] == true);
    const auto lines = st["about"]["lines"].get<std::vector<std::string>>();
    REQUIRE(lines.size() >= 3);
    CHECK(lines[0] == "Killswitch Editor " + std::string(version::number()));
    bool licence = false;
    for (const std::string& line : lines)
        licence = licence || line.find("Licence: " + std::string(version::license())) != std::string::npos;
    CHECK(licence);
    s.click(st["spots"]["about.close"]);
    st = s.wait("the box closed", [](const json& j) { return j["about"]["open"] == false; });
    CHECK_FALSE(test::has_spot(st, "about.close"));
}
