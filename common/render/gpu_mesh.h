#pragma once
// A mesh uploaded to the GPU (VAO + vertex/index buffers) with its bounds. Instance attributes (model
// matrix, parameters) come from the renderer's shared instance buffer, bound per draw.
#include "render/mesh_data.h"

#include <vector>

namespace ks::render {

class GpuMesh {
  public:
    GpuMesh() = default;
    explicit GpuMesh(const MeshData& data);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    unsigned vao() const { return vao_; }
    int index_count() const { return index_count_; }
    const geometry::Aabb& bounds() const { return bounds_; }
    // The corners of the mesh's convex hull (mesh space): the points the view model's screen footprint
    // projects (view_model_layer.h), a tighter outline than the bounds' corners. Made on first use from the
    // vertex buffer read back (one Qhull run, kept with the mesh: only the meshes that ask pay); the bounds'
    // 8 corners when the vertices span no volume.
    const std::vector<Vec3>& hull_corners() const;
    // Points attributes 4..8 of this VAO at `instance_buffer` starting at `byte_offset`.
    void bind_instances(unsigned instance_buffer, std::size_t byte_offset) const;

  private:
    unsigned vao_ = 0, vbo_ = 0, ebo_ = 0;
    int index_count_ = 0, vertex_count_ = 0;
    geometry::Aabb bounds_;
    mutable std::vector<Vec3> hull_corners_; // empty until first asked for
};

struct InstanceData {
    Mat4 model;
    Vec4 params; // x: emissive scale, yzw: tint (MeshInstance::tint)
};

} // namespace ks::render
