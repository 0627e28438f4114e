#pragma once
// The window shell shared by the runtime and the editor: a GLFW window with an OpenGL 3.3+ core context,
// Dear ImGui's context, fonts and GLFW platform backend, a fixed-step loop, and the --screenshot/--frames
// mode that renders N frames, writes a PNG and exits (used by tests and for looking at what we build).
// The loop draws only when something changes (frame_pacing.h): input, or the app saying it animates; an idle
// window waits for events and costs next to nothing.
// The split with common/render/: the shell owns the window, events, time and ImGui's platform side and
// issues no OpenGL call; every GL call (clearing, ImGui's OpenGL3 renderer backend, read-backs) goes
// through render/ (window_target.h, imgui_renderer.h).
#include "core/result.h"
#include "shell/display.h"
#include "shell/gamepad.h"

#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;
struct ImFont;

namespace ks {
class CommandLine;
}

namespace ks::shell {

class FramePacer;

// The heartbeat of the --status-file modes (ShellConfig::heartbeat_seconds).
inline constexpr double kStatusHeartbeatSeconds = 0.1;

struct ShellConfig {
    std::string title = "Killswitch";
    int width = 1280;
    int height = 720;
    int msaa_samples = 4;
    bool vsync = true;
    double fixed_step = 1.0 / 120.0;
    std::string screenshot_path; // when set: render `frames` frames, save, exit
    int frames = 3;
    // > 0: a frame at least this often even when idle (--status-file: tests count frames to know that the
    // input they sent has been seen).
    double heartbeat_seconds = 0.0;
};

// Reads --width, --height, --screenshot, --frames, --no-vsync into a config.
Result<ShellConfig> shell_config_from_command_line(const CommandLine& cl, ShellConfig defaults);
// The options shell_config_from_command_line understands (for the executables' unknown-option checks).
const std::vector<std::string>& shell_options();

// The fonts loaded for menus and HUD (assets/fonts/), at sizes good for 720p and 1080p.
struct Fonts {
    ImFont* body = nullptr;  // ~18 px at 720p
    ImFont* title = nullptr; // ~48 px
    ImFont* hud = nullptr;   // ~24 px bold
    ImFont* mono = nullptr;  // ~15 px monospace (debug text)
};

struct FrameInfo {
    int width = 0, height = 0; // framebuffer size in pixels
    double frame_dt = 0.0;     // real (or, in screenshot mode, fixed 1/60 s) frame time
    double alpha = 0.0;        // interpolation between the last two fixed steps
    long long frame_index = 0;
    // The last frame's work: from the end of its wait to the end of its buffer swap (s; 0 before the first).
    // Unlike frame_dt it leaves out the pacing's waits, so it says how long the machine needs for a frame
    // (the game's dynamic resolution reads it; a software rasteriser draws during the swap).
    double previous_work = 0.0;
};

struct ShellHooks {
    std::function<void(double step)> fixed_update; // called 0..n times per frame with the fixed step
    std::function<void(const FrameInfo&)> render;  // draw the scene (GL)
    std::function<void(const FrameInfo&)> imgui;   // build ImGui windows for this frame
    std::function<bool()> wants_close;             // return true to end the loop
    // True while the app needs frame after frame (play, an animation, a running job whose progress shows).
    // Unset: always (a view that never rests). Otherwise the loop waits for input between frames; a held
    // key or mouse button counts as animating (key repeat, drags, flying).
    std::function<bool()> animating;
    // While the loop waits: the app's cheap checks (files changed on disk, a child process's output,
    // timers), about twice a second; true when the window should be drawn again.
    std::function<bool()> idle_poll;
};

class AppShell {
  public:
    static Result<AppShell*> create(const ShellConfig& config); // owned by caller via destroy()
    static void destroy(AppShell* shell);

    // Runs until the window closes or hooks.wants_close() says so; returns the process exit code.
    int run(const ShellHooks& hooks);
    // From any thread (a background job that finished): wakes the waiting loop for one frame.
    static void wake();

    GLFWwindow* window() const { return window_; }
    const Fonts& fonts() const { return fonts_; }
    const ShellConfig& config() const { return config_; }
    bool screenshot_mode() const { return !config_.screenshot_path.empty(); }
    std::string gl_renderer() const;
    // The first gamepad as polled at the start of this frame (before the fixed steps).
    const GamepadState& gamepad() const { return gamepad_; }
    // Scripted input (tests): from now on the pad reads `state` instead of the real one.
    void inject_gamepad(const GamepadState& state) {
        gamepad_ = state;
        gamepad_injected_ = true;
    }

  private:
    AppShell() = default;
    ~AppShell();
    Result<void> init(const ShellConfig& config);
    // Waits until the next frame is due (frame_pacing.h); true when it waited for events.
    bool wait_for_frame(const ShellHooks& hooks, FramePacer& pacer);
    bool input_held() const;
    double max_fps() const;

    ShellConfig config_;
    GLFWwindow* window_ = nullptr;
    Fonts fonts_;
    bool imgui_ready_ = false;
    GamepadState gamepad_;
    bool gamepad_injected_ = false;
};

} // namespace ks::shell
