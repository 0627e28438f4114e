#pragma once
// Dear ImGui's OpenGL3 renderer backend: the GL half of ImGui (its shaders, font texture and draw calls).
// The shell runs ImGui's context, fonts and GLFW platform backend and calls these each frame.
struct ImDrawData;

namespace ks::render {

// Creates the backend's GL objects for the current context (after ImGui::CreateContext).
bool init_imgui_renderer();
void shutdown_imgui_renderer();
// Before ImGui::NewFrame: uploads the font atlas the first time.
void begin_imgui_frame();
// After ImGui::Render: draws the frame's lists into the window with the full viewport.
void draw_imgui(ImDrawData* draw_data, int width, int height);

} // namespace ks::render
