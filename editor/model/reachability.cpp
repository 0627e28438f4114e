#include "model/reachability.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>

namespace ks::editor {
namespace {
using level::Entity;
using level::EntityType;

constexpr int kMaxSurfaces = 4; // walkable layers per cell kept for the search (ground, platform, tread, ...)
constexpr int kMaxFound = 8;    // surfaces gathered per cell before buried ones are dropped

struct Solid {
    geometry::Obb box;
    geometry::Aabb bounds;
    // Floor slabs only matter as headroom (a low ceiling or an overhang above the node): they are tested
    // against the body's centre column. Their edges are not walls: climbing onto a slab is the step rule's
    // business, and where a stair meets a platform the slab's edge hides inside the stair's wedge.
    bool slab = false;
};
constexpr float kSlabColumn = 0.1f; // half width of the headroom column

bool blocks_walking(EntityType t) {
    switch (t) {
    case EntityType::Wall:
    case EntityType::Floor: // slabs: a low ceiling or platform edge the body cannot pass through
    case EntityType::FloorLight:
    case EntityType::GasCylinder:
    case EntityType::ControlPanel:
        return true;
    default:
        return false; // doors open, robots and pickups move or vanish, stairs are walked on
    }
}
} // namespace

WalkGridStats walk_to_control_panel(const level::Level& level, const ValidationOptions& o) {
    WalkGridStats stats;
    const Entity* panel = nullptr;
    struct SupportBox {
        const Entity* entity;
        geometry::Obb box;
    };
    std::vector<SupportBox> supports;
    std::vector<Solid> solids;
    geometry::Aabb area{Vec3(3e38f), Vec3(-3e38f)};
    for (const auto& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation)) continue;
        if (!panel && e.type() == EntityType::ControlPanel) panel = &e;
        const geometry::Obb box = entity_obb(e);
        if (blocks_walking(e.type())) solids.push_back({box, box.aabb(), e.type() == EntityType::Floor});
        const auto* floor = e.try_as<level::FloorProps>();
        if (e.type() == EntityType::Stair || (floor && !floor->ceiling)) {
            supports.push_back({&e, box});
            const geometry::Aabb b = box.aabb();
            area.min = glm::min(area.min, b.min);
            area.max = glm::max(area.max, b.max);
        }
    }
    if (!panel || supports.empty() || !is_finite(level.player_start.position)) return stats;

    const auto& ch = o.character;
    float cell = std::max(o.walk_cell, 0.05f);
    const float width = area.max.x - area.min.x, depth = area.max.z - area.min.z;
    while ((width / cell + 1) * (depth / cell + 1) > 2e6f) cell *= 2;
    const int cols = static_cast<int>(std::ceil(width / cell)) + 1;
    const int rows = static_cast<int>(std::ceil(depth / cell)) + 1;
    stats.columns = cols, stats.rows = rows, stats.cell = cell;

    const size_t cells = static_cast<size_t>(cols) * static_cast<size_t>(rows);
    std::vector<std::array<float, kMaxSurfaces>> heights(cells);
    std::vector<std::uint8_t> layer_count(cells, 0), open(cells * kMaxSurfaces, 0);
    auto centre = [&](int c, int r) {
        return Vec2(area.min.x + (static_cast<float>(c) + 0.5f) * cell,
                    area.min.z + (static_cast<float>(r) + 0.5f) * cell);
    };

    // Pass 1: the walkable surfaces of every cell (each support only over the cells its bounds cover).
    std::vector<std::array<float, kMaxFound>> found(cells);
    std::vector<std::uint8_t> found_count(cells, 0);
    // Per found surface: the stair's base height, or NaN for a floor.
    std::vector<float> stair_base(cells * kMaxFound, 0.0f);
    auto cell_range = [&](const geometry::Aabb& b, float grow, int& c0, int& c1, int& r0, int& r1) {
        c0 = std::max(0, static_cast<int>(std::floor((b.min.x - grow - area.min.x) / cell)));
        c1 = std::min(cols - 1, static_cast<int>(std::floor((b.max.x + grow - area.min.x) / cell)));
        r0 = std::max(0, static_cast<int>(std::floor((b.min.z - grow - area.min.z) / cell)));
        r1 = std::min(rows - 1, static_cast<int>(std::floor((b.max.z + grow - area.min.z) / cell)));
    };
    for (const auto& s : supports) {
        int c0, c1, r0, r1;
        cell_range(s.box.aabb(), 0.0f, c0, c1, r0, r1);
        const bool stair = s.entity->type() == EntityType::Stair;
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const Vec2 p = centre(c, r);
                auto h = surface_height_at(*s.entity, s.box, p.x, p.y, /*stair_as_ramp=*/true);
                const size_t index = static_cast<size_t>(r) * cols + c;
                if (!h || found_count[index] == kMaxFound) continue;
                stair_base[index * kMaxFound + found_count[index]] =
                    stair ? s.entity->position.y : std::nanf("");
                found[index][found_count[index]++] = *h;
            }
    }
    for (size_t index = 0; index < cells; ++index) {
        const int n_found = std::min<int>(found_count[index], kMaxFound);
        if (n_found == 0) continue;
        // A floor surface under a stair's tread is buried inside the stair's solid.
        std::array<float, kMaxFound> kept{};
        int n = 0;
        for (int i = 0; i < n_found; ++i) {
            bool buried = false;
            const float h = found[index][i];
            if (std::isnan(stair_base[index * kMaxFound + i]))
                for (int j = 0; j < n_found; ++j) {
                    const float base = stair_base[index * kMaxFound + j];
                    if (!std::isnan(base) && base <= h + 1e-3f && found[index][j] > h + 1e-3f) {
                        buried = true;
                        break;
                    }
                }
            if (!buried) kept[n++] = found[index][i];
        }
        // At most kMaxFound values: insertion sort, then drop near-duplicates (two floors flush at a seam).
        for (int i = 1; i < n; ++i)
            for (int j = i; j > 0 && kept[j] < kept[j - 1]; --j) std::swap(kept[j], kept[j - 1]);
        int unique = 0;
        for (int i = 0; i < n; ++i)
            if (unique == 0 || std::abs(kept[i] - kept[unique - 1]) >= 1e-3f) kept[unique++] = kept[i];
        n = unique;
        const int first = std::max(0, n - kMaxSurfaces);
        for (int k = first; k < n; ++k) {
            heights[index][k - first] = kept[k];
            open[index * kMaxSurfaces + (k - first)] = 1;
        }
        layer_count[index] = static_cast<std::uint8_t>(n - first);
    }

    // Pass 2: close every node where a solid intersects the body (from step height to full height),
    // visiting only the cells each solid's bounds (grown by the body radius) can reach.
    const float body_half_height = (ch.height - ch.step_height) / 2;
    for (const Solid& s : solids) {
        int c0, c1, r0, r1;
        const float reach = s.slab ? kSlabColumn : ch.radius;
        cell_range(s.bounds, reach, c0, c1, r0, r1);
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const size_t index = static_cast<size_t>(r) * cols + c;
                for (int k = 0; k < layer_count[index]; ++k) {
                    std::uint8_t& node = open[index * kMaxSurfaces + k];
                    const float h = heights[index][k];
                    if (!node || s.bounds.min.y >= h + ch.height || s.bounds.max.y <= h + ch.step_height)
                        continue;
                    const Vec2 p = centre(c, r);
                    geometry::Obb body;
                    body.center = {p.x, h + ch.step_height + body_half_height, p.y};
                    body.half = {reach, body_half_height, reach};
                    if (geometry::obb_overlap(body, s.box).overlapping) node = 0;
                }
            }
    }
    for (size_t i = 0; i < open.size(); ++i) stats.open_nodes += open[i];

    // Start: the highest surface under the player start's feet.
    const Vec3 start = level.player_start.position;
    const int sc = static_cast<int>(std::floor((start.x - area.min.x) / cell));
    const int sr = static_cast<int>(std::floor((start.z - area.min.z) / cell));
    if (sc < 0 || sr < 0 || sc >= cols || sr >= rows) return stats;
    const size_t start_cell = static_cast<size_t>(sr) * cols + sc;
    int start_layer = -1;
    for (int k = 0; k < layer_count[start_cell]; ++k)
        if (heights[start_cell][k] <= start.y + o.support_tolerance + ch.step_height) start_layer = k;
    if (start_layer < 0) return stats;
    stats.decided = true;

    // Reached: the body touches the panel (its box grown by the body radius and a little reach).
    geometry::Obb goal = entity_obb(*panel);
    goal.half += Vec3(ch.radius + cell + 0.25f, 0.5f, ch.radius + cell + 0.25f);
    std::vector<std::uint8_t> seen(cells * kMaxSurfaces, 0);
    std::deque<size_t> queue{start_cell * kMaxSurfaces + static_cast<size_t>(start_layer)};
    seen[queue.front()] = 1;
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    while (!queue.empty()) {
        const size_t node = queue.front();
        queue.pop_front();
        ++stats.visited_nodes;
        const size_t index = node / kMaxSurfaces;
        const float h = heights[index][node % kMaxSurfaces];
        const int c = static_cast<int>(index % static_cast<size_t>(cols)),
                  r = static_cast<int>(index / static_cast<size_t>(cols));
        const Vec2 p = centre(c, r);
        if (goal.contains({p.x, h + ch.height / 2, p.y})) {
            stats.reachable = true;
            break;
        }
        for (int d = 0; d < 4; ++d) {
            const int nc = c + dc[d], nr = r + dr[d];
            if (nc < 0 || nr < 0 || nc >= cols || nr >= rows) continue;
            const size_t ni = static_cast<size_t>(nr) * cols + nc;
            // Step up at most step_height; otherwise land on the highest surface below (a drop).
            int target = -1;
            for (int k = 0; k < layer_count[ni]; ++k)
                if (heights[ni][k] <= h + ch.step_height + 1e-3f) target = k;
            if (target < 0) continue;
            const size_t next = ni * kMaxSurfaces + static_cast<size_t>(target);
            if (seen[next] || !open[next]) continue;
            seen[next] = 1;
            queue.push_back(next);
        }
    }
    return stats;
}

std::uint64_t walk_fingerprint(const level::Level& level, const ValidationOptions& o) {
    // FNV-1a over the bytes of the values the check reads.
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    };
    auto mix_value = [&mix](const auto& v) { mix(&v, sizeof v); };
    mix_value(o.walk_cell), mix_value(o.support_tolerance);
    mix_value(o.character.radius), mix_value(o.character.height), mix_value(o.character.step_height);
    mix_value(level.player_start.position);
    for (const auto& e : level.entities) {
        const EntityType t = e.type();
        const auto* floor = e.try_as<level::FloorProps>();
        if (!blocks_walking(t) && t != EntityType::Stair && t != EntityType::ControlPanel) continue;
        const geometry::Obb box = entity_obb(e);
        const int type = static_cast<int>(t), ceiling = floor && floor->ceiling ? 1 : 0;
        mix_value(e.id), mix_value(type), mix_value(ceiling), mix_value(e.position), mix_value(e.rotation);
        mix_value(box.center), mix_value(box.axes), mix_value(box.half);
    }
    return h;
}

void check_reachability(const level::Level& level, const ValidationOptions& options,
                        std::vector<Issue>& out) {
    const WalkGridStats stats = walk_to_control_panel(level, options);
    if (!stats.decided || stats.reachable) return;
    int panel_id = 0;
    for (const auto& e : level.entities)
        if (e.type() == EntityType::ControlPanel) {
            panel_id = e.id;
            break;
        }
    out.push_back(
        {Rule::Reachability,
         IssueSeverity::Warning,
         panel_id,
         "control panel " + std::to_string(panel_id) +
             " cannot be reached on foot from the player start (doors count as open, jumps are not counted)",
         {}});
}

} // namespace ks::editor
