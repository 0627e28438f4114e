#pragma once
// The camera of the left column's thumbnails (the Prefabs and Models tabs): a three-quarter view from the
// front right, above, framing a box.
#include "geometry/camera.h"

namespace ks::editor::ui {

geometry::Camera thumbnail_camera(Vec3 lo, Vec3 hi);

} // namespace ks::editor::ui
