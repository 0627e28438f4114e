#pragma once
// The left column's thumbnails (the Prefabs and Models tabs): a three-quarter view from the front right,
// above, framing a box, and the one way both draw one.
#include "geometry/camera.h"
#include "render/scene.h"
#include "ui/render_target.h"

#include <string>
#include <vector>

namespace ks::render {
class SceneRenderer;
}

namespace ks::editor::ui {

geometry::Camera thumbnail_camera(Vec3 lo, Vec3 hi);

// Draws `instances` framed on the box lo..hi into `target` (size x size) under `environment` (its sky
// lifted so a dark level still shows the thing), lit by `lights` or, when it has none of its own, by a lamp
// over the camera's shoulder. The renderer's cached shadow map is the level's: dropped before and after.
// False when the target cannot be made.
bool render_thumbnail(render::SceneRenderer& renderer, RenderTarget& target, int size, Vec3 lo, Vec3 hi,
                      const render::Environment& environment,
                      const std::vector<render::MeshInstance>& instances, std::vector<render::Light>& lights);

// The name under a thumbnail, cut with ".." to the cell's width, green when it is the armed one.
void thumbnail_label(std::string label, float cell, bool armed);

} // namespace ks::editor::ui
