#include "render/app_shell.h"
#include "render/raster_threads.h"

#include "core/cli.h"
#include "core/fixed_step.h"
#include "core/log.h"
#include "core/paths.h"

// epoxy must come before any header that pulls in GL/gl.h.
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdlib>
#include <vector>

namespace ks::render {

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

bool display_available() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

std::string no_display_message(const std::string& program) {
    return "No display found (DISPLAY is not set), so " + program +
           " cannot open a window.\n"
           "  On a desktop, run it from a terminal inside the graphical session.\n"
           "  Without one, use a virtual display:  xvfb-run -s \"-screen 0 1280x720x24\" " +
           program +
           " ...\n"
           "  or take a picture without looking:   " +
           program +
           " --screenshot out.png --frames 60 "
           "(under xvfb-run).";
}

namespace {
void glfw_error_callback(int code, const char* description) {
    log::error("GLFW error ", code, ": ", description);
}

ImFont* load_font(const char* file, float size) {
    std::string path = paths::asset(std::string("fonts/") + file).string();
    ImGuiIO& io = ImGui::GetIO();
    if (FILE* probe = std::fopen(path.c_str(), "rb")) {
        std::fclose(probe);
        ImFontConfig cfg;
        cfg.OversampleH = 2;
        cfg.OversampleV = 2;
        if (ImFont* font = io.Fonts->AddFontFromFileTTF(path.c_str(), size, &cfg)) return font;
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
    if (!display_available()) return Error(no_display_message(config.title));
    glfwSetErrorCallback(glfw_error_callback);
    configure_software_raster_threads(); // before the context: llvmpipe reads it once
    if (!glfwInit())
        return Error("cannot initialise GLFW (is the X server reachable?)", Location{},
                     no_display_message(config.title));
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0); // MSAA is done in the renderer's own framebuffer
    window_ = glfwCreateWindow(config.width, config.height, config.title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        return Error("cannot create an OpenGL 3.3 core window", Location{},
                     "the driver must support OpenGL 3.3 core; under Xvfb, Mesa's llvmpipe does");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(config.vsync ? 1 : 0);
    log::info("OpenGL ", reinterpret_cast<const char*>(glGetString(GL_VERSION)), " on ", gl_renderer());

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
    ImGui_ImplOpenGL3_Init("#version 330 core");
    imgui_ready_ = true;
    return ok();
}

AppShell::~AppShell() {
    if (imgui_ready_) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    if (window_) {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
}

std::string AppShell::gl_renderer() const {
    const GLubyte* name = glGetString(GL_RENDERER);
    return name ? reinterpret_cast<const char*>(name) : "unknown";
}

int AppShell::run(const ShellHooks& hooks) {
    FixedStepClock clock(config_.fixed_step);
    double last = glfwGetTime();
    FrameInfo info;
    int exit_code = 0;
    while (!glfwWindowShouldClose(window_)) {
        glfwPollEvents();
        double now = glfwGetTime();
        // Screenshot runs use a fixed 1/60 s per frame so the picture is the same on every machine.
        info.frame_dt = screenshot_mode() ? 1.0 / 60.0 : now - last;
        last = now;
        int steps = clock.advance(info.frame_dt);
        for (int i = 0; i < steps && hooks.fixed_update; ++i) hooks.fixed_update(clock.step());
        info.alpha = clock.alpha();
        glfwGetFramebufferSize(window_, &info.width, &info.height);

        glViewport(0, 0, info.width, info.height);
        if (hooks.render) {
            hooks.render(info);
        } else {
            glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        }
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (hooks.imgui) hooks.imgui(info);
        ImGui::Render();
        glViewport(0, 0, info.width, info.height);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        ++info.frame_index;
        if (screenshot_mode() && info.frame_index >= config_.frames) {
            glFinish();
            if (auto saved = save_framebuffer_png(config_.screenshot_path, info.width, info.height); !saved) {
                log::error(saved.error().str());
                exit_code = 1;
            } else {
                log::info("screenshot written to ", config_.screenshot_path);
            }
            break;
        }
        glfwSwapBuffers(window_);
        if (hooks.wants_close && hooks.wants_close()) break;
    }
    return exit_code;
}

} // namespace ks::render
