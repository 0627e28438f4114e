// modelio's levels of detail: meshoptimizer's simplified levels keep the model's bounds and reach the ratios
// asked for on a dense model, a small model gets none, and each instance's choice by its size on screen moves
// one way only inside the hysteresis band.
#include "modelio/model_lod.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::modelio;

namespace {

// A UV sphere of radius 1 with a ridge round its equator (so it is not trivially flat anywhere), one mesh.
ImportedModel ridged_sphere(int slices, int stacks) {
    ImportedModel model;
    ImportedMesh mesh;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j <= slices; ++j) {
            const float theta = kPi * static_cast<float>(i) / static_cast<float>(stacks);
            const float phi = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(slices);
            const float r = 1.0f + 0.1f * std::cos(8.0f * phi) * std::sin(theta);
            const Vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(n * r);
            mesh.normals.push_back(n);
            mesh.uvs.emplace_back(static_cast<float>(j) / slices, static_cast<float>(i) / stacks);
        }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const auto a = static_cast<std::uint32_t>(i * (slices + 1) + j), b = a + 1,
                       c = a + static_cast<std::uint32_t>(slices + 1), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    model.bounds = geometry::Aabb::empty();
    for (const Vec3& p : mesh.positions) model.bounds.grow(p);
    model.triangle_count = mesh.indices.size() / 3;
    model.meshes.push_back(std::move(mesh));
    return model;
}

} // namespace

TEST_CASE("modelio: levels of detail reach their ratios and keep the model's bounds") {
    ImportedModel model = ridged_sphere(96, 48);
    const std::size_t full = model.triangle_count;
    optimize_draw_order(model);
    CHECK(model.meshes[0].indices.size() / 3 == full); // the same triangles, reordered
    build_lods(model);
    REQUIRE(model.lods.size() == std::size(kLodRatios));
    const float size = glm::length(model.bounds.max - model.bounds.min);
    float previous_error = 0.0f;
    for (std::size_t i = 0; i < model.lods.size(); ++i) {
        const ModelLod& lod = model.lods[i];
        INFO("level ", i + 1, " ratio ", lod.ratio, " triangles ", lod.triangle_count, " error ", lod.error);
        const double reached = static_cast<double>(lod.triangle_count) / static_cast<double>(full);
        CHECK(reached <= lod.ratio * 1.05);
        CHECK(reached >= lod.ratio * 0.75);
        CHECK(lod.error > 0.0f);
        CHECK(lod.error >= previous_error);
        CHECK(lod.error < 0.1f * size);
        previous_error = lod.error;
        REQUIRE(lod.meshes.size() == 1);
        const ImportedMesh& mesh = lod.meshes[0];
        CHECK(mesh.positions.size() == mesh.normals.size());
        CHECK(mesh.positions.size() == mesh.uvs.size());
        CHECK(mesh.positions.size() < model.meshes[0].positions.size()); // compacted
        geometry::Aabb bounds = geometry::Aabb::empty();
        bool indices_inside = true;
        for (std::uint32_t index : mesh.indices) {
            indices_inside = indices_inside && index < mesh.positions.size();
            if (index < mesh.positions.size()) bounds.grow(mesh.positions[index]);
        }
        CHECK(indices_inside);
        for (int k = 0; k < 3; ++k) { // inside the model's bounds, and short of them by at most the error
            CHECK(bounds.min[k] >= model.bounds.min[k] - 1e-6f);
            CHECK(bounds.max[k] <= model.bounds.max[k] + 1e-6f);
            CHECK(bounds.min[k] <= model.bounds.min[k] + lod.error + 1e-6f);
            CHECK(bounds.max[k] >= model.bounds.max[k] - lod.error - 1e-6f);
        }
    }
}

TEST_CASE("modelio: a model too small to simplify gets no coarser level") {
    ImportedModel model = ridged_sphere(4, 2); // 16 triangles, mostly at the poles
    build_lods(model);
    for (const ModelLod& lod : model.lods) CHECK(lod.triangle_count <= kLodMinSaving * model.triangle_count);
    const std::vector<float> errors = lod_relative_errors(model);
    CHECK(errors.size() == model.lods.size() + 1);
    CHECK(errors[0] == 0.0f);
}

TEST_CASE("modelio: the level picked by size on screen, with hysteresis") {
    const std::vector<float> errors{0.0f, 0.01f, 0.04f}; // level 1 is fine under 100 px, level 2 under 25 px
    const LodPolicy policy{.max_error_pixels = 1.0f, .hysteresis = 0.8f};
    CHECK(pick_lod(errors, 1000.0f, 2, policy) == 0);
    CHECK(pick_lod(errors, 10.0f, 0, policy) == 2);
    CHECK(pick_lod(errors, 50.0f, 0, policy) == 1);
    // Shrinking through level 1's threshold (100 px): coarser only under 80 px.
    CHECK(pick_lod(errors, 90.0f, 0, policy) == 0);
    CHECK(pick_lod(errors, 79.0f, 0, policy) == 1);
    // Growing back: level 1 is kept up to 100 px, then the full model.
    CHECK(pick_lod(errors, 90.0f, 1, policy) == 1);
    CHECK(pick_lod(errors, 101.0f, 1, policy) == 0);
    // A size going back and forth inside the band does not switch.
    int level = 1;
    for (float pixels : {85.0f, 95.0f, 82.0f, 99.0f}) {
        level = pick_lod(errors, pixels, level, policy);
        CHECK(level == 1);
    }
    CHECK(pick_lod(errors, 5.0f, 7, policy) == 2); // a stale level is clamped
    CHECK(pick_lod(errors, std::nanf(""), 2, policy) == 0);
    CHECK(pick_lod({}, 5.0f, 0, policy) == 0);
}
