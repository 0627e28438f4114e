#pragma once
// A model entity's file, placement and collision (docs/models.md): the one place that turns its properties
// into the imported mesh, the matrix that draws it, the brush the game and the navigation mesh collide with
// and the box the editor picks. Files are read through modelio's cache, so every user shares one import per
// file.
#include "brush/brush.h"
#include "level/entity_shapes.h"
#include "level/level.h"
#include "modelio/model_import.h"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace ks::level {

// The most corners a model's collision hull keeps: more cost every contact test and say little about a prop's
// shape. A hull with more is rebuilt from the vertices snapped to a coarser grid (model_collision).
inline constexpr std::size_t kMaxModelHullFaces = 256;

// The entity's model as read from its file (resolved by modelio::resolve_model_file). An Error for other
// types, a badly spelt name, and a file that is missing or cannot be read (naming the file).
Result<std::shared_ptr<const modelio::ImportedModel>> entity_model(const Entity& entity);

// Model space to world: the entity's frame (full yaw, pitch, roll) times its scale.
Mat4 model_matrix(const Entity& entity);

// The collision the entity chose, as convex brushes in the world: "box" the box around the scaled model,
// "hull" the convex hull of its scaled vertices, "hulls" at most `hulls` convex hulls from the model's
// convex decomposition (brush/convex_decomposition.h, made once per model file and cap in this process and
// scaled), each hull built by Qhull through brush::make_from_points; when one has more than
// kMaxModelHullFaces faces its points are snapped to a grid of 64, 32, 16 or 8 cells along its largest side,
// and the first hull under the cap is kept. Empty for "none" and "mesh" (model_mesh_collision). An Error when
// the model cannot be read or no hull can be built (flat models: choose "box" or "none").
Result<std::vector<brush::Brush>> model_collision(const Entity& entity);

// The most triangles a "mesh" collision takes (the import refuses more too: this says why for collision).
inline constexpr std::size_t kMaxModelMeshTriangles = 1'000'000;

// A model's triangles placed in the world (double): what "mesh" collision collides with and what the
// navigation mesh is built on (physics/triangle_mesh.h drops the zero-area ones).
struct CollisionMesh {
    std::vector<DVec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};
// The "mesh" collision of the entity: every triangle of every mesh of its model, scaled, turned and placed.
// nullopt for any other choice. An Error when the model cannot be read or has more than
// kMaxModelMeshTriangles triangles.
Result<std::optional<CollisionMesh>> model_mesh_collision(const Entity& entity);

// The box around the scaled model in the entity's frame; a unit cube standing on the position (the marker the
// renderer draws) when the file cannot be read.
PlacedShape model_bounding_shape(const Entity& entity);

} // namespace ks::level
