#pragma once
// Texture coordinates of brush faces, and texture lock.
//
// Projection: onto the face's own plane (not onto the dominant axis plane as in the Quake "standard"
// format). Each normal has a fixed pair of unit axes in its plane (base_texture_axes); the face's rotation
// turns them about the normal, its scale divides and its offset adds. Why: a sloped face is not stretched,
// and since the axes of the turned face and the turned axes of the face differ only by a turn about the
// normal, every rigid motion (translation and rotation) is represented exactly, so texture lock is exact
// rather than approximate; the dominant-axis projection cannot keep a mapping through a turn that is not
// about a world axis.
#include "brush/brush.h"

namespace ks::brush {

struct TextureAxes {
    DVec3 u, v; // unit, in the face plane, cross(u, v) == normal
};

// Walls (normal not near +-y): u is horizontal (cross(+y, normal)) and v points up. Floors and ceilings
// (|normal.y| > 0.9999): u follows +x projected on the plane.
TextureAxes base_texture_axes(const DVec3& normal);
// The base axes turned by the face's rotation.
TextureAxes texture_axes(const Face& face);
// (dot(p, u) / scale.x + offset.x, dot(p, v) / scale.y + offset.y).
glm::dvec2 texture_coordinates(const Face& face, const DVec3& world_point);

// The attributes that keep `face`'s mapping on the world after the motion p -> rotation * p + translation:
// every point keeps its texture coordinates. `rotation` must be a rotation matrix.
FaceAttributes locked_attributes(const Face& face, const glm::dmat3& rotation, const DVec3& translation);

enum class TextureLock { off, on };

// The brush moved by p -> rotation * p + translation (a proper rotation: orthonormal, determinant +1, else
// refused). With the lock on, every face keeps its world mapping; off, attributes stay as they are (the
// texture stays put in the face's frame and slides over the world).
Result<Brush> transformed(const Brush& brush, const glm::dmat3& rotation, const DVec3& translation,
                          TextureLock lock = TextureLock::on);
// The same result as transformed(brush, rotation, translation, TextureLock::on) but with the geometry
// carried through the motion (Brush::carried) instead of derived again: for placing a stored brush in the
// world once, as the level does for each brush entity (see Brush::carried for the error it adds).
Result<Brush> placed(const Brush& brush, const glm::dmat3& rotation, const DVec3& translation);
Result<Brush> translated(const Brush& brush, const DVec3& delta, TextureLock lock = TextureLock::on);

} // namespace ks::brush
