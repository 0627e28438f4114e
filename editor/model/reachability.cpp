#include "model/reachability.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <optional>

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

struct SupportBox {
    const Entity* entity;
    geometry::Obb box;
};

// What the walk reads from the level: the goal, what the body stands on and what it bumps into.
struct WalkScene {
    const Entity* panel = nullptr;
    std::vector<SupportBox> supports;
    std::vector<Solid> solids;
    geometry::Aabb area{Vec3(3e38f), Vec3(-3e38f)}; // the supports' extent, which the grid covers
};

WalkScene gather_scene(const level::Level& level) {
    WalkScene scene;
    for (const auto& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation)) continue;
        if (!scene.panel && e.type() == EntityType::ControlPanel) scene.panel = &e;
        const geometry::Obb box = entity_obb(e);
        if (blocks_walking(e.type()))
            scene.solids.push_back({box, box.aabb(), e.type() == EntityType::Floor});
        const auto* floor = e.try_as<level::FloorProps>();
        if (e.type() == EntityType::Stair || (floor && !floor->ceiling)) {
            scene.supports.push_back({&e, box});
            const geometry::Aabb b = box.aabb();
            scene.area.min = glm::min(scene.area.min, b.min);
            scene.area.max = glm::max(scene.area.max, b.max);
        }
    }
    return scene;
}

// An XZ grid over the walkable area. A node is one walkable surface of one cell: up to kMaxSurfaces per cell,
// lowest first, each open while the body fits on it.
struct WalkGrid {
    Vec3 origin{0.0f}; // the area's minimum corner
    float cell = 0.0f;
    int cols = 0, rows = 0;
    std::vector<std::array<float, kMaxSurfaces>> heights;
    std::vector<std::uint8_t> layer_count, open;

    size_t cells() const { return static_cast<size_t>(cols) * static_cast<size_t>(rows); }
    size_t index(int c, int r) const { return static_cast<size_t>(r) * cols + c; }
    Vec2 centre(int c, int r) const {
        return Vec2(origin.x + (static_cast<float>(c) + 0.5f) * cell,
                    origin.z + (static_cast<float>(r) + 0.5f) * cell);
    }
    // The cells that `b`, grown by `grow` on X and Z, covers.
    void cell_range(const geometry::Aabb& b, float grow, int& c0, int& c1, int& r0, int& r1) const {
        c0 = std::max(0, static_cast<int>(std::floor((b.min.x - grow - origin.x) / cell)));
        c1 = std::min(cols - 1, static_cast<int>(std::floor((b.max.x + grow - origin.x) / cell)));
        r0 = std::max(0, static_cast<int>(std::floor((b.min.z - grow - origin.z) / cell)));
        r1 = std::min(rows - 1, static_cast<int>(std::floor((b.max.z + grow - origin.z) / cell)));
    }
};

// The cell size doubles until the grid has at most about 2M cells.
WalkGrid make_grid(const geometry::Aabb& area, float walk_cell) {
    WalkGrid grid;
    grid.origin = area.min;
    float cell = std::max(walk_cell, 0.05f);
    const float width = area.max.x - area.min.x, depth = area.max.z - area.min.z;
    while ((width / cell + 1) * (depth / cell + 1) > 2e6f) cell *= 2;
    grid.cell = cell;
    grid.cols = static_cast<int>(std::ceil(width / cell)) + 1;
    grid.rows = static_cast<int>(std::ceil(depth / cell)) + 1;
    grid.heights.resize(grid.cells());
    grid.layer_count.assign(grid.cells(), 0);
    grid.open.assign(grid.cells() * kMaxSurfaces, 0);
    return grid;
}

// Every support's surface height at the centre of each cell, up to kMaxFound per cell.
struct FoundSurfaces {
    std::vector<std::array<float, kMaxFound>> heights;
    std::vector<std::uint8_t> count;
    std::vector<float> stair_base; // per found surface: the stair's base height, or NaN for a floor
};

FoundSurfaces find_surfaces(const WalkGrid& grid, const std::vector<SupportBox>& supports) {
    FoundSurfaces found;
    found.heights.resize(grid.cells());
    found.count.assign(grid.cells(), 0);
    found.stair_base.assign(grid.cells() * kMaxFound, 0.0f);
    for (const auto& s : supports) {
        int c0, c1, r0, r1;
        grid.cell_range(s.box.aabb(), 0.0f, c0, c1, r0, r1);
        const bool stair = s.entity->type() == EntityType::Stair;
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const Vec2 p = grid.centre(c, r);
                auto h = surface_height_at(*s.entity, s.box, p.x, p.y, /*stair_as_ramp=*/true);
                const size_t index = grid.index(c, r);
                if (!h || found.count[index] == kMaxFound) continue;
                found.stair_base[index * kMaxFound + found.count[index]] =
                    stair ? s.entity->position.y : std::nanf("");
                found.heights[index][found.count[index]++] = *h;
            }
    }
    return found;
}

// One cell's surfaces: buried floors dropped, sorted, near-duplicates merged, the highest kMaxSurfaces kept
// and opened.
void keep_walkable_surfaces(WalkGrid& grid, const FoundSurfaces& found, size_t index) {
    const int n_found = std::min<int>(found.count[index], kMaxFound);
    if (n_found == 0) return;
    const auto& heights = found.heights[index];
    const float* stair_base = &found.stair_base[index * kMaxFound];
    // A floor surface under a stair's tread is buried inside the stair's solid.
    std::array<float, kMaxFound> kept{};
    int n = 0;
    for (int i = 0; i < n_found; ++i) {
        bool buried = false;
        const float h = heights[i];
        if (std::isnan(stair_base[i]))
            for (int j = 0; j < n_found; ++j) {
                const float base = stair_base[j];
                if (!std::isnan(base) && base <= h + 1e-3f && heights[j] > h + 1e-3f) {
                    buried = true;
                    break;
                }
            }
        if (!buried) kept[n++] = heights[i];
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
        grid.heights[index][k - first] = kept[k];
        grid.open[index * kMaxSurfaces + (k - first)] = 1;
    }
    grid.layer_count[index] = static_cast<std::uint8_t>(n - first);
}

// Closes every node where a solid intersects the body (from step height to full height), visiting only the
// cells each solid's bounds (grown by the body radius) can reach.
void close_blocked_nodes(WalkGrid& grid, const std::vector<Solid>& solids, const CharacterLimits& ch) {
    const float body_half_height = (ch.height - ch.step_height) / 2;
    for (const Solid& s : solids) {
        int c0, c1, r0, r1;
        const float reach = s.slab ? kSlabColumn : ch.radius;
        grid.cell_range(s.bounds, reach, c0, c1, r0, r1);
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const size_t index = grid.index(c, r);
                for (int k = 0; k < grid.layer_count[index]; ++k) {
                    std::uint8_t& node = grid.open[index * kMaxSurfaces + k];
                    const float h = grid.heights[index][k];
                    if (!node || s.bounds.min.y >= h + ch.height || s.bounds.max.y <= h + ch.step_height)
                        continue;
                    const Vec2 p = grid.centre(c, r);
                    geometry::Obb body;
                    body.center = {p.x, h + ch.step_height + body_half_height, p.y};
                    body.half = {reach, body_half_height, reach};
                    if (geometry::obb_overlap(body, s.box).overlapping) node = 0;
                }
            }
    }
}

// The node of the highest surface under the player start's feet, if any.
std::optional<size_t> start_node(const WalkGrid& grid, const Vec3& start, const ValidationOptions& o) {
    const int sc = static_cast<int>(std::floor((start.x - grid.origin.x) / grid.cell));
    const int sr = static_cast<int>(std::floor((start.z - grid.origin.z) / grid.cell));
    if (sc < 0 || sr < 0 || sc >= grid.cols || sr >= grid.rows) return std::nullopt;
    const size_t start_cell = grid.index(sc, sr);
    int start_layer = -1;
    for (int k = 0; k < grid.layer_count[start_cell]; ++k)
        if (grid.heights[start_cell][k] <= start.y + o.support_tolerance + o.character.step_height)
            start_layer = k;
    if (start_layer < 0) return std::nullopt;
    return start_cell * kMaxSurfaces + static_cast<size_t>(start_layer);
}

// Reached: the body touches the panel (its box grown by the body radius and a little reach).
geometry::Obb goal_box(const Entity& panel, const CharacterLimits& ch, float cell) {
    geometry::Obb goal = entity_obb(panel);
    goal.half += Vec3(ch.radius + cell + 0.25f, 0.5f, ch.radius + cell + 0.25f);
    return goal;
}

// The layer of cell `index` that a step from height h lands on: up at most step_height, otherwise the highest
// surface below (a drop). -1 where there is none.
int landing_layer(const WalkGrid& grid, size_t index, float h, const CharacterLimits& ch) {
    int target = -1;
    for (int k = 0; k < grid.layer_count[index]; ++k)
        if (grid.heights[index][k] <= h + ch.step_height + 1e-3f) target = k;
    return target;
}

// Breadth-first over open nodes from `start` until the body reaches `goal`; counts the nodes visited.
void flood_fill(const WalkGrid& grid, size_t start, const geometry::Obb& goal, const CharacterLimits& ch,
                WalkGridStats& stats) {
    std::vector<std::uint8_t> seen(grid.cells() * kMaxSurfaces, 0);
    std::deque<size_t> queue{start};
    seen[start] = 1;
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    while (!queue.empty()) {
        const size_t node = queue.front();
        queue.pop_front();
        ++stats.visited_nodes;
        const size_t index = node / kMaxSurfaces;
        const float h = grid.heights[index][node % kMaxSurfaces];
        const int c = static_cast<int>(index % static_cast<size_t>(grid.cols)),
                  r = static_cast<int>(index / static_cast<size_t>(grid.cols));
        const Vec2 p = grid.centre(c, r);
        if (goal.contains({p.x, h + ch.height / 2, p.y})) {
            stats.reachable = true;
            return;
        }
        for (int d = 0; d < 4; ++d) {
            const int nc = c + dc[d], nr = r + dr[d];
            if (nc < 0 || nr < 0 || nc >= grid.cols || nr >= grid.rows) continue;
            const size_t ni = grid.index(nc, nr);
            const int target = landing_layer(grid, ni, h, ch);
            if (target < 0) continue;
            const size_t next = ni * kMaxSurfaces + static_cast<size_t>(target);
            if (seen[next] || !grid.open[next]) continue;
            seen[next] = 1;
            queue.push_back(next);
        }
    }
}

} // namespace

WalkGridStats walk_to_control_panel(const level::Level& level, const ValidationOptions& o) {
    WalkGridStats stats;
    const WalkScene scene = gather_scene(level);
    if (!scene.panel || scene.supports.empty() || !is_finite(level.player_start.position)) return stats;

    WalkGrid grid = make_grid(scene.area, o.walk_cell);
    stats.columns = grid.cols, stats.rows = grid.rows, stats.cell = grid.cell;
    const FoundSurfaces found = find_surfaces(grid, scene.supports);
    for (size_t index = 0; index < grid.cells(); ++index) keep_walkable_surfaces(grid, found, index);
    close_blocked_nodes(grid, scene.solids, o.character);
    for (size_t i = 0; i < grid.open.size(); ++i) stats.open_nodes += grid.open[i];

    const auto start = start_node(grid, level.player_start.position, o);
    if (!start) return stats;
    stats.decided = true;
    flood_fill(grid, *start, goal_box(*scene.panel, o.character, grid.cell), o.character, stats);
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
