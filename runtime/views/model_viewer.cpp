#include "views/model_viewer.h"

#include "core/paths.h"
#include "render/level_scene.h"
#include "render/mesh_data.h"
#include "render/model.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace ks::runtime {

ModelViewer::ModelViewer(render::AssetLibrary& assets, const std::string& name,
                         render::Environment& environment, std::vector<render::Light>& lights) {
    std::string model_name = name;
    std::filesystem::path p(name);
    if (p.has_extension()) model_name = paths::resolve_user_path(p).string();
    model_ = &assets.model(model_name);
    render::MeshData floor;
    render::append_box(floor, Vec3(0, -0.05f, 0), Vec3(40, 0.1f, 40), Mat4(1.0f), 2.0f);
    floor_ = std::make_unique<render::GpuMesh>(floor);
    floor_material_ = &assets.surface("tiles");
    environment = render::preview_environment(0.04f);
    const auto& b = model_->bounds;
    radius_ = std::max(1.0f, glm::length(b.max - b.min)) * 1.1f;
    lights.push_back({render::Light::Type::Point, Vec3(2.5f, 3.0f, 3.0f) * (radius_ / 3.0f), Vec3(0, -1, 0),
                      Vec3(1.0f, 0.85f, 0.7f), 0.6f, radius_ * 4.0f, 0.8f, 0.9f});
    lights.push_back({render::Light::Type::Point, Vec3(-3.0f, 2.0f, -2.0f) * (radius_ / 3.0f), Vec3(0, -1, 0),
                      Vec3(0.5f, 0.7f, 1.0f), 0.5f, radius_ * 4.0f, 0.8f, 0.9f});
}

void ModelViewer::emit(double time, std::vector<Mat4>& scratch, std::vector<render::MeshInstance>& instances,
                       geometry::Camera& camera) const {
    instances.clear();
    float angle = static_cast<float>(time) * 0.6f + 0.6f;
    Mat4 root = glm::rotate(Mat4(1.0f), angle, Vec3(0, 1, 0));
    const auto& b = model_->bounds;
    root = glm::translate(root, Vec3(-b.center().x, -b.min.y, -b.center().z));
    model_->emit(root, scratch, instances);
    instances.push_back({floor_.get(), floor_material_, Mat4(1.0f), 1.0f, false});
    float h = b.max.y - b.min.y;
    Vec3 target(0.0f, h * 0.45f, 0.0f);
    camera.position = target + Vec3(0.0f, radius_ * 0.35f, radius_ * 1.15f);
    Vec3 d = glm::normalize(target - camera.position);
    camera.yaw = std::atan2(-d.x, -d.z);
    camera.pitch = std::asin(d.y);
    camera.fov_y = radians(45.0f);
}

} // namespace ks::runtime
