// killswitch-editor driven by real X input in tests: see editor_session.h.
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"

#include <doctest/doctest.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace ks::test {

EditorProcess::EditorProcess(const std::vector<std::string>& args, std::vector<std::string> env,
                             const PrivateDisplay& display) {
    env.push_back("DISPLAY=" + display.name());
    pid_ = fork();
    if (pid_ == 0) {
        for (auto& e : env) putenv(e.data());
        std::vector<std::string> all = {(bin_dir() / "killswitch-editor").string()};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (auto& a : all) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
}

EditorProcess::~EditorProcess() {
    if (pid_ > 0) {
        kill(pid_, SIGTERM);
        waitpid(pid_, nullptr, 0);
    }
}

bool EditorProcess::alive() const {
    return pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == 0;
}

int EditorProcess::wait_exit(double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (pid_ > 0 && std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {
            pid_ = -1; // reaped: the destructor has nothing to stop
            return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
    }
    return -1;
}

EditorSession::EditorSession(std::filesystem::path status, const EditorProcess& process,
                             const PrivateDisplay& display)
    : status_(std::move(status)), process_(process), display_(display.name()) {}

EditorSession::json EditorSession::wait(const char* what, const std::function<bool(const json&)>& ready) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    while (std::chrono::steady_clock::now() < deadline) {
        std::ifstream in(status_);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        json s = json::parse(text, nullptr, false);
        if (!s.is_discarded()) {
            last_ = s;
            if (ready(s)) return s;
        }
        if (!process_.alive()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
    }
    FAIL("timed out waiting for: " << std::string(what) << "\nlast status: " << last_.dump());
    return last_;
}

EditorSession::json EditorSession::frames(int n) {
    wait("the current frame", [](const json&) { return true; });
    const auto start = last_.value("frame", 0ull);
    return wait("frames", [&](const json& s) { return s["frame"].get<unsigned long long>() >= start + n; });
}

std::string EditorSession::at(const json& point) const {
    const int x = last_["window"][0].get<int>() + static_cast<int>(point[0].get<float>());
    const int y = last_["window"][1].get<int>() + static_cast<int>(point[1].get<float>());
    return std::to_string(x) + " " + std::to_string(y);
}

void EditorSession::key(const std::string& keys, std::chrono::milliseconds hold) {
    focus();
    auto keys_down = [](const json& j) { return j["input"].value("keys_down", 0); };
    xdo("keydown " + keys);
    // Released as soon as a frame has seen it: counting frames instead held it past ImGui's key-repeat
    // delay whenever frames were slow (a sanitizer build in CI), and Ctrl+Z undid twice.
    wait("the key seen pressed", [&](const json& j) { return keys_down(j) > 0; });
    if (hold.count() > 0) { // past ImGui's key-repeat delay (0.275 s), then two more frames see it
        std::this_thread::sleep_for(hold);
        frames(2);
    }
    xdo("keyup " + keys);
    wait("the key seen released", [&](const json& j) { return keys_down(j) == 0; });
}

void EditorSession::type(const std::string& text) {
    focus();
    xdo("type --delay 60 '" + text + "'");
    frames(2);
}

void EditorSession::focus() {
    if (window_.empty()) {
        // `search --sync` waits for the window forever; `timeout` bounds it should the editor not map one.
        window_ = xdo("search --sync --onlyvisible --pid " + std::to_string(last_["pid"].get<long>()), 60);
        window_ = window_.substr(0, window_.find('\n'));
    }
    // Only when another window has it: refocusing the focused window can send it a focus-out and focus-in
    // that ImGui sees in different frames, and a focus loss releases every key ImGui holds.
    std::string focused = xdo("getwindowfocus");
    focused = focused.substr(0, focused.find('\n'));
    if (focused != window_) xdo("windowfocus --sync " + window_);
}

void EditorSession::move_to(const json& point) {
    focus();
    xdo("mousemove " + at(point));
    // Window coordinates as at() sends them (truncated); the editor reports where ImGui saw the pointer.
    const float x = std::trunc(point[0].get<float>()), y = std::trunc(point[1].get<float>());
    wait("the pointer seen where it was moved", [&](const json& j) {
        const json& mouse = j["input"]["mouse"];
        return std::fabs(mouse[0].get<float>() - x) <= 1.0f && std::fabs(mouse[1].get<float>() - y) <= 1.0f;
    });
}

void EditorSession::click(const json& point) {
    move_to(point);
    frames(1);
    xdo("click 1");
}

void EditorSession::drag(const json& from, float dx, float dy, int steps) {
    move_to(from);
    frames(1);
    press();
    for (int i = 1; i <= steps; ++i) {
        const float u = static_cast<float>(i) / static_cast<float>(steps);
        move_to(json{from[0].get<float>() + dx * u, from[1].get<float>() + dy * u});
    }
    release();
    frames(1);
}

void EditorSession::press() {
    xdo("mousedown 1");
    wait("the button seen held", [](const json& j) { return (j["input"]["buttons"].get<int>() & 1) != 0; });
}

void EditorSession::release() {
    xdo("mouseup 1");
    wait("the button seen let go", [](const json& j) { return (j["input"]["buttons"].get<int>() & 1) == 0; });
}

std::string EditorSession::xdo(const std::string& args, int timeout_s) const {
    bool ok = false;
    const std::string output = xdotool(args, &ok, display_, timeout_s);
    INFO("xdotool " << args << ": " << output);
    REQUIRE(ok);
    return output;
}

void require_window_test_tools() {
    REQUIRE_MESSAGE(have_display(), "needs a display: ./run.sh test runs this under xvfb-run");
    REQUIRE_MESSAGE(have_xdotool(), "needs xdotool (./run.sh installs it)");
}

bool has_spot(const nlohmann::json& status, const std::string& name) {
    return status.contains("spots") && status["spots"].contains(name);
}

ScratchEditor::ScratchEditor() {
    require_window_test_tools();
}

void ScratchEditor::start(std::vector<std::string> args) {
    const auto status = dir_ / "status.json";
    args.insert(args.end(), {"--status-file", status.string()});
    process_ = std::make_unique<EditorProcess>(
        args,
        std::vector<std::string>{"XDG_CONFIG_HOME=" + (dir_ / "config").string(),
                                 "XDG_DATA_HOME=" + (dir_ / "data").string()},
        display_);
    session_ = std::make_unique<EditorSession>(status, *process_, display_);
}

EditorWindow::EditorWindow(const std::string& level_json, const std::vector<std::string>& args) {
    level_file_ = write_file(dir_ / "level.json", level_json);
    std::vector<std::string> all{"--level", level_file_.string()};
    all.insert(all.end(), args.begin(), args.end());
    start(std::move(all));
}

DojoWindow::DojoWindow(const std::string& view) {
    clips_ = dir_ / "clips.json";
    std::filesystem::copy_file(source_dir() / "assets" / "animations" / "robot.json", clips_);
    std::vector<std::string> args{"--dojo", "--dojo-file", clips_.string()};
    if (!view.empty()) args.insert(args.end(), {"--dojo-view", view});
    args.insert(args.end(), {"--width", "1280", "--height", "720"});
    start(std::move(args));
}

} // namespace ks::test
