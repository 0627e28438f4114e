#include "brush/brush_validate.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace ks::brush {
namespace {

std::string number_text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string vector_text(const DVec3& v) {
    return "(" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + ")";
}

Result<void> check_numbers(const Face& face, std::size_t i) {
    const Plane& p = face.plane;
    if (!is_finite(p.normal))
        return Error("the plane normal " + vector_text(p.normal) + " is not a finite number",
                     face_location(i, ".plane.normal"), "give three finite numbers");
    if (!std::isfinite(p.distance))
        return Error("the plane distance " + number_text(p.distance) + " is not a finite number",
                     face_location(i, ".plane.distance"), "give a finite number");
    return check_attributes(face.attributes, i);
}

} // namespace

Result<void> check_rigid_motion(const glm::dmat3& rotation, const DVec3& translation) {
    const glm::dmat3 should_be_identity = glm::transpose(rotation) * rotation;
    double off = std::abs(glm::determinant(rotation) - 1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            off = std::max(off, std::abs(should_be_identity[c][r] - (c == r ? 1.0 : 0.0)));
    if (!(off < 1e-9) || !is_finite(translation))
        return Error("the motion is not a rotation and a finite translation", Location({}, 0, 0, "rotation"),
                     "give an orthonormal rotation matrix with determinant 1");
    return ok();
}

Result<void> check_attributes(const FaceAttributes& a, std::size_t i) {
    if (!std::isfinite(a.offset.x) || !std::isfinite(a.offset.y))
        return Error("the texture offset is not finite", face_location(i, ".offset"),
                     "give two finite numbers");
    if (!std::isfinite(a.rotation_degrees))
        return Error("the texture rotation is not finite", face_location(i, ".rotation"),
                     "give a finite angle in degrees");
    for (int k = 0; k < 2; ++k)
        if (!std::isfinite(a.scale[k]) || a.scale[k] == 0.0)
            return Error("the texture scale " + number_text(a.scale[k]) + " is zero or not finite",
                         face_location(i, k == 0 ? ".scale.x" : ".scale.y"),
                         "give a finite, non-zero scale (1 = one world unit per texture unit)");
    return ok();
}

namespace {

Result<void> normalize(Face& face, std::size_t i) {
    const double len = glm::length(face.plane.normal);
    if (!(len > 1e-150) || !std::isfinite(len))
        return Error("the plane normal " + vector_text(face.plane.normal) + " has no direction",
                     face_location(i, ".plane.normal"), "give the non-zero direction the face looks toward");
    // A normal already unit length within rounding is kept as it is: dividing it by its computed length
    // (1 +- an ulp or two) would move its last bits every time, so a brush read from a file, saved and
    // read again would not give the same planes (normalising is idempotent this way).
    if (std::abs(len - 1.0) > 4.0 * std::numeric_limits<double>::epsilon()) {
        face.plane.normal /= len;
        face.plane.distance /= len;
    }
    if (!std::isfinite(face.plane.distance) || std::abs(face.plane.distance) > 4.0 * kMaxCoordinate)
        return Error("the plane lies " + number_text(face.plane.distance) +
                         " units from the origin, beyond the world",
                     face_location(i, ".plane.distance"),
                     "keep brushes within +-" + number_text(kMaxCoordinate) + " units of the origin");
    return ok();
}

// Duplicate (same plane twice) and opposite (the same plane facing both ways: zero thickness, or facing
// away from each other with no room between) planes.
Result<void> check_pairs(std::vector<Face>& faces, RedundantPlanes redundant) {
    for (std::size_t i = 0; i < faces.size(); ++i) {
        for (std::size_t j = i + 1; j < faces.size(); ++j) {
            const Plane& a = faces[i].plane;
            const Plane& b = faces[j].plane;
            if (same_plane(a, b)) {
                if (redundant == RedundantPlanes::drop) {
                    faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(j--));
                    continue;
                }
                return Error("duplicates faces[" + std::to_string(i) + "] (the same plane)", face_location(j),
                             "remove one of the two faces");
            }
            if (same_direction(a.normal, -b.normal)) {
                const double gap = a.distance + b.distance; // the slab -b.distance <= n.x <= a.distance
                if (std::abs(gap) <= kOnPlaneEpsilon)
                    return Error("is faces[" + std::to_string(i) +
                                     "] turned around: the brush would have zero "
                                     "thickness",
                                 face_location(j), "move one of the two planes apart or remove one");
                if (gap < 0)
                    return Error("faces away from faces[" + std::to_string(i) +
                                     "] with no room between them: "
                                     "the brush is empty",
                                 face_location(j), "flip the normal of one of them or move them apart");
            }
        }
    }
    return ok();
}

// A brush needs normals spanning all three dimensions: if every normal is perpendicular to one direction
// the planes form an infinite prism along it; if all are parallel, a slab.
Result<void> check_spread(const std::vector<Face>& faces) {
    const DVec3 n0 = faces[0].plane.normal;
    std::size_t second = 0;
    for (std::size_t i = 1; i < faces.size() && !second; ++i)
        if (glm::length(glm::cross(n0, faces[i].plane.normal)) > 1e-9) second = i;
    if (!second)
        return Error("all " + std::to_string(faces.size()) +
                         " planes are parallel (all coplanar or stacked): they bound no volume",
                     face_location(0), "add planes facing other directions (a box needs six)");
    const DVec3 axis = glm::normalize(glm::cross(n0, faces[second].plane.normal));
    for (const Face& f : faces)
        if (std::abs(glm::dot(f.plane.normal, axis)) > 1e-9) return ok();
    return Error("the brush is unbounded along " + vector_text(axis) +
                     ": every plane contains that direction",
                 face_location(0), "add two planes closing it along that direction");
}

} // namespace

Location face_location(std::size_t index, const std::string& field) {
    return Location({}, 0, 0, "faces[" + std::to_string(index) + "]" + field);
}

Result<std::vector<Face>> validate_faces(std::vector<Face> faces, RedundantPlanes redundant) {
    if (faces.size() > kMaxFaces)
        return Error("a brush of " + std::to_string(faces.size()) + " planes is beyond the limit of " +
                         std::to_string(kMaxFaces),
                     Location({}, 0, 0, "faces"), "split the shape into several brushes");
    if (faces.size() < 4)
        return Error("a brush needs at least 4 planes, this one has " + std::to_string(faces.size()),
                     Location({}, 0, 0, "faces"), "add planes until they enclose a volume (a box has six)");
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (auto r = check_numbers(faces[i], i); !r) return r.error();
        if (auto r = normalize(faces[i], i); !r) return r.error();
    }
    if (auto r = check_pairs(faces, redundant); !r) return r.error();
    if (faces.size() < 4)
        return Error("only " + std::to_string(faces.size()) + " distinct planes remain",
                     Location({}, 0, 0, "faces"), "add planes until they enclose a volume");
    if (auto r = check_spread(faces); !r) return r.error();
    return faces;
}

} // namespace ks::brush
