#include "physics/brush_shape.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {

Polyhedron brush_polyhedron(const brush::Brush& b, const DVec3& origin) {
    Polyhedron p;
    p.vertices.reserve(b.vertices().size());
    for (const DVec3& v : b.vertices()) p.vertices.push_back(Vec3(v - origin));
    const auto& faces = b.faces();
    const auto& polygons = b.polygons();
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        Polyhedron::Face f;
        f.first = static_cast<std::uint16_t>(p.face_vertices.size());
        f.count = static_cast<std::uint16_t>(polygons[i].size());
        DVec3 centre(0.0);
        for (int v : polygons[i]) {
            p.face_vertices.push_back(static_cast<std::uint16_t>(v));
            centre += b.vertices()[v] - origin;
        }
        centre /= static_cast<double>(polygons[i].size());
        f.normal = Vec3(faces[i].plane.normal);
        // The plane through the face's centre with the rounded normal: the normal's rounding then tilts the
        // face about its own centre (error: its size times 6e-8), not about the far-away origin.
        f.offset = static_cast<float>(glm::dot(DVec3(f.normal), centre));
        f.centre = Vec3(centre);
        p.faces.push_back(f);
    }
    p.bounds = geometry::Aabb::empty();
    for (const Vec3& v : p.vertices) p.bounds.grow(v);
    derive_edges(p);
    return p;
}

BrushBody brush_body(const brush::Brush& b) {
    BrushBody body;
    body.transform.position = Vec3((b.bounds_min() + b.bounds_max()) * 0.5);
    Polyhedron p = brush_polyhedron(b, exact_double(body.transform.position));
    body.shape.kind = ShapeKind::Hull;
    // The local box is centred on the position only to float rounding: the half extents cover both sides,
    // so world bounds stay conservative.
    body.shape.half_extents = glm::max(glm::abs(p.bounds.min), glm::abs(p.bounds.max));
    body.shape.polyhedron = std::make_shared<const Polyhedron>(std::move(p));
    return body;
}

} // namespace ks::physics
