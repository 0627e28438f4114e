#pragma once
// A mesh uploaded to the GPU (VAO + vertex/index buffers) with its bounds. Instance attributes (model
// matrix, parameters) come from the renderer's shared instance buffer, bound per draw.
#include "render/mesh_data.h"

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
    // Points attributes 4..8 of this VAO at `instance_buffer` starting at `byte_offset`.
    void bind_instances(unsigned instance_buffer, std::size_t byte_offset) const;

  private:
    unsigned vao_ = 0, vbo_ = 0, ebo_ = 0;
    int index_count_ = 0;
    geometry::Aabb bounds_;
};

struct InstanceData {
    Mat4 model;
    Vec4 params; // x: emissive scale, yzw: tint (MeshInstance::tint)
};

} // namespace ks::render
