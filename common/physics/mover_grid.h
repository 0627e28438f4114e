#pragma once
// The movers' broadphase: an x/z grid of every mover's start-of-step centre, hashed into buckets and rebuilt
// each step (a counting sort: no allocation once warm). Each mover sits in exactly one cell, so a query
// visits every candidate once without marking it; a query widens its box by the largest half-size of a mover
// in the grid plus how far one may travel in the step, so a mover's current bounds are always found. A mover
// pushed further than that inside the step (out of a door that closed on it, out of a packed crowd) leaves
// its cell for a short list every query reads. Entries are positions (0..count-1) given by the caller.
#include "geometry/aabb.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::physics {

class MoverGrid {
  public:
    // Indexes movers 0..bounds.size()-1 by their bounds now; `slack` is how far (x/z) one may travel
    // before update() is told.
    void build(std::span<const geometry::Aabb> bounds, float slack);
    // Position `position`'s bounds are now `bounds` (it moved inside the step).
    void update(std::uint32_t position, const geometry::Aabb& bounds);
    // Calls visit(position) once for each mover whose current bounds overlap `region` (closed boxes).
    template <class Visit>
    void query(const geometry::Aabb& region, Visit&& visit) const;

  private:
    static constexpr float kCell = 8.0f; // a power of two: cells are found by multiplying by its reciprocal
    static constexpr int kMaxQueryCells = 64; // a query over more cells tests every mover instead
    static constexpr std::uint32_t kNotInCell = 0x80000000u; // in slot_of_: an index into always_ instead
    std::uint32_t scan_cells(const geometry::Aabb& region) const; // fills hits_, returns how many
    bool leaves_cell(std::uint32_t position, const geometry::Aabb& bounds) const;

    std::uint32_t mask_ = 0;               // buckets - 1
    std::vector<std::uint32_t> start_;     // bucket -> its first slot (buckets + 1 entries)
    std::vector<std::uint32_t> slot_item_; // slot -> position, bucket by bucket
    std::vector<geometry::Aabb> slot_box_; // slot -> the bounds now (a box that overlaps nothing once left)
    std::vector<std::uint32_t> slot_of_;   // position -> slot, or kNotInCell | index into always_
    std::vector<float> anchor_;            // position -> start-of-step centre, x then z
    std::vector<std::uint32_t> always_;    // positions every query tests: too big for a cell, or moved out
    std::vector<geometry::Aabb> always_box_;
    float reach_ = 0.0f;                      // the largest half-size of a mover in a cell plus the slack
    mutable std::vector<std::uint32_t> hits_; // a query's slots that overlap it
};

template <class Visit>
void MoverGrid::query(const geometry::Aabb& region, Visit&& visit) const {
    const std::uint32_t hits = scan_cells(region);
    for (std::uint32_t i = 0; i < hits; ++i) visit(slot_item_[hits_[i]]);
    for (std::size_t i = 0; i < always_.size(); ++i)
        if (always_box_[i].overlaps(region)) visit(always_[i]);
}

} // namespace ks::physics
