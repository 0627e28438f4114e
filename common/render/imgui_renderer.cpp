#include "render/imgui_renderer.h"

// epoxy must come before any header that pulls in GL/gl.h.
#include <epoxy/gl.h>

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace ks::render {

bool init_imgui_renderer() {
    return ImGui_ImplOpenGL3_Init("#version 330 core");
}

void shutdown_imgui_renderer() {
    ImGui_ImplOpenGL3_Shutdown();
}

void begin_imgui_frame() {
    ImGui_ImplOpenGL3_NewFrame();
}

void draw_imgui(ImDrawData* draw_data, int width, int height) {
    glViewport(0, 0, width, height);
    ImGui_ImplOpenGL3_RenderDrawData(draw_data);
}

} // namespace ks::render
