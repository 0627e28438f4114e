#include "mesh.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace ks::assetgen {

float largest_stretch(const glm::mat3& linear) {
    // The largest singular value. Columns all as long as the cube root of the determinant are orthogonal
    // (Hadamard's inequality is then an equality): a similarity, the shapes' usual placement.
    const float uniform = std::cbrt(std::abs(glm::determinant(linear)));
    float frobenius = 0.0f;
    for (int c = 0; c < 3; ++c) frobenius += glm::dot(linear[c], linear[c]);
    frobenius = std::sqrt(frobenius);
    float longest = 0.0f;
    for (int c = 0; c < 3; ++c) longest = std::max(longest, glm::length(linear[c]));
    const bool similarity = std::abs(longest - uniform) <= 1e-5f * std::max(longest, 1e-30f);
    return similarity ? longest : frobenius;
}

void Mesh::append(const Mesh& other, const mat4& transform) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    const glm::mat3 linear(transform);
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;
    for (const Vertex& v : other.vertices) {
        Vertex t = v;
        t.position = vec3(transform * vec4(v.position, 1.0f));
        t.normal = glm::normalize(normal_matrix * v.normal);
        vec3 tangent = linear * vec3(v.tangent);
        const float len = glm::length(tangent);
        tangent = len > 0.0f ? tangent / len : vec3(1, 0, 0);
        t.tangent = vec4(tangent, mirrored ? -v.tangent.w : v.tangent.w);
        vertices.push_back(t);
    }
    for (size_t i = 0; i + 2 < other.indices.size(); i += 3) {
        const std::uint32_t a = other.indices[i] + base, b = other.indices[i + 1] + base,
                            c = other.indices[i + 2] + base;
        if (mirrored)
            triangle(a, c, b);
        else
            triangle(a, b, c);
    }
    if (other.deviation > 0.0f) deviation = std::max(deviation, other.deviation * largest_stretch(linear));
}

void Mesh::compute_tangents() {
    std::vector<vec3> tan(vertices.size(), vec3(0.0f)), up(vertices.size(), vec3(0.0f));
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        const std::uint32_t ia = indices[i], ib = indices[i + 1], ic = indices[i + 2];
        const Vertex &a = vertices[ia], &b = vertices[ib], &c = vertices[ic];
        const vec3 e1 = b.position - a.position, e2 = c.position - a.position;
        const vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12f) continue;
        const float r = 1.0f / det;
        const vec3 dpdu = (e1 * d2.y - e2 * d1.y) * r;
        const vec3 dpdv = (e2 * d1.x - e1 * d2.x) * r;
        for (std::uint32_t k : {ia, ib, ic}) {
            tan[k] += dpdu;
            up[k] -= dpdv; // image "up" is -v in glTF uv space
        }
    }
    for (size_t k = 0; k < vertices.size(); ++k) {
        const vec3 n = vertices[k].normal;
        vec3 t = tan[k] - n * glm::dot(n, tan[k]);
        if (glm::dot(t, t) < 1e-20f) {
            // No uv gradient here (degenerate): any direction perpendicular to the normal will do.
            t = std::abs(n.x) < 0.9f ? glm::cross(n, vec3(1, 0, 0)) : glm::cross(n, vec3(0, 1, 0));
            t = glm::cross(t, n);
        }
        t = glm::normalize(t);
        const float w = glm::dot(glm::cross(n, t), up[k]) < 0.0f ? -1.0f : 1.0f;
        vertices[k].tangent = vec4(t, w);
    }
}

void Mesh::transform_uvs(vec2 scale, vec2 offset) {
    for (Vertex& v : vertices) v.uv = v.uv * scale + offset;
}

mat4 trs(vec3 translation, vec3 euler_xyz, vec3 scale) {
    mat4 m = glm::translate(mat4(1.0f), translation);
    // Euler XYZ as three.js applies it: R = Rx * Ry * Rz acting on column vectors.
    m = glm::rotate(m, euler_xyz.x, vec3(1, 0, 0));
    m = glm::rotate(m, euler_xyz.y, vec3(0, 1, 0));
    m = glm::rotate(m, euler_xyz.z, vec3(0, 0, 1));
    return glm::scale(m, scale);
}

} // namespace ks::assetgen
