// An idle window is idle (common/shell/frame_pacing.h): the editor with the main level open and the game's
// main menu, each on an X server of the test's own, use next to no CPU once they have settled, and input
// wakes them (they draw again). CPU time is read from /proc/PID/stat (user + system, every thread: the
// software rasteriser's too). The bound is generous (a tenth of a core: ctest runs suites side by side on a
// busy machine); docs/performance.md ("Idle windows") has the measured numbers.
#include "runtime/editor_session.h"
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>

using namespace ks;

namespace {
constexpr double kIdleCoresBound = 0.10;

// User + system CPU seconds of process `pid` so far (-1 when it is gone).
double cpu_seconds(pid_t pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t paren = text.rfind(')'); // the command name may hold spaces
    if (paren == std::string::npos) return -1.0;
    std::istringstream fields(text.substr(paren + 2));
    std::string field;
    unsigned long long utime = 0, stime = 0;
    for (int i = 3; i <= 15 && fields >> field; ++i) { // fields 3.. after "pid (comm)"
        if (i == 14) utime = std::stoull(field);
        if (i == 15) stime = std::stoull(field);
    }
    return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// Cores used by `pid` over `seconds` of wall time.
double cores_over(pid_t pid, double seconds) {
    const double cpu0 = cpu_seconds(pid);
    const auto t0 = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return (cpu_seconds(pid) - cpu0) / wall;
}

// Waits (up to two minutes: loading and the first light-map bake take a while on a busy machine) until a
// second passes with the process under the bound, then measures five seconds; returns the cores used. Over
// the bound, five seconds more and the lower of the two: once-only work on a low-priority worker (the
// editor's preview bake) can pause through the quiet second when other low-priority work starves it and
// resume inside the first window, while a process that really wakes without input fails both.
double settled_idle_cores(pid_t pid) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    double last = 0.0;
    while (std::chrono::steady_clock::now() < deadline) {
        last = cores_over(pid, 1.0);
        if (last < kIdleCoresBound) {
            const double first = cores_over(pid, 5.0);
            return first < kIdleCoresBound ? first : std::min(first, cores_over(pid, 5.0));
        }
    }
    FAIL("never settled: still " << last << " cores after two minutes");
    return last;
}

// Waits (up to two minutes) until a light bake is stored under `cache_dir`: on a cold start the menu's level
// bakes in full on a low-priority worker (render/background_bake.h) and stores it when done, work the idle
// menu does once, not idling.
bool bake_stored(const std::filesystem::path& cache_dir) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (std::chrono::steady_clock::now() < deadline) {
        std::error_code ec;
        for (auto it = std::filesystem::recursive_directory_iterator(cache_dir, ec);
             !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
            if (it->path().filename().string().starts_with("lightbake-")) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
}

// The pointer moved over the window 20 times, 50 ms apart: the CPU seconds the process used meanwhile.
double cpu_while_moving(pid_t pid, const std::string& display) {
    bool ok = false;
    const std::string window =
        test::xdotool("search --sync --onlyvisible --pid " + std::to_string(pid), &ok, display, 60);
    REQUIRE(ok);
    const std::string id = window.substr(0, window.find('\n'));
    const double cpu0 = cpu_seconds(pid);
    for (int i = 0; i < 20; ++i) {
        test::xdotool("mousemove --window " + id + " " + std::to_string(200 + 10 * i) + " 200", &ok, display);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return cpu_seconds(pid) - cpu0;
}
} // namespace

TEST_CASE("idle: the editor with the main level open waits for input") {
    REQUIRE_MESSAGE((test::have_display() && test::have_xdotool()),
                    "no DISPLAY or xdotool: idle test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    const test::PrivateDisplay display;
    test::EditorProcess editor(
        {"--width", "1280", "--height", "720", "--level",
         (test::source_dir() / "levels" / "main.json").string()},
        {"XDG_CONFIG_HOME=" + (dir / "config").string(), "XDG_DATA_HOME=" + (dir / "data").string()},
        display);
    const pid_t pid = editor.pid();
    const double idle = settled_idle_cores(pid);
    MESSAGE("editor idle: " << idle * 100.0 << " % of a core");
    CHECK(idle < kIdleCoresBound);
    // Input wakes it: the frames drawn for 20 pointer moves cost far more than nothing.
    const double moving = cpu_while_moving(pid, display.name());
    MESSAGE("editor, pointer moving for 1.3 s: " << moving << " CPU seconds");
    CHECK(moving > 0.05);
    CHECK(editor.alive());
}

TEST_CASE("idle: the game's main menu waits for input") {
    REQUIRE_MESSAGE((test::have_display() && test::have_xdotool()),
                    "no DISPLAY or xdotool: idle test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    const test::PrivateDisplay display;
    // No sound card in a test: OpenAL's null output would mix in a thread of its own.
    setenv("ALSOFT_DRIVERS", "none", 1);
    // A cache of its own, so that the start is cold whatever ran before: the full bake runs behind the menu.
    const char* shared_cache = std::getenv("XDG_CACHE_HOME");
    const std::string saved_cache = shared_cache ? shared_cache : "";
    setenv("XDG_CACHE_HOME", (dir / "cache").c_str(), 1);
    test::GameProcess game({"--width", "1280", "--height", "720"}, dir / "game.log", dir / "config",
                           display.name());
    unsetenv("ALSOFT_DRIVERS");
    shared_cache ? setenv("XDG_CACHE_HOME", saved_cache.c_str(), 1) : unsetenv("XDG_CACHE_HOME");
    REQUIRE_MESSAGE(bake_stored(dir / "cache"),
                    "the menu's level never stored its light map: " << game.log());
    const double idle = settled_idle_cores(game.pid());
    MESSAGE("game main menu idle: " << idle * 100.0 << " % of a core");
    CHECK(idle < kIdleCoresBound);
    const double moving = cpu_while_moving(game.pid(), display.name());
    MESSAGE("game main menu, pointer moving for 1.3 s: " << moving << " CPU seconds");
    CHECK(moving > 0.05);
    INFO(game.log());
    CHECK(game.running());
}
