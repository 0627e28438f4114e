#pragma once
// Levels of detail of a designer's model (docs/models.md): meshoptimizer simplifies every mesh to a few
// fractions of its triangles once, when the file is imported (import_cached keeps them with the import), and
// each drawn instance picks the coarsest level whose error would cover at most about a pixel on screen, with
// a band of hysteresis so an instance at a threshold does not switch every frame.
#include "modelio/lod_fidelity.h"
#include "modelio/model_import.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::modelio {

// The fractions of the triangles the coarser levels aim for (level 0 is the model itself).
inline constexpr float kLodRatios[] = {0.5f, 0.25f, 0.1f};
// Shading normals that bend by more than this (radians) count as an error as wide as the region they bend
// over (LevelFidelity::normal_extent).
inline constexpr float kLodMaxNormalBend = 0.26f;
// A level that keeps more than this fraction of the previous level's triangles is not kept: it would cost a
// draw's worth of memory for no saving (a 12-triangle crate has no coarser levels).
inline constexpr float kLodMinSaving = 0.85f;

// One triangle list simplified toward `ratio` of its triangles by meshopt_simplify (vertices it does not
// collapse stay where they were; attribute seams are kept), then put in vertex-cache and overdraw order.
// `vertices` is read in place (an interleaved buffer or separate arrays). `error`, in the positions' units,
// is the larger of the surface's deviation (meshoptimizer's) and how far the texture slid along it
// (lod_fidelity.h: meshoptimizer 0.18 sees neither texture coordinates nor normals), or the width of any
// region whose normals bend by more than kLodMaxNormalBend. The indices refer to the same vertices.
std::vector<std::uint32_t> simplify_triangles(const VertexStreams& vertices,
                                              std::span<const std::uint32_t> indices, float ratio,
                                              float& error);

// Orders every mesh's triangles for the vertex cache and then for overdraw (meshopt_optimizeVertexCache,
// meshopt_optimizeOverdraw), in place: the same triangles, drawn in a cheaper order.
void optimize_draw_order(ImportedModel& model);

// Fills model.lods, one level per ratio (finest first) that saves triangles (kLodMinSaving), each simplified
// from the full meshes by meshopt_simplify (which keeps the vertices it does not collapse where they were, so
// a level's bounds lie inside the model's), put in draw order and its vertices compacted.
void build_lods(ImportedModel& model, std::span<const float> ratios = kLodRatios);

// How an instance chooses its level.
struct LodPolicy {
    float max_error_pixels = 1.0f; // the most a level's error may cover on screen
    float hysteresis = 0.8f;       // going coarser needs the error under max_error_pixels * hysteresis
};

// Each level's error as a fraction of the model's size (its bounds' diagonal), level 0 first (0): what
// pick_lod compares with the size on screen.
std::vector<float> lod_relative_errors(const ImportedModel& model);

// The level to draw for an instance whose bounds' diagonal covers `pixels` on screen, given the level it was
// drawn at last (`current`, clamped to the levels there are): the coarsest level whose error (relative error
// times `pixels`) is at most policy.max_error_pixels. A finer level is taken as soon as the current one's
// error is over the limit; a coarser one only when its error is under the limit times policy.hysteresis.
int pick_lod(std::span<const float> relative_errors, float pixels, int current, const LodPolicy& policy = {});

} // namespace ks::modelio
