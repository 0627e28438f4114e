// The editor's Save for an untitled level offers the player's levels folder (where the game's Custom level…
// looks): with real X events, Ctrl+S on a new level and Enter in the path prompt save untitled.json into
// $XDG_DATA_HOME/killswitch/levels, which the editor creates.
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace ks;
using nlohmann::json;
using test::EditorProcess;
using Session = test::EditorSession;

TEST_CASE("editor input: an untitled level's Save offers the user levels folder, created on demand") {
    REQUIRE_MESSAGE((ks::test::have_display() && test::have_xdotool()),
                    "no DISPLAY or xdotool: input test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    const auto status = dir / "status.json";
    const auto levels = dir / "data" / "killswitch" / "levels";
    const test::PrivateDisplay display;
    EditorProcess editor(
        {"--width", "960", "--height", "540", "--status-file", status.string()},
        {"XDG_CONFIG_HOME=" + (dir / "config").string(), "XDG_DATA_HOME=" + (dir / "data").string()},
        display);
    Session s(status, editor, display);
    json st = s.wait("first frames", [](const json& j) { return j["frame"] >= 2; });
    CHECK(st["file"] == "");
    CHECK_FALSE(std::filesystem::exists(levels));
    s.key("ctrl+s"); // untitled: the path prompt, with the user levels folder filled in
    // Return goes to the prompt's field once it has the keyboard (a frame after it opens; on a slow frame
    // an earlier Return went nowhere and nothing was saved).
    s.wait("the path prompt taking text", [](const json& j) { return j["input"]["text_input"] == true; });
    CHECK(std::filesystem::is_directory(levels)); // made when the prompt opened
    s.key("Return");
    st = s.wait("saved", [](const json& j) { return j["file"] != ""; });
    CHECK(std::filesystem::path(st["file"].get<std::string>()) == levels / "untitled.json");
    CHECK(std::filesystem::exists(levels / "untitled.json"));
}
