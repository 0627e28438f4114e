#pragma once
// killswitch --view MODEL: one model turning on a tiled floor disc under a sky-ish ambient, a sun and two
// coloured key lights, with the camera framing it from its bounds.
#include "geometry/camera.h"
#include "render/asset_library.h"
#include "render/gpu_mesh.h"
#include "render/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace ks::runtime {

class ModelViewer {
  public:
    // `name` is a path (with an extension) or a name in assets/models; fills the stage's environment and
    // key lights.
    ModelViewer(render::AssetLibrary& assets, const std::string& name, render::Environment& environment,
                std::vector<render::Light>& lights);

    // The model at turntable angle for `time` seconds plus the floor into `instances` (cleared first), and
    // the camera framing them.
    void emit(double time, std::vector<Mat4>& scratch, std::vector<render::MeshInstance>& instances,
              geometry::Camera& camera) const;

  private:
    const render::Model* model_ = nullptr;
    std::unique_ptr<render::GpuMesh> floor_;
    const render::Material* floor_material_ = nullptr;
    float radius_ = 3.0f;
};

} // namespace ks::runtime
