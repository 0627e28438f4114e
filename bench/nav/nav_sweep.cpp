#include "nav/nav_sweep.h"

#include "nav/nav_mesh.h"
#include "nav/visibility_reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace ks::bench::nav_sweep {
namespace {

constexpr float kField = 60.0f, kWallHeight = 4.0f, kThick = 0.5f;

void add_box(level::Level& lv, Vec2 centre, Vec2 size, const char* name) {
    auto& w = lv.add(level::EntityType::Wall, Vec3(centre.x, 0.0f, centre.y), name);
    w.as<level::WallProps>().size = Vec3(size.x, kWallHeight, size.y);
}

void add_floor(level::Level& lv, Vec2 centre, Vec2 size) {
    auto& f = lv.add(level::EntityType::Floor, Vec3(centre.x, 0.0f, centre.y), "floor");
    f.as<level::FloorProps>().size = size;
}

double build_ms(const level::Level& lv, const nav::NavSettings& s, std::unique_ptr<nav::NavMesh>& out) {
    const auto t0 = std::chrono::steady_clock::now();
    auto mesh = nav::NavMesh::build(lv, s);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!mesh) {
        std::printf("  build failed: %s\n", mesh.error().str().c_str());
        out.reset();
        return ms;
    }
    out = std::move(mesh.value());
    return ms;
}

} // namespace

ObstacleField make_obstacle_field(int obstacle_count, int query_count, std::uint64_t seed) {
    using nav_reference::Rect;
    const float r = level::kRobotRadius, half = kField * 0.5f;
    const float spacing = 2.0f * r + 2.0f; // every gap stays wider than the coarsest mesh can close
    ObstacleField field;
    field.level.name = "nav bench: obstacle field";
    add_floor(field.level, Vec2(0.0f), Vec2(kField + 2.0f));
    add_box(field.level, Vec2(0, -half - kThick * 0.5f), Vec2(kField + 2 * kThick, kThick), "outer wall");
    add_box(field.level, Vec2(0, half + kThick * 0.5f), Vec2(kField + 2 * kThick, kThick), "outer wall");
    add_box(field.level, Vec2(-half - kThick * 0.5f, 0), Vec2(kThick, kField), "outer wall");
    add_box(field.level, Vec2(half + kThick * 0.5f, 0), Vec2(kThick, kField), "outer wall");
    Rng rng(seed);
    std::vector<Rect> rects;
    const Rect inner{Vec2(-half), Vec2(half)};
    for (int tries = 0; static_cast<int>(rects.size()) < obstacle_count && tries < 10000; ++tries) {
        const Vec2 size(rng.uniform(1.0f, 6.0f), rng.uniform(1.0f, 6.0f));
        const Vec2 centre(rng.uniform(-half + 6, half - 6), rng.uniform(-half + 6, half - 6));
        const Rect rect{centre - size * 0.5f, centre + size * 0.5f};
        const Rect grown{rect.min - Vec2(spacing), rect.max + Vec2(spacing)};
        bool clear = true;
        for (const Rect& o : rects)
            clear = clear && (grown.max.x < o.min.x || o.max.x < grown.min.x || grown.max.y < o.min.y ||
                              o.max.y < grown.min.y);
        if (!clear) continue;
        rects.push_back(rect);
        add_box(field.level, centre, size, "obstacle");
    }
    const nav_reference::VisibilityGraph graph(rects, inner, r);
    const float margin = r + 0.8f; // clear of the coarsest mesh's erosion, so both ends are on it
    const nav_reference::VisibilityGraph clearance(rects, inner, margin);
    while (static_cast<int>(field.queries.size()) < query_count) {
        const Vec2 a(rng.uniform(-half, half), rng.uniform(-half, half));
        const Vec2 b(rng.uniform(-half, half), rng.uniform(-half, half));
        if (!clearance.free(a) || !clearance.free(b) || glm::length(b - a) < 10.0f) continue;
        const float exact = graph.shortest(a, b);
        if (!std::isfinite(exact)) continue;
        field.queries.push_back({Vec3(a.x, 0, a.y), Vec3(b.x, 0, b.y), exact});
    }
    return field;
}

GapStrips make_gap_strips(float r, std::uint64_t seed) {
    constexpr float kStrip = 8.0f, kLength = 20.0f;
    GapStrips out;
    out.level.name = "nav bench: gap strips";
    Rng rng(seed);
    std::vector<float> widths;
    for (float d = -0.35f; d < 1.2f; d += 0.1f) // never exactly 2r: the exact rule is clear either side
        for (int k = 0; k < 3; ++k) widths.push_back(2.0f * r + d);
    const float total = kStrip * static_cast<float>(widths.size());
    add_floor(out.level, Vec2(total * 0.5f, 0.0f), Vec2(total, kLength));
    for (size_t i = 0; i <= widths.size(); ++i)
        add_box(out.level, Vec2(static_cast<float>(i) * kStrip, 0.0f), Vec2(kThick, kLength), "strip wall");
    for (size_t i = 0; i < widths.size(); ++i) {
        const float x0 = static_cast<float>(i) * kStrip + kThick * 0.5f, x1 = x0 + kStrip - kThick;
        const float w = widths[i];
        const float start = rng.uniform(x0 + 1.0f, x1 - 1.0f - w);
        add_box(out.level, Vec2((x0 + start) * 0.5f, 0.0f), Vec2(start - x0, kThick), "gap wall");
        add_box(out.level, Vec2((start + w + x1) * 0.5f, 0.0f), Vec2(x1 - start - w, kThick), "gap wall");
        const float mid = (x0 + x1) * 0.5f;
        out.gaps.push_back({w, Vec3(mid, 0, 5.0f), Vec3(mid, 0, -5.0f)});
    }
    return out;
}

int tile_cells_for(float cell_size, const nav::NavSettings& base) {
    const float tile_world = static_cast<float>(base.tile_size_cells) * base.cell_size;
    nav::NavSettings s = base;
    s.cell_size = cell_size;
    const int minimum = 2 * (nav::agent_cells(s).radius + 3);
    return std::max(minimum, static_cast<int>(std::lround(tile_world / cell_size)));
}

SweepRow measure_cell_size(float cell_size, const nav::NavSettings& base, const ObstacleField& field,
                           const GapStrips& gaps, const level::Level& main_level) {
    nav::NavSettings s = base;
    s.cell_size = cell_size;
    s.tile_size_cells = tile_cells_for(cell_size, base);
    SweepRow row;
    row.cell_size = cell_size;
    std::unique_ptr<nav::NavMesh> mesh;
    row.build_main_ms = build_ms(main_level, s, mesh);
    row.build_field_ms = build_ms(field.level, s, mesh);
    if (mesh) {
        double sum = 0.0;
        for (const FieldQuery& q : field.queries) {
            ++row.paths;
            const auto length = mesh->path_length(q.from, q.to);
            if (!length) {
                ++row.unreached;
                continue;
            }
            const double error = 100.0 * (*length - q.exact) / q.exact;
            sum += std::abs(error);
            row.max_error_pct = std::max(row.max_error_pct, std::abs(error));
        }
        const int reached = row.paths - row.unreached;
        row.mean_error_pct = reached > 0 ? sum / reached : 0.0;
    }
    (void)build_ms(gaps.level, s, mesh);
    if (mesh)
        for (const Gap& g : gaps.gaps) {
            const bool exact_open = g.width >= 2.0f * s.agent_radius;
            const bool mesh_open = mesh->reachable(g.near, g.far);
            if (exact_open) {
                ++row.gaps_open;
                row.wrongly_closed += mesh_open ? 0 : 1;
            } else {
                ++row.gaps_closed;
                row.wrongly_opened += mesh_open ? 1 : 0;
            }
        }
    return row;
}

} // namespace ks::bench::nav_sweep
