#include "runtime/play_session.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace ks::test {

std::string corridor_level_json(double start_yaw) {
    char start[128];
    std::snprintf(start, sizeof(start), R"({"position": [0, 0, 20], "yaw": %.4f})", start_yaw);
    return std::string(R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Input test corridor",
  "player_start": )") +
           start + R"(,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, -10], "props": {"size": [20, 80]}},
    {"id": 2, "type": "wall", "name": "Wall west of the door", "position": [-6.25, 0, 0],
     "props": {"size": [7.5, 16, 0.5]}},
    {"id": 3, "type": "wall", "name": "Wall east of the door", "position": [6.25, 0, 0],
     "props": {"size": [7.5, 16, 0.5]}},
    {"id": 4, "type": "wall", "name": "Lintel", "position": [0, 5, 0], "props": {"size": [5, 11, 0.5]}},
    {"id": 5, "type": "top_light", "name": "Lamp south", "position": [0, 16, 10]},
    {"id": 6, "type": "top_light", "name": "Lamp north", "position": [0, 16, -18]},
    {"id": 10, "type": "pickup", "name": "Ammo", "position": [0, 0, 16], "props": {"kind": "ammo", "amount": 50}},
    {"id": 11, "type": "floor_light", "name": "Floor light", "position": [3, 0, 9], "rotation": [90, 0, 0]},
    {"id": 12, "type": "door", "name": "Door", "position": [0, 0, 0]},
    {"id": 13, "type": "gas_cylinder", "name": "Cylinder", "position": [0, 0, -14],
     "props": {"radius": 0.8, "height": 5}},
    {"id": 14, "type": "control_panel", "name": "Panel", "position": [0, 0, -24],
     "links": [{"event": "on_use", "target": "shutdown", "action": "complete"}]}
  ],
  "objectives": [{"id": "shutdown", "text": "Shut down the simulation at the control panel"}]
}
)";
}

Status parse_status(const std::string& text) {
    Status s;
    s.text = text;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream in(line);
        std::string key;
        in >> key;
        auto rest = [&]() {
            std::string r;
            std::getline(in, r);
            return r.empty() ? r : r.substr(1);
        };
        if (key == "screen")
            in >> s.screen;
        else if (key == "phase")
            in >> s.phase;
        else if (key == "captured")
            in >> s.captured;
        else if (key == "paused")
            in >> s.paused;
        else if (key == "feet")
            in >> s.feet[0] >> s.feet[1] >> s.feet[2];
        else if (key == "yaw")
            in >> s.yaw;
        else if (key == "pitch")
            in >> s.pitch;
        else if (key == "health")
            in >> s.health;
        else if (key == "shield")
            in >> s.shield;
        else if (key == "ammo")
            in >> s.ammo;
        else if (key == "shots")
            in >> s.shots;
        else if (key == "camera_roll")
            in >> s.camera_roll;
        else if (key == "game_steps")
            in >> s.game_steps;
        else if (key == "dropped_steps")
            in >> s.dropped_steps;
        else if (key == "frame") {
            in >> s.frame;
            s.valid = true; // the last line: the file is complete
        } else if (key == "caption")
            s.caption = rest();
        else if (key == "door") {
            int id = 0;
            double p = 0;
            in >> id >> p;
            s.doors[id] = p;
        } else if (key == "light" || key == "pickup" || key == "cylinder") {
            int id = 0;
            std::string v;
            in >> id >> v;
            (key == "light" ? s.lights : key == "pickup" ? s.pickups : s.cylinders)[id] = v;
        } else if (key == "button") {
            Status::Button b;
            in >> b.x0 >> b.y0 >> b.x1 >> b.y1;
            s.buttons[rest()] = b;
        }
    }
    return s;
}

Status read_status(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return {};
    return parse_status(read_file(file));
}

GameProcess::GameProcess(const std::vector<std::string>& args, const std::filesystem::path& log,
                         const std::filesystem::path& config_dir, const std::string& display)
    : log_(log) {
    const std::string exe = (bin_dir() / "killswitch").string();
    std::vector<std::string> argv_store = {exe};
    argv_store.insert(argv_store.end(), args.begin(), args.end());
    pid_ = ::fork();
    if (pid_ == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            ::dup2(fd, 1);
            ::dup2(fd, 2);
            ::close(fd);
        }
        ::setenv("XDG_CONFIG_HOME", config_dir.c_str(), 1);
        if (!display.empty()) ::setenv("DISPLAY", display.c_str(), 1);
        std::vector<char*> argv;
        for (auto& a : argv_store) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execv(exe.c_str(), argv.data());
        std::_Exit(127);
    }
}

GameProcess::~GameProcess() {
    if (running()) {
        ::kill(pid_, SIGTERM);
        if (wait(5.0) < 0 && running()) {
            ::kill(pid_, SIGKILL);
            wait(5.0);
        }
    }
}

bool GameProcess::running() {
    if (pid_ <= 0 || exit_code_ >= 0) return false;
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == 0) return true;
    exit_code_ = r == pid_ && WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    return false;
}

int GameProcess::wait(double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (running() && std::chrono::steady_clock::now() < end)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return running() ? -1 : exit_code_;
}

std::string GameProcess::log() const {
    std::error_code ec;
    return std::filesystem::exists(log_, ec) ? read_file(log_) : std::string();
}

std::string scripted_env(const ScratchDir& dir) {
    static const PrivateDisplay display;
    return "env DISPLAY=" + display.name() + " XDG_CONFIG_HOME=" + (dir / "config").string() +
           " XDG_DATA_HOME=" + (dir / "data").string() + " ";
}

bool have_xdotool() {
    return run_command("command -v xdotool").exit_code == 0;
}

PrivateDisplay::PrivateDisplay() {
    const char* current = std::getenv("DISPLAY");
    name_ = current ? current : "";
    if (run_command("command -v Xvfb").exit_code != 0) return;
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
        ::close(fds[0]);
        const int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0) {
            ::dup2(null, 1);
            ::dup2(null, 2);
        }
        const std::string fd = std::to_string(fds[1]);
        // -r: no key autorepeat. A test holds a key until a frame has seen it, which on a loaded machine
        // can outlast the server's repeat delay: the repeats then typed into whatever took the keyboard
        // next (Ctrl+S's "s" into the Save prompt's path, which then saved to a file named "s").
        ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x720x24", "-nolisten", "tcp",
                 "-noreset", "-r", static_cast<char*>(nullptr));
        std::_Exit(127);
    }
    ::close(fds[1]);
    // The server writes its display number once it accepts connections.
    std::string number;
    char c = 0;
    while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (pid_ > 0 && !number.empty()) {
        name_ = ":" + number;
    } else {
        if (pid_ > 0) {
            ::kill(pid_, SIGTERM);
            ::waitpid(pid_, nullptr, 0);
        }
        pid_ = -1;
    }
}

PrivateDisplay::~PrivateDisplay() {
    if (pid_ > 0) {
        ::kill(pid_, SIGTERM);
        ::waitpid(pid_, nullptr, 0);
    }
}

std::string xdotool(const std::string& args, bool* ok, const std::string& display, int timeout_s) {
    auto r = run_command((display.empty() ? std::string() : "env DISPLAY=" + display + " ") + "timeout " +
                         std::to_string(timeout_s) + " xdotool " + args);
    if (ok) *ok = r.exit_code == 0;
    while (!r.output.empty() && (r.output.back() == '\n' || r.output.back() == ' ')) r.output.pop_back();
    return r.output;
}

} // namespace ks::test
