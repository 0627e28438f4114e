#pragma once
// A walk grid over one floor level, built from the physics world by capsule overlap queries, and A* on it
// (8-connected, no corner cutting). Door leaves, characters and triggers do not block (the bot opens doors
// and fights robots); gas cylinders block with a margin, since touching one sets it off.
#include "core/math.h"
#include "physics/world.h"

#include <cstdint>
#include <vector>

namespace ks::game {

class NavGrid {
  public:
    struct Config {
        float cell = 1.0f;
        float clearance = 1.15f;      // capsule radius tested per cell (player radius 1 + margin)
        float height = 3.0f;          // capsule height tested
        float cylinder_margin = 2.6f; // extra keep-out around gas cylinders (their radius plus this)
    };
    // Covers `region` (x, z) at floor height `floor_y`.
    static NavGrid build(const physics::World& world, const geometry::Aabb& region, float floor_y,
                         Config config);
    static NavGrid build(const physics::World& world, const geometry::Aabb& region, float floor_y) {
        return build(world, region, floor_y, Config{});
    }

    bool walkable(int cx, int cz) const;
    bool walkable_at(const Vec3& p) const;
    int width() const { return width_; }
    int depth() const { return depth_; }
    int walkable_count() const;
    Vec3 cell_centre(int cx, int cz) const;
    void cell_of(const Vec3& p, int& cx, int& cz) const;
    // Path of cell centres from `from` to `to` (both snapped to the nearest walkable cell within 4 cells);
    // empty when unreachable. Reuses internal buffers.
    bool find_path(const Vec3& from, const Vec3& to, std::vector<Vec3>& path);

  private:
    bool nearest_walkable(int& cx, int& cz) const;
    Vec3 origin_{0.0f}; // min corner
    float cell_ = 1.0f;
    float floor_y_ = 0.0f;
    int width_ = 0, depth_ = 0;
    std::vector<std::uint8_t> walkable_;
    std::vector<float> cost_;
    std::vector<std::int32_t> parent_;
    std::vector<std::uint32_t> closed_stamp_;
    std::vector<std::pair<float, std::int32_t>> open_; // binary heap (f, cell), reused
    std::uint32_t stamp_ = 0;
};

} // namespace ks::game
