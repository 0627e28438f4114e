#include "shell/app_shell.h"

#include "core/cli.h"
#include "core/fixed_step.h"
#include "core/log.h"
#include "core/paths.h"
#include "core/startup_trace.h"
#include "render/imgui_renderer.h"
#include "render/window_target.h"
#include "shell/frame_pacing.h"
#include "shell/gl_window.h"
#include "shell/key_taps.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

namespace ks::shell {

// How many of the first frames the start-up trace marks when they are presented (a loading screen's bar
// takes one frame per step).
constexpr long long kTracedFrames = 200;

const std::vector<std::string>& shell_options() {
    static const std::vector<std::string> options = {"width", "height", "screenshot", "frames", "no-vsync"};
    return options;
}

Result<ShellConfig> shell_config_from_command_line(const CommandLine& cl, ShellConfig config) {
    auto width = cl.get_int("width", config.width, 64, 8192);
    if (!width) return width.error();
    auto height = cl.get_int("height", config.height, 64, 8192);
    if (!height) return height.error();
    auto frames = cl.get_int("frames", config.frames, 1, 100000);
    if (!frames) return frames.error();
    config.width = *width;
    config.height = *height;
    config.frames = *frames;
    config.screenshot_path = cl.get_or("screenshot", config.screenshot_path);
    if (cl.has("no-vsync") || !config.screenshot_path.empty()) config.vsync = false;
    return config;
}

namespace {
// Latin-1 and the punctuation menus and level texts use (dashes, quotes, the ellipsis of "Custom level…",
// bullets), arrows and check marks: DejaVu has them all; ImGui's default range stops at U+00FF.
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x2010, 0x2027, 0x2190, 0x2193, 0x2713, 0x2714, 0};

ImFont* load_font(const char* file, float size) {
    std::string path = paths::asset(std::string("fonts/") + file).string();
    ImGuiIO& io = ImGui::GetIO();
    if (FILE* probe = std::fopen(path.c_str(), "rb")) {
        std::fclose(probe);
        ImFontConfig cfg;
        cfg.OversampleH = 2;
        cfg.OversampleV = 2;
        if (ImFont* font = io.Fonts->AddFontFromFileTTF(path.c_str(), size, &cfg, kGlyphRanges)) return font;
    }
    log::warn(path, ": font missing or unreadable; using ImGui's built-in font (reinstall assets/fonts/)");
    ImFontConfig cfg;
    cfg.SizePixels = size;
    return io.Fonts->AddFontDefault(&cfg);
}
} // namespace

Result<AppShell*> AppShell::create(const ShellConfig& config) {
    auto* shell = new AppShell();
    if (auto r = shell->init(config); !r) {
        delete shell;
        return r.error();
    }
    return shell;
}

void AppShell::destroy(AppShell* shell) {
    delete shell;
}

Result<void> AppShell::init(const ShellConfig& config) {
    config_ = config;
    auto window = open_gl_window({config.title, config.width, config.height, true, true});
    if (!window) return window.error();
    window_ = *window;
    startup::mark("window and GL context");
    glfwSwapInterval(config.vsync ? 1 : 0);
    log::info("OpenGL ", render::gl_version_name(), " on ", gl_renderer());

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // layouts are the program's business, not a stray imgui.ini in the cwd
    // Sizes scale with the window height so text stays readable from 720p to 1080p and up.
    float scale = std::max(1.0f, static_cast<float>(config.height) / 720.0f);
    fonts_.body = load_font("DejaVuSans.ttf", 18.0f * scale);
    fonts_.title = load_font("DejaVuSans-Bold.ttf", 48.0f * scale);
    fonts_.hud = load_font("DejaVuSans-Bold.ttf", 24.0f * scale);
    fonts_.mono = load_font("DejaVuSansMono.ttf", 15.0f * scale);
    io.FontDefault = fonts_.body;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    install_key_taps(window_); // in front of the backend's key callback: quick taps are never lost
    render::init_imgui_renderer();
    imgui_ready_ = true;
    return ok();
}

AppShell::~AppShell() {
    if (imgui_ready_) {
        render::shutdown_imgui_renderer();
        uninstall_key_taps(window_);
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    close_gl_window(window_);
}

std::string AppShell::gl_renderer() const {
    return render::gl_renderer_name();
}

void AppShell::wake() {
    glfwPostEmptyEvent();
}

bool AppShell::input_held() const {
    for (int b = GLFW_MOUSE_BUTTON_1; b <= GLFW_MOUSE_BUTTON_LAST; ++b)
        if (glfwGetMouseButton(window_, b) == GLFW_PRESS) return true;
    for (int k = GLFW_KEY_SPACE; k <= GLFW_KEY_LAST; ++k)
        if (glfwGetKey(window_, k) == GLFW_PRESS) return true;
    return false;
}

// The display's refresh rate with vsync (swaps wait for it anyway where the driver honours the interval;
// under Xvfb or with llvmpipe they do not), 60 without.
double AppShell::max_fps() const {
    if (!config_.vsync) return 60.0;
    const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor());
    return mode && mode->refreshRate >= 24 && mode->refreshRate <= 1000 ? mode->refreshRate : 60.0;
}

bool AppShell::wait_for_frame(const ShellHooks& hooks, FramePacer& pacer) {
    bool waited = false;
    for (;;) {
        double now = glfwGetTime();
        const bool animating = !hooks.animating || hooks.animating() || input_held();
        if (pacer.frame_due(animating, now)) {
            if (animating)
                if (double cap = pacer.cap_wait(now); cap > 0.0)
                    std::this_thread::sleep_for(std::chrono::duration<double>(cap));
            return waited;
        }
        if (pacer.take_idle_poll(now)) {
            // A pad sends no events: it is polled here (a change is input). ImGui's text cursor blinks.
            const GamepadState before = gamepad_;
            if (!gamepad_injected_) poll_gamepad(gamepad_);
            if (!(gamepad_ == before)) pacer.on_event();
            if ((hooks.idle_poll && hooks.idle_poll()) || ImGui::GetIO().WantTextInput) pacer.request_frame();
            continue;
        }
        double timeout = pacer.wait_seconds(now);
        if (gamepad_.connected && !gamepad_injected_) timeout = std::min(timeout, 1.0 / 30.0);
        if (!(timeout > 0.0)) continue;
        glfwWaitEventsTimeout(timeout);
        waited = true;
        const double started = now;
        now = glfwGetTime();
        // Back before the timeout: an event came (or a wake()). Either way the next frame shows it.
        if (now < started + timeout - 1e-3 || glfwWindowShouldClose(window_)) pacer.on_event();
        if (gamepad_.connected && !gamepad_injected_) {
            const GamepadState before = gamepad_;
            poll_gamepad(gamepad_);
            if (!(gamepad_ == before)) pacer.on_event();
        }
    }
}

int AppShell::run(const ShellHooks& hooks) {
    FixedStepClock clock(config_.fixed_step);
    PacingSettings pacing;
    pacing.max_fps = max_fps();
    pacing.heartbeat_seconds = config_.heartbeat_seconds;
    FramePacer pacer(pacing);
    double last = glfwGetTime();
    FrameInfo info;
    int exit_code = 0;
    while (!glfwWindowShouldClose(window_)) {
        // Screenshot runs draw their frames back to back, as fast as they go.
        const bool waited = !screenshot_mode() && wait_for_frame(hooks, pacer);
        if (glfwWindowShouldClose(window_)) break;
        glfwPollEvents();
        if (!gamepad_injected_) poll_gamepad(gamepad_);
        double now = glfwGetTime();
        const double work_start = now;
        pacer.drew(now);
        // After a wait the time spent idle is no frame time: a clip or the world resumes where it stood.
        if (waited) last = std::max(last, now - pacer.frame_interval());
        // Screenshot runs use a fixed 1/60 s per frame so the picture is the same on every machine.
        info.frame_dt = screenshot_mode() ? 1.0 / 60.0 : now - last;
        last = now;
        int steps = clock.advance(info.frame_dt);
        for (int i = 0; i < steps && hooks.fixed_update; ++i) hooks.fixed_update(clock.step());
        info.alpha = clock.alpha();
        glfwGetFramebufferSize(window_, &info.width, &info.height);

        if (hooks.render) {
            render::bind_window_target(info.width, info.height);
            hooks.render(info);
        } else {
            render::clear_window_target(info.width, info.height, Vec3(0.05f, 0.06f, 0.08f));
        }
        render::begin_imgui_frame();
        ImGui_ImplGlfw_NewFrame();
        feed_imgui_nav(gamepad_);
        ImGui::NewFrame();
        if (hooks.imgui) hooks.imgui(info);
        ImGui::Render();
        release_seen_taps(); // this frame has seen the keys tapped since the last: let them go
        render::draw_imgui(ImGui::GetDrawData(), info.width, info.height);

        ++info.frame_index;
        if (screenshot_mode() && info.frame_index >= config_.frames) {
            render::finish_gpu();
            if (auto saved = render::save_framebuffer_png(config_.screenshot_path, info.width, info.height);
                !saved) {
                log::error(saved.error().str());
                exit_code = 1;
            } else {
                log::info("screenshot written to ", config_.screenshot_path);
            }
            break;
        }
        glfwSwapBuffers(window_);
        info.previous_work = glfwGetTime() - work_start;
        // The start-up trace's frames, each once it is on screen (a launcher stops the game at the one it
        // waits for).
        if (startup::enabled() && info.frame_index <= kTracedFrames) startup::mark("presented");
        if (hooks.wants_close && hooks.wants_close()) break;
    }
    return exit_code;
}

} // namespace ks::shell
