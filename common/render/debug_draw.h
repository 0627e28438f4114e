#pragma once
// Debug lines for the editor and physics debugging: lines, boxes, capsules, rays. Calls accumulate into a
// reused vertex list; SceneRenderer::render draws and the owner clears it each frame.
#include "core/math.h"
#include "geometry/aabb.h"

#include <vector>

namespace ks::render {

struct DebugVertex {
    Vec3 position;
    Vec4 color;
};

class DebugDraw {
  public:
    DebugDraw() { vertices_.reserve(8192); }
    void line(const Vec3& a, const Vec3& b, const Vec4& color);
    void box(const geometry::Aabb& box, const Vec4& color);
    void box(const Mat4& transform, const Vec3& half_extents, const Vec4& color); // oriented
    void capsule(const Vec3& a, const Vec3& b, float radius, const Vec4& color, int segments = 16);
    void ray(const Vec3& origin, const Vec3& direction, float length, const Vec4& color);
    void clear() { vertices_.clear(); }
    const std::vector<DebugVertex>& vertices() const { return vertices_; }

  private:
    std::vector<DebugVertex> vertices_;
};

} // namespace ks::render
