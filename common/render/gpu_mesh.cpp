#include "render/gpu_mesh.h"

#include "brush/convex_hull.h"

#include <epoxy/gl.h>

#include <cstddef>

namespace ks::render {

GpuMesh::GpuMesh(const MeshData& data)
    : index_count_(static_cast<int>(data.indices.size())),
      vertex_count_(static_cast<int>(data.vertices.size())), bounds_(data.bounds()) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glGenBuffers(1, &ebo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.vertices.size() * sizeof(Vertex)),
                 data.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)), data.indices.data(),
                 GL_STATIC_DRAW);
    auto attrib = [](GLuint index, GLint size, std::size_t offset) {
        glEnableVertexAttribArray(index);
        glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<void*>(offset));
    };
    attrib(0, 3, offsetof(Vertex, position));
    attrib(1, 3, offsetof(Vertex, normal));
    attrib(2, 2, offsetof(Vertex, uv));
    attrib(3, 4, offsetof(Vertex, tangent));
    attrib(9, 2, offsetof(Vertex, lightmap_uv));
    for (GLuint i = 4; i <= 8; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribDivisor(i, 1);
    }
    glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (ebo_) glDeleteBuffers(1, &ebo_);
}

const std::vector<Vec3>& GpuMesh::hull_corners() const {
    if (!hull_corners_.empty()) return hull_corners_;
    std::vector<Vertex> vertices(static_cast<std::size_t>(vertex_count_));
    if (vbo_ && !vertices.empty()) {
        glBindBuffer(GL_COPY_READ_BUFFER, vbo_);
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                           vertices.data());
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
    }
    std::vector<DVec3> points;
    points.reserve(vertices.size());
    for (const Vertex& v : vertices) points.push_back(exact_double(v.position));
    if (auto hull = brush::convex_hull_measure(points); hull)
        for (int corner : hull->corners)
            hull_corners_.push_back(vertices[static_cast<std::size_t>(corner)].position);
    if (hull_corners_.empty() && bounds_.valid())
        for (int corner = 0; corner < 8; ++corner)
            hull_corners_.push_back(Vec3((corner & 1) ? bounds_.max.x : bounds_.min.x,
                                         (corner & 2) ? bounds_.max.y : bounds_.min.y,
                                         (corner & 4) ? bounds_.max.z : bounds_.min.z));
    return hull_corners_;
}

void GpuMesh::bind_instances(unsigned instance_buffer, std::size_t byte_offset) const {
    glBindBuffer(GL_ARRAY_BUFFER, instance_buffer);
    for (GLuint i = 0; i < 4; ++i)
        glVertexAttribPointer(4 + i, 4, GL_FLOAT, GL_FALSE, sizeof(InstanceData),
                              reinterpret_cast<void*>(byte_offset + sizeof(Vec4) * i));
    glVertexAttribPointer(8, 4, GL_FLOAT, GL_FALSE, sizeof(InstanceData),
                          reinterpret_cast<void*>(byte_offset + offsetof(InstanceData, params)));
}

} // namespace ks::render
