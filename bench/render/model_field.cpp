#include "render/model_field.h"

#include "modelio/model_files.h"
#include "modelio/model_lod.h"

#include <meshoptimizer.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace ks::bench {

namespace fs = std::filesystem;

namespace {

constexpr int kColumns = 25;
constexpr float kSpacing = 4.0f;
constexpr int kSlices = 96, kStacks = 48; // 9 216 triangles

// A rounded, ridged statue about 2 units tall, standing on its origin.
void write_statue(const fs::path& file) {
    std::ofstream out(file);
    for (int i = 0; i <= kStacks; ++i)
        for (int j = 0; j <= kSlices; ++j) {
            const float theta = kPi * static_cast<float>(i) / kStacks;
            const float phi = 2.0f * kPi * static_cast<float>(j) / kSlices;
            const float r =
                0.8f + 0.12f * std::cos(7.0f * phi) * std::sin(theta) + 0.05f * std::cos(5 * theta);
            const Vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            out << "v " << n.x * r << ' ' << 1.0f + n.y * r * 1.2f << ' ' << n.z * r << "\nvn " << n.x << ' '
                << n.y << ' ' << n.z << '\n';
        }
    for (int i = 0; i < kStacks; ++i)
        for (int j = 0; j < kSlices; ++j) {
            const int a = i * (kSlices + 1) + j + 1, b = a + 1, c = a + kSlices + 1, d = c + 1;
            out << "f " << a << "//" << a << ' ' << c << "//" << c << ' ' << b << "//" << b << "\nf " << b
                << "//" << b << ' ' << c << "//" << c << ' ' << d << "//" << d << '\n';
        }
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The statue's import, draw ordering and levels, timed, and each level's triangles and error.
void report_levels(const fs::path& file) {
    auto t0 = std::chrono::steady_clock::now();
    Result<modelio::ImportedModel> model = modelio::import_model(file);
    if (!model) {
        std::printf("statue: %s\n", model.error().str().c_str());
        return;
    }
    const double import_ms = ms_since(t0);
    // Vertices shaded per triangle with a 16-entry post-transform cache (meshoptimizer's model of a GPU's).
    auto acmr = [&] {
        const modelio::ImportedMesh& mesh = model->meshes.front();
        return meshopt_analyzeVertexCache(mesh.indices.data(), mesh.indices.size(), mesh.positions.size(), 16,
                                          0, 0)
            .acmr;
    };
    const float acmr_before = acmr();
    t0 = std::chrono::steady_clock::now();
    modelio::optimize_draw_order(*model);
    const double order_ms = ms_since(t0);
    std::printf("statue: vertices shaded per triangle (16-entry cache) %.2f as written, %.2f in draw order\n",
                acmr_before, acmr());
    t0 = std::chrono::steady_clock::now();
    modelio::build_lods(*model);
    const double lod_ms = ms_since(t0);
    const float size = glm::length(model->bounds.max - model->bounds.min);
    std::printf(
        "statue: %zu triangles, %.2f units across; import %.1f ms, draw order %.1f ms, levels %.1f ms\n",
        model->triangle_count, size, import_ms, order_ms, lod_ms);
    std::printf("| ratio | triangles | error (units) | error / size | full size on screen for 1 px |\n");
    for (const modelio::ModelLod& lod : model->lods)
        std::printf("| %.2f | %zu | %.4f | %.4f | %.0f px |\n", lod.ratio, lod.triangle_count, lod.error,
                    lod.error / size, lod.error > 0 ? size / lod.error : 0.0);
}

} // namespace

level::Level model_field_level(int count, const fs::path& scratch) {
    const fs::path models = scratch / "killswitch" / "models";
    fs::create_directories(models / "bench");
    setenv("XDG_DATA_HOME", scratch.c_str(), 1);
    write_statue(models / "bench" / "statue.obj");
    report_levels(models / "bench" / "statue.obj");

    level::Level level;
    level.name = "model field";
    level.player_start = {{0.0f, 0.0f, 2.0f}, 0.0f};
    auto& floor =
        level.add(level::EntityType::Floor, {0.0f, 0.0f, -100.0f}, "Ground").as<level::FloorProps>();
    floor.size = {240.0f, 240.0f};
    for (int i = 0; i < count; ++i) {
        const int row = i / kColumns, column = i % kColumns;
        const Vec3 at((static_cast<float>(column) - 0.5f * (kColumns - 1)) * kSpacing, 0.0f,
                      -6.0f - static_cast<float>(row) * kSpacing);
        level::Entity& e = level.add(level::EntityType::Model, at, "Model " + std::to_string(i + 1));
        e.rotation.x = static_cast<float>((i * 37) % 360);
        auto& props = e.as<level::ModelProps>();
        props.file = i % 5 == 4 ? "gas_cylinder.gltf" : "bench/statue.obj";
        props.collision.value = "none";
    }
    return level;
}

} // namespace ks::bench
