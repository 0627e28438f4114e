// The menu entries' StartupWMClass (packaging/*.desktop) is the class of the window each program opens
// (GLFW names it after the window's first title), so a desktop shows the entry's name and icon for the
// running window. Each program runs on a display of the test's own; xdotool finds its window by class.
#include "runtime/editor_session.h"
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <chrono>
#include <sstream>
#include <string>
#include <thread>

using namespace ks;

namespace {
std::string startup_wm_class(const std::string& entry) {
    std::istringstream in(test::read_file(test::source_dir() / "packaging" / (entry + ".desktop")));
    for (std::string line; std::getline(in, line);)
        if (line.rfind("StartupWMClass=", 0) == 0) return line.substr(15);
    return "";
}

// Polls (up to a minute: start-up is slow on a busy machine) for a window of exactly that class.
bool window_of_class(const std::string& wm_class, const test::PrivateDisplay& display) {
    for (int i = 0; i < 120; ++i) {
        bool ok = false;
        const std::string found =
            test::xdotool("search --class '^" + wm_class + "$'", &ok, display.name(), 10);
        if (ok && !found.empty()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    return false;
}
} // namespace

TEST_CASE("desktop entries: StartupWMClass is the class of each program's window") {
    REQUIRE_MESSAGE((test::have_display() && test::have_xdotool()),
                    "no DISPLAY or xdotool: window class test cannot run");
    test::ScratchDir dir;
    const test::PrivateDisplay display;
    const std::string game_class = startup_wm_class("killswitch");
    const std::string editor_class = startup_wm_class("killswitch-editor");
    REQUIRE(game_class == "Killswitch");
    REQUIRE(editor_class == "Killswitch Editor");
    {
        test::GameProcess game({"--width", "320", "--height", "240"}, dir / "game.log", dir / "config",
                               display.name());
        INFO(game.log());
        CHECK(window_of_class(game_class, display));
    }
    test::EditorProcess editor({"--width", "640", "--height", "480"},
                               {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    CHECK(window_of_class(editor_class, display));
}
