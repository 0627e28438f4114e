#pragma once
// The checks on a brush's input planes that need no derivation: counts, finite numbers, texture scales,
// duplicate and opposite planes, all planes parallel or all containing one direction (unbounded).
#include "brush/brush.h"

namespace ks::brush {

// Returns the faces with unit normals (a plane given with a longer normal is scaled, distance too). In
// `drop` mode a duplicate of an earlier face is removed instead of refused.
Result<std::vector<Face>> validate_faces(std::vector<Face> faces, RedundantPlanes redundant);

// A face's texture attributes: finite offset and rotation, finite non-zero scales (`index` names the face).
Result<void> check_attributes(const FaceAttributes& attributes, std::size_t index);

// A proper rotation (orthonormal within 1e-9, determinant +1) and a finite translation.
Result<void> check_rigid_motion(const glm::dmat3& rotation, const DVec3& translation);

// "faces[i]" followed by `field` (".plane.normal"): the path every brush error uses.
Location face_location(std::size_t index, const std::string& field = {});

} // namespace ks::brush
