#pragma once
// Triangle meshes as the glTF writer wants them: one vertex array (position, normal, tangent, uv) and a
// 32-bit index list, counter-clockwise front faces. Shapes are built in their own frame and appended into
// a node's per-material mesh with a transform.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace ks::assetgen {

using glm::mat4;
using glm::quat;
using glm::vec2;
using glm::vec3;
using glm::vec4;

struct Vertex {
    vec3 position{0.0f};
    vec3 normal{0.0f, 1.0f, 0.0f};
    vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; // xyz along +u; w: bitangent = cross(normal, tangent) * w
    vec2 uv{0.0f};
};

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    // At a coarser level of detail (shapes.h: Detail), the most any point of this mesh lies from the same
    // mesh built in full, and any point of that from this (a bound on their Hausdorff distance, in this
    // mesh's units); 0 at full detail. append() carries it through transforms.
    float deviation = 0.0f;

    std::uint32_t add(const Vertex& v) {
        vertices.push_back(v);
        return static_cast<std::uint32_t>(vertices.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        indices.insert(indices.end(), {a, b, c});
    }
    size_t triangle_count() const { return indices.size() / 3; }

    // Appends `other` transformed by `transform` (normals by its inverse transpose; a mirroring transform
    // flips the winding and the tangent handedness so faces stay outward). The deviation becomes the larger
    // of the two, `other`'s scaled by the transform's largest stretch.
    void append(const Mesh& other, const mat4& transform = mat4(1.0f));
    // Per-vertex tangents from positions and uvs (accumulated over triangles, Gram-Schmidt against the
    // normal). The bitangent points toward the image top (-v in glTF uv), matching +Y-up normal maps.
    void compute_tangents();
    // Multiplies every uv by `scale` and adds `offset`.
    void transform_uvs(vec2 scale, vec2 offset = vec2(0.0f));
};

// The most `linear` stretches any vector: exact for a rotation times a uniform scale (to 1e-5), else the
// Frobenius norm, which bounds it from above.
float largest_stretch(const glm::mat3& linear);

// Translation * rotation (Euler XYZ radians, applied x then y then z like the reference's nodes) * scale.
mat4 trs(vec3 translation, vec3 euler_xyz = vec3(0.0f), vec3 scale = vec3(1.0f));

} // namespace ks::assetgen
