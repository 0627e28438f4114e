#include "game/nav_grid.h"

#include "game/game.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace ks::game {

NavGrid NavGrid::build(const physics::World& world, const geometry::Aabb& region, float floor_y,
                       Config config) {
    NavGrid g;
    g.cell_ = config.cell;
    g.floor_y_ = floor_y;
    g.origin_ = Vec3(region.min.x, floor_y, region.min.z);
    g.width_ = std::max(1, static_cast<int>(std::ceil((region.max.x - region.min.x) / config.cell)));
    g.depth_ = std::max(1, static_cast<int>(std::ceil((region.max.z - region.min.z) / config.cell)));
    const std::size_t n = static_cast<std::size_t>(g.width_) * static_cast<std::size_t>(g.depth_);
    g.walkable_.assign(n, 0);
    std::vector<physics::BodyId> hits;
    const float r = config.clearance;
    physics::RayFilter ground;
    ground.layers = physics::layer::kSolid;
    for (int cz = 0; cz < g.depth_; ++cz) {
        for (int cx = 0; cx < g.width_; ++cx) {
            const Vec3 c = g.cell_centre(cx, cz);
            hits.clear();
            const physics::Segment seg{c + Vec3(0, 0.1f + r, 0),
                                       c + Vec3(0, std::max(0.1f + r, config.height - r), 0)};
            world.overlap_capsule(seg, r, hits, physics::layer::kSolid);
            bool blocked = false;
            for (physics::BodyId id : hits) {
                const BodyKind kind = user_kind(world.user_data(id));
                if (kind == BodyKind::DoorLeaf || kind == BodyKind::Player || kind == BodyKind::Robot)
                    continue;
                blocked = true;
                break;
            }
            if (blocked) continue;
            // Something to stand on just below.
            if (!world.ray_any({c + Vec3(0, 0.5f, 0), Vec3(0, -1, 0), 1.0f}, ground)) continue;
            g.walkable_[static_cast<std::size_t>(cz) * g.width_ + cx] = 1;
        }
    }
    // Gas cylinders: keep well away (touching one sets it off).
    const float cell = config.cell;
    for (int cz = 0; cz < g.depth_; ++cz)
        for (int cx = 0; cx < g.width_; ++cx) {
            auto& w = g.walkable_[static_cast<std::size_t>(cz) * g.width_ + cx];
            if (!w) continue;
            const Vec3 c = g.cell_centre(cx, cz);
            hits.clear();
            const float reach = r + config.cylinder_margin;
            world.overlap_capsule({c + Vec3(0, 1.0f, 0), c + Vec3(0, 1.0f + cell * 0.01f, 0)}, reach, hits,
                                  physics::layer::kSolid);
            for (physics::BodyId id : hits)
                if (user_kind(world.user_data(id)) == BodyKind::Cylinder) w = 0;
        }
    g.cost_.assign(n, 0.0f);
    g.parent_.assign(n, -1);
    g.closed_stamp_.assign(n, 0);
    return g;
}

bool NavGrid::walkable(int cx, int cz) const {
    return cx >= 0 && cz >= 0 && cx < width_ && cz < depth_ &&
           walkable_[static_cast<std::size_t>(cz) * width_ + cx] != 0;
}

bool NavGrid::walkable_at(const Vec3& p) const {
    int cx, cz;
    cell_of(p, cx, cz);
    return walkable(cx, cz);
}

int NavGrid::walkable_count() const {
    return static_cast<int>(std::count(walkable_.begin(), walkable_.end(), 1));
}

Vec3 NavGrid::cell_centre(int cx, int cz) const {
    return origin_ +
           Vec3((static_cast<float>(cx) + 0.5f) * cell_, 0, (static_cast<float>(cz) + 0.5f) * cell_);
}

void NavGrid::cell_of(const Vec3& p, int& cx, int& cz) const {
    cx = static_cast<int>(std::floor((p.x - origin_.x) / cell_));
    cz = static_cast<int>(std::floor((p.z - origin_.z) / cell_));
}

bool NavGrid::nearest_walkable(int& cx, int& cz) const {
    if (walkable(cx, cz)) return true;
    for (int ring = 1; ring <= 4; ++ring)
        for (int dz = -ring; dz <= ring; ++dz)
            for (int dx = -ring; dx <= ring; ++dx) {
                if (std::max(std::abs(dx), std::abs(dz)) != ring) continue;
                if (walkable(cx + dx, cz + dz)) {
                    cx += dx;
                    cz += dz;
                    return true;
                }
            }
    return false;
}

bool NavGrid::find_path(const Vec3& from, const Vec3& to, std::vector<Vec3>& path) {
    path.clear();
    int sx, sz, gx, gz;
    cell_of(from, sx, sz);
    cell_of(to, gx, gz);
    if (!nearest_walkable(sx, sz) || !nearest_walkable(gx, gz)) return false;
    if (++stamp_ == 0) { // wrapped: reset stamps
        std::fill(closed_stamp_.begin(), closed_stamp_.end(), 0);
        stamp_ = 1;
    }
    std::fill(cost_.begin(), cost_.end(), 3.4e38f);
    open_.clear();
    const auto push = [&](float f, std::int32_t i) {
        open_.emplace_back(f, i);
        std::push_heap(open_.begin(), open_.end(), std::greater<>());
    };
    const auto index = [&](int x, int z) { return z * width_ + x; };
    const auto heuristic = [&](int x, int z) {
        const float dx = static_cast<float>(std::abs(x - gx)), dz = static_cast<float>(std::abs(z - gz));
        return (dx + dz) + (1.41421356f - 2.0f) * std::min(dx, dz);
    };
    const std::int32_t start = index(sx, sz), goal = index(gx, gz);
    cost_[static_cast<std::size_t>(start)] = 0.0f;
    parent_[static_cast<std::size_t>(start)] = -1;
    push(heuristic(sx, sz), start);
    static constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
    static constexpr int kDz[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    bool found = false;
    while (!open_.empty()) {
        std::pop_heap(open_.begin(), open_.end(), std::greater<>());
        const std::int32_t cur = open_.back().second;
        open_.pop_back();
        const auto ucur = static_cast<std::size_t>(cur);
        if (closed_stamp_[ucur] == stamp_) continue;
        closed_stamp_[ucur] = stamp_;
        if (cur == goal) {
            found = true;
            break;
        }
        const int x = cur % width_, z = cur / width_;
        for (int k = 0; k < 8; ++k) {
            const int nx = x + kDx[k], nz = z + kDz[k];
            if (!walkable(nx, nz)) continue;
            if (k >= 4 && (!walkable(x + kDx[k], z) || !walkable(x, z + kDz[k])))
                continue; // no corner cutting
            const std::int32_t ni = index(nx, nz);
            const auto uni = static_cast<std::size_t>(ni);
            if (closed_stamp_[uni] == stamp_) continue;
            const float g = cost_[ucur] + (k >= 4 ? 1.41421356f : 1.0f);
            if (g < cost_[uni]) {
                cost_[uni] = g;
                parent_[uni] = cur;
                push(g + heuristic(nx, nz), ni);
            }
        }
    }
    if (!found) return false;
    for (std::int32_t at = goal; at >= 0; at = parent_[static_cast<std::size_t>(at)]) {
        path.push_back(cell_centre(at % width_, at / width_));
        if (at == start) break;
    }
    std::reverse(path.begin(), path.end());
    return true;
}

} // namespace ks::game
