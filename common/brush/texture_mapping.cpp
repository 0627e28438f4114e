#include "brush/texture_mapping.h"

#include "brush/brush_validate.h"

#include <cmath>

namespace ks::brush {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

} // namespace

TextureAxes base_texture_axes(const DVec3& normal) {
    DVec3 u;
    if (std::abs(normal.y) < 0.9999)
        u = glm::normalize(glm::cross(DVec3(0, 1, 0), normal));
    else
        u = glm::normalize(DVec3(1, 0, 0) - normal * normal.x);
    return {u, glm::cross(normal, u)};
}

TextureAxes texture_axes(const Face& face) {
    const TextureAxes base = base_texture_axes(face.plane.normal);
    const double a = face.attributes.rotation_degrees / kDegrees;
    const double c = std::cos(a), s = std::sin(a);
    return {c * base.u + s * base.v, -s * base.u + c * base.v};
}

glm::dvec2 texture_coordinates(const Face& face, const DVec3& world_point) {
    const TextureAxes axes = texture_axes(face);
    const FaceAttributes& at = face.attributes;
    return {glm::dot(world_point, axes.u) / at.scale.x + at.offset.x,
            glm::dot(world_point, axes.v) / at.scale.y + at.offset.y};
}

FaceAttributes locked_attributes(const Face& face, const glm::dmat3& rotation, const DVec3& translation) {
    const TextureAxes old_axes = texture_axes(face);
    const DVec3 u = rotation * old_axes.u, v = rotation * old_axes.v;
    const TextureAxes base = base_texture_axes(glm::normalize(rotation * face.plane.normal));
    FaceAttributes out = face.attributes;
    // The turned axes are the new base axes turned by some angle about the new normal: that angle.
    out.rotation_degrees = std::atan2(glm::dot(u, base.v), glm::dot(u, base.u)) * kDegrees;
    // s'(R p + t) = dot(R p + t, R u) / sx + o' = s(p) when o' = o - dot(t, R u) / sx.
    out.offset.x = face.attributes.offset.x - glm::dot(translation, u) / face.attributes.scale.x;
    out.offset.y = face.attributes.offset.y - glm::dot(translation, v) / face.attributes.scale.y;
    return out;
}

Result<Brush> transformed(const Brush& brush, const glm::dmat3& rotation, const DVec3& translation,
                          TextureLock lock) {
    if (auto rigid = check_rigid_motion(rotation, translation); !rigid) return rigid.error();
    // The anchor moves with the brush, rounded to whole units; the anchored planes absorb the remainder, a
    // small number, so a brush moved by grid steps keeps its planes' precision.
    const DVec3 moved_anchor = rotation * brush.anchor() + translation;
    const DVec3 anchor = glm::round(moved_anchor);
    std::vector<Face> faces = brush.anchored_faces();
    for (std::size_t i = 0; i < faces.size(); ++i) {
        Face& f = faces[i];
        f.plane.normal = glm::normalize(rotation * f.plane.normal);
        f.plane.distance += glm::dot(f.plane.normal, moved_anchor - anchor);
        if (lock == TextureLock::on)
            f.attributes = locked_attributes(brush.faces()[i], rotation, translation);
    }
    return Brush::from_anchored_faces(anchor, std::move(faces));
}

Result<Brush> placed(const Brush& brush, const glm::dmat3& rotation, const DVec3& translation) {
    if (auto rigid = check_rigid_motion(rotation, translation); !rigid) return rigid.error();
    std::vector<FaceAttributes> locked;
    locked.reserve(brush.faces().size());
    for (const Face& face : brush.faces()) locked.push_back(locked_attributes(face, rotation, translation));
    return brush.carried(rotation, translation, std::move(locked));
}

Result<Brush> translated(const Brush& brush, const DVec3& delta, TextureLock lock) {
    return transformed(brush, glm::dmat3(1.0), delta, lock);
}

} // namespace ks::brush
