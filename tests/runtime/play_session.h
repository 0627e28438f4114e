#pragma once
// Helpers for the tests that play `killswitch` through its input: a small level written to a scratch
// folder, the binary started in the background, its --status-file read back, and xdotool for real X events.
#include "test_support.h"

#include <map>
#include <string>
#include <sys/types.h>
#include <vector>

namespace ks::test {

// A corridor level for input tests: the player starts at (0, 0, 20) facing −z (yaw `start_yaw` degrees);
// an ammo pickup (id 10) at z = 16; a floor light (id 11) at (3, 0, 9); a door (id 12) at z = 0 in a wall;
// a tall gas cylinder (id 13) at z = −14 straight ahead; the control panel (id 14) at z = −24. No robots.
std::string corridor_level_json(double start_yaw = 0.0);

// What `killswitch --status-file` wrote (runtime/app/game_app.cpp write_status).
struct Status {
    bool valid = false;
    std::string text;
    std::string screen, phase, caption;
    bool captured = false, paused = false;
    double feet[3] = {0, 0, 0};
    double yaw = 0, pitch = 0, health = 0, shield = 0, camera_roll = 0;
    int ammo = 0, shots = 0;
    long long frame = -1, game_steps = 0, dropped_steps = 0;
    std::map<int, double> doors;          // id → opening progress 0..1
    std::map<int, std::string> lights;    // id → on/off
    std::map<int, std::string> pickups;   // id → present/taken
    std::map<int, std::string> cylinders; // id → standing/exploded
    struct Button {
        double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    };
    std::map<std::string, Button> buttons; // label → rectangle in window pixels
};
Status parse_status(const std::string& text);
Status read_status(const std::filesystem::path& file);

// killswitch running in the background with its output in a log file; killed when the object dies.
class GameProcess {
  public:
    // `display`: the X display to open (e.g. ":42"); empty keeps $DISPLAY.
    GameProcess(const std::vector<std::string>& args, const std::filesystem::path& log,
                const std::filesystem::path& config_dir, const std::string& display = "");
    ~GameProcess();
    GameProcess(const GameProcess&) = delete;
    GameProcess& operator=(const GameProcess&) = delete;
    bool running();
    // Waits for the process to end (up to `seconds`); returns its exit code or -1.
    int wait(double seconds);
    std::string log() const;
    pid_t pid() const { return pid_; }

  private:
    pid_t pid_ = -1;
    int exit_code_ = -1;
    std::filesystem::path log_;
};

// An X server of the test's own (Xvfb, display number chosen by the server), so that no other test's window
// takes the keyboard focus while real key events are sent (ctest runs the GL tests in parallel on one
// display, and every new GLFW window takes the focus). Falls back to $DISPLAY when Xvfb cannot start.
class PrivateDisplay {
  public:
    PrivateDisplay();
    ~PrivateDisplay();
    PrivateDisplay(const PrivateDisplay&) = delete;
    PrivateDisplay& operator=(const PrivateDisplay&) = delete;
    const std::string& name() const { return name_; } // ":N", or $DISPLAY
    bool own() const { return pid_ > 0; }

  private:
    pid_t pid_ = -1;
    std::string name_;
};

bool have_xdotool();
// "env DISPLAY=… XDG_CONFIG_HOME=… XDG_DATA_HOME=… ": a scripted run gets an X server of its own (one per
// test process), so that a window of a test running in parallel cannot sit over it and take the pointer or
// the focus, and config and data folders inside `dir`.
std::string scripted_env(const ScratchDir& dir);
// Runs "xdotool ARGS" on `display` (empty: $DISPLAY), killed after `timeout_s` (a `--sync` waits forever
// otherwise); returns its output (trimmed). `ok` is set from the exit code.
std::string xdotool(const std::string& args, bool* ok = nullptr, const std::string& display = "",
                    int timeout_s = 30);

} // namespace ks::test
