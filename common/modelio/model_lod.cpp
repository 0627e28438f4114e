#include "modelio/model_lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ks::modelio {

namespace {

// How much worse than the best order overdraw ordering may make the vertex cache (meshoptimizer's advice).
constexpr float kOverdrawThreshold = 1.05f;

void order_for_drawing(std::vector<std::uint32_t>& indices, const Vec3* positions, std::size_t vertex_count,
                       std::size_t stride) {
    if (indices.empty()) return;
    meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertex_count);
    meshopt_optimizeOverdraw(indices.data(), indices.data(), indices.size(), &positions->x, vertex_count,
                             stride, kOverdrawThreshold);
}

// Keeps only the vertices `mesh.indices` uses, in the order the triangles first use them.
void compact_vertices(ImportedMesh& mesh) {
    std::vector<std::uint32_t> remap(mesh.positions.size());
    const std::size_t kept = meshopt_optimizeVertexFetchRemap(remap.data(), mesh.indices.data(),
                                                              mesh.indices.size(), mesh.positions.size());
    meshopt_remapIndexBuffer(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(), remap.data());
    auto remap_stream = [&](auto& stream) {
        using T = typename std::decay_t<decltype(stream)>::value_type;
        std::vector<T> out(kept);
        meshopt_remapVertexBuffer(out.data(), stream.data(), stream.size(), sizeof(T), remap.data());
        stream = std::move(out);
    };
    remap_stream(mesh.positions);
    remap_stream(mesh.normals);
    remap_stream(mesh.uvs);
}

// One mesh simplified toward `ratio` of its triangles; `error` gets the deviation in model units. No
// triangles when the simplification bends its normals too far (simplify_triangles).
ImportedMesh simplify_mesh(const ImportedMesh& full, float ratio, float& error) {
    ImportedMesh out;
    out.material = full.material;
    error = 0.0f;
    if (full.indices.empty()) return out;
    VertexStreams streams;
    streams.positions = full.positions.data();
    streams.normals = full.normals.size() == full.positions.size() ? full.normals.data() : nullptr;
    streams.uvs = full.uvs.size() == full.positions.size() ? full.uvs.data() : nullptr;
    streams.count = full.positions.size();
    out.indices = simplify_triangles(streams, full.indices, ratio, error);
    if (out.indices.empty()) return out;
    out.positions = full.positions;
    out.normals = full.normals;
    out.uvs = full.uvs;
    compact_vertices(out);
    return out;
}

} // namespace

std::vector<std::uint32_t> simplify_triangles(const VertexStreams& vertices,
                                              std::span<const std::uint32_t> indices, float ratio,
                                              float& error) {
    error = 0.0f;
    if (indices.empty() || vertices.count == 0 || !vertices.positions) return {};
    const std::size_t target = std::max<std::size_t>(
        3, static_cast<std::size_t>(static_cast<float>(indices.size() / 3) * ratio) * 3);
    std::vector<std::uint32_t> out(indices.size());
    float relative = 0.0f;
    const float* positions = &vertices.positions->x;
    // The error limit is the whole model (1.0): the ratio decides, and the error says what it cost.
    const std::size_t count =
        meshopt_simplify(out.data(), indices.data(), indices.size(), positions, vertices.count,
                         vertices.position_stride, target, 1.0f, 0, &relative);
    const float scale = meshopt_simplifyScale(positions, vertices.count, vertices.position_stride);
    error = relative * scale;
    out.resize(count);
    // Samples may lie off the original surface by the deviation (meshoptimizer's is an estimate): search
    // twice as far, and a little more for a level that moved nothing.
    const LevelFidelity fidelity =
        measure_level_fidelity(vertices, indices, out, 2.0f * error + 1e-4f * scale, kLodMaxNormalBend);
    error = std::max({error, fidelity.texture_shift, fidelity.normal_extent});
    order_for_drawing(out, vertices.positions, vertices.count, vertices.position_stride);
    return out;
}

void optimize_draw_order(ImportedModel& model) {
    for (ImportedMesh& mesh : model.meshes)
        order_for_drawing(mesh.indices, mesh.positions.data(), mesh.positions.size(), sizeof(Vec3));
}

void build_lods(ImportedModel& model, std::span<const float> ratios) {
    model.lods.clear();
    std::size_t previous = model.triangle_count;
    float worst = 0.0f; // a coarser level is never reported better than a finer one
    for (float ratio : ratios) {
        ModelLod lod;
        lod.ratio = ratio;
        for (const ImportedMesh& mesh : model.meshes) {
            float error = 0.0f;
            ImportedMesh simple = simplify_mesh(mesh, ratio, error);
            lod.error = std::max(lod.error, error);
            lod.triangle_count += simple.indices.size() / 3;
            if (!simple.indices.empty()) lod.meshes.push_back(std::move(simple));
        }
        if (lod.triangle_count == 0 ||
            static_cast<float>(lod.triangle_count) > kLodMinSaving * static_cast<float>(previous))
            continue;
        worst = std::max(worst, lod.error);
        lod.error = worst;
        previous = lod.triangle_count;
        model.lods.push_back(std::move(lod));
    }
}

std::vector<float> lod_relative_errors(const ImportedModel& model) {
    const float size = glm::length(model.bounds.max - model.bounds.min);
    std::vector<float> errors{0.0f};
    for (const ModelLod& lod : model.lods) errors.push_back(size > 0.0f ? lod.error / size : 0.0f);
    return errors;
}

int pick_lod(std::span<const float> relative_errors, float pixels, int current, const LodPolicy& policy) {
    const int count = static_cast<int>(relative_errors.size());
    if (count == 0 || !std::isfinite(pixels) || pixels < 0.0f) return 0;
    auto error_pixels = [&](int level) { return relative_errors[static_cast<std::size_t>(level)] * pixels; };
    int level = std::clamp(current, 0, count - 1);
    while (level > 0 && error_pixels(level) > policy.max_error_pixels) --level;
    while (level + 1 < count && error_pixels(level + 1) <= policy.max_error_pixels * policy.hysteresis)
        ++level;
    return level;
}

} // namespace ks::modelio
