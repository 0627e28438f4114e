#include "ui/thumbnail_camera.h"

#include "render/debug_draw.h"
#include "render/scene_renderer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ks::editor::ui {

geometry::Camera thumbnail_camera(Vec3 lo, Vec3 hi) {
    geometry::Camera camera;
    camera.aspect = 1.0f;
    camera.fov_y = radians(40.0f);
    camera.yaw = radians(35.0f);
    camera.pitch = radians(-28.0f);
    const Vec3 centre = (lo + hi) * 0.5f;
    const float radius = std::max(0.5f, glm::length(hi - lo) * 0.5f);
    const float distance = radius / std::sin(camera.fov_y * 0.5f) * 1.02f;
    camera.position = centre - camera.forward() * distance;
    camera.near_plane = std::max(0.05f, distance - radius * 2.0f);
    camera.far_plane = distance + radius * 2.0f;
    return camera;
}

bool render_thumbnail(render::SceneRenderer& renderer, RenderTarget& target, int size, Vec3 lo, Vec3 hi,
                      const render::Environment& environment,
                      const std::vector<render::MeshInstance>& instances,
                      std::vector<render::Light>& lights) {
    const geometry::Camera camera = thumbnail_camera(lo, hi);
    if (lights.empty()) {
        render::Light lamp;
        lamp.position = camera.position + Vec3(0, glm::length(hi - lo) * 0.5f, 0);
        lamp.range = glm::length(hi - lo) * 3.0f + 10.0f;
        lamp.intensity = 1.6f;
        lights.push_back(lamp);
    }
    render::DebugDraw no_debug;
    render::SceneFrame frame;
    frame.camera = camera;
    frame.environment = environment;
    frame.environment.sky_color = glm::max(frame.environment.sky_color, Vec3(0.35f));
    frame.instances = &instances;
    frame.lights = &lights;
    frame.debug = &no_debug;
    frame.width = frame.height = size;
    if (!target.ensure(size, size)) return false;
    renderer.invalidate_shadows();
    target.bind();
    renderer.render(frame);
    renderer.invalidate_shadows();
    return true;
}

void thumbnail_label(std::string label, float cell, bool armed) {
    while (label.size() > 3 && ImGui::CalcTextSize(label.c_str()).x > cell)
        label.resize(label.size() - 4), label += "..";
    ImGui::PushStyleColor(ImGuiCol_Text, armed ? ImVec4(0.55f, 1.0f, 0.65f, 1) : ImVec4(0.85f, 0.9f, 1, 1));
    ImGui::TextUnformatted(label.c_str());
    ImGui::PopStyleColor();
}

} // namespace ks::editor::ui
