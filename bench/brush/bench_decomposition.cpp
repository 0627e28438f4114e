// ks_bench decomposition: the convex decomposition's cost against its error (brush/convex_decomposition.h),
// on closed shapes of known volume and on the shipped models, for several caps and voxel resolutions. The
// baselines in the same run: one Qhull hull of all the vertices (what "hull" collision takes) and the box.
// Error: the hulls' volume over the solid's (closed shapes; 0 % is exact), over the one hull's (how much of
// the single hull's overreach the decomposition removes), and the farthest a surface point lies outside
// every hull (should be none).
#include "bench_registry.h"
#include "brush/solid_meshes.h"
#include "physics/bench_util.h"

#include "brush/convex_decomposition.h"
#include "brush/convex_hull.h"
#include "modelio/model_files.h"
#include "modelio/model_import.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace ks::brush::bench {
namespace {

using physics::bench::cpu_seconds;
using physics::bench::fmt;

struct Shape {
    std::string name;
    SolidMesh mesh;
    bool closed = true;
};

std::vector<Shape> shapes() {
    std::vector<Shape> out{
        {"L", l_shape()},
        {"arch", arch()},
        {"table", table()},
        {"ring", ring(2.0, 0.5, 48, 16)},
        {"ball", ball(16, 32, 1.0)},
        {"ring, 98 304 tris", ring(2.0, 0.5, 384, 128)},
        {"thin L (0.01)", boxes({{{0, 0, 0}, {4, 0.01, 1}}, {{0, 0.01, 0}, {0.01, 4, 1}}})}};
    for (Shape& s : out)
        if (s.mesh.volume == 0.0) s.mesh.volume = std::abs(enclosed_volume(s.mesh));
    for (const char* file : {"archive_shelf.gltf", "control_panel.gltf"}) {
        auto model = modelio::import_cached(modelio::resolve_model_file(file));
        if (!model) continue;
        Shape s{file, {}, false};
        for (const modelio::ImportedMesh& m : (*model)->meshes) {
            const auto base = static_cast<std::uint32_t>(s.mesh.vertices.size());
            for (const Vec3& v : m.positions) s.mesh.vertices.push_back(DVec3(v));
            for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3)
                s.mesh.triangles.push_back(
                    {base + m.indices[i], base + m.indices[i + 1], base + m.indices[i + 2]});
        }
        out.push_back(std::move(s));
    }
    return out;
}

double one_hull_volume(const SolidMesh& m) {
    Result<double> v = convex_hull_volume(m.vertices);
    return v ? *v : 0.0;
}

int run(int argc, const char* const* argv) {
    const std::optional<bool> quick_given = ks::bench::quick_option(argc, argv);
    if (!quick_given) return 2;
    const bool quick = *quick_given;
    const std::vector<int> caps = quick ? std::vector<int>{8} : std::vector<int>{1, 2, 4, 8, 16};
    const std::vector<int> resolutions = quick ? std::vector<int>{48} : std::vector<int>{32, 48, 64};
    std::printf("load average %s; CPU time of one decomposition (best of %d)\n\n",
                physics::bench::load_average().c_str(), quick ? 1 : 2);
    std::printf("%-22s %5s %4s %9s %5s %5s %10s %10s %11s\n", "shape", "cap", "res", "ms", "hulls", "parts",
                "vs solid", "vs 1 hull", "outside");
    std::vector<std::string> csv;
    for (const Shape& s : shapes()) {
        const double one = one_hull_volume(s.mesh);
        if (s.closed)
            std::printf("%-22s %5s %4s %9s %5s %5s %9.1f%% %10s %11s\n", s.name.c_str(), "1 hull", "-", "-",
                        "1", "-", 100.0 * (one / s.mesh.volume - 1.0), "100.0%", "0");
        for (int resolution : resolutions)
            for (int cap : caps) {
                DecompositionOptions options;
                options.max_hulls = cap;
                options.resolution = resolution;
                double best = 1e300;
                Result<ConvexDecomposition> d = Error("not run");
                for (int rep = 0; rep < (quick ? 1 : 2); ++rep) {
                    const double start = cpu_seconds();
                    d = decompose_convex(s.mesh.vertices, s.mesh.triangles, options);
                    best = std::min(best, cpu_seconds() - start);
                }
                if (!d) {
                    std::printf("%-22s %5d %4d refused: %s\n", s.name.c_str(), cap, resolution,
                                d.error().str().c_str());
                    continue;
                }
                // The hulls' planes straight from Qhull: a dense model's hull may have more faces than a
                // brush takes (the model entity snaps those; the decomposition itself is measured here).
                HullPlanes hulls;
                for (const auto& points : d->hulls)
                    if (Result<Hull> h = convex_hull(points)) {
                        hulls.emplace_back();
                        for (const HullFace& f : h->faces) hulls.back().push_back(f.plane);
                    }
                Rng rng(11);
                const double outside = std::max(0.0, surface_outside(s.mesh, hulls, 20000, rng));
                const double vs_solid = s.closed ? 100.0 * (d->hull_volume / s.mesh.volume - 1.0) : 0.0;
                const double vs_one = one > 0 ? 100.0 * d->hull_volume / one : 0.0;
                std::printf("%-22s %5d %4d %9.2f %5zu %5d %9s %9.1f%% %11.2g\n", s.name.c_str(), cap,
                            resolution, best * 1e3, d->hulls.size(), d->parts,
                            s.closed ? fmt("%.1f%%", vs_solid).c_str() : "-", vs_one, outside);
                csv.push_back(s.name + "," + std::to_string(cap) + "," + std::to_string(resolution) + "," +
                              fmt("%.2f", best * 1e3) + "," + std::to_string(d->hulls.size()) + "," +
                              std::to_string(d->parts) + "," + (s.closed ? fmt("%.2f", vs_solid) : "") + "," +
                              fmt("%.2f", vs_one) + "," + fmt("%.3g", outside));
            }
    }
    if (quick) {
        std::printf("\n--quick: docs/bench/decomposition.csv left as it is\n");
        return 0;
    }
    physics::bench::write_csv(
        "decomposition",
        "shape,cap,resolution,ms,hulls,parts,excess_vs_solid_pct,volume_vs_one_hull_pct,max_outside", csv);
    return 0;
}

const ks::bench::Registrar
    registrar({"decomposition",
               "convex decomposition: ms per model against excess volume, by cap and resolution", run});

} // namespace
} // namespace ks::brush::bench
