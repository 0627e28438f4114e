#pragma once
// A brush face: its plane and its surface attributes (material and texture mapping; see texture_mapping.h).
#include "brush/plane.h"

#include <string>

namespace ks::brush {

struct FaceAttributes {
    std::string material;
    glm::dvec2 offset{0.0};      // texture units added after scaling
    glm::dvec2 scale{1.0};       // world units per texture unit along u and v; never 0
    double rotation_degrees = 0; // turn of the texture axes about the face normal, counter-clockwise

    bool operator==(const FaceAttributes&) const = default;
};

struct Face {
    Plane plane;
    FaceAttributes attributes;

    bool operator==(const Face&) const = default;
};

} // namespace ks::brush
