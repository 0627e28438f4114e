#include "physics/mover_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::physics {

namespace {
std::uint32_t cell_hash(int ix, int iz) {
    return static_cast<std::uint32_t>(ix) * 73856093u ^ static_cast<std::uint32_t>(iz) * 19349663u;
}
// For |v| <= kMaxCoordinate only (the callers check): truncation, then one down for negative fractions.
int cell_of(float v, float cell) {
    const float scaled = v * (1.0f / cell);
    const int truncated = static_cast<int>(scaled);
    return truncated - (scaled < static_cast<float>(truncated) ? 1 : 0);
}
// Cells are ints: coordinates beyond this (or not numbers) go to the always-tested list, and a query reaching
// past it tests every mover.
constexpr float kMaxCoordinate = 1e9f;
// Branch-free: the result decides whether a slot is kept, and a mispredicted branch per candidate was most of
// the query's cost.
bool overlaps(const geometry::Aabb& a, const geometry::Aabb& b) {
    return (a.min.x <= b.max.x) & (b.min.x <= a.max.x) & (a.min.y <= b.max.y) & (b.min.y <= a.max.y) &
           (a.min.z <= b.max.z) & (b.min.z <= a.max.z);
}
bool in_range(float v) {
    return v >= -kMaxCoordinate && v <= kMaxCoordinate; // false for NaN
}
// A box that overlaps nothing, not even an infinite region (every comparison with NaN is false).
geometry::Aabb nowhere() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {Vec3(nan), Vec3(nan)};
}
} // namespace

void MoverGrid::build(std::span<const geometry::Aabb> bounds, float slack) {
    const std::size_t n = bounds.size();
    std::uint32_t buckets = 16;
    while (buckets < 2 * n) buckets *= 2;
    mask_ = buckets - 1;
    start_.assign(buckets + 1, 0);
    slot_of_.resize(n);
    anchor_.resize(2 * n);
    always_.clear();
    always_box_.clear();
    float largest_half = 0.0f;
    for (std::size_t i = 0; i < n; ++i) { // count each bucket's movers (slot_of_ holds the bucket for now)
        const geometry::Aabb& b = bounds[i];
        const float cx = (b.min.x + b.max.x) * 0.5f, cz = (b.min.z + b.max.z) * 0.5f;
        const float hx = (b.max.x - b.min.x) * 0.5f, hz = (b.max.z - b.min.z) * 0.5f;
        if (!(hx >= 0.0f && hx <= 0.5f * kCell && hz >= 0.0f && hz <= 0.5f * kCell && in_range(cx) &&
              in_range(cz))) {
            slot_of_[i] = kNotInCell | static_cast<std::uint32_t>(always_.size());
            always_.push_back(static_cast<std::uint32_t>(i));
            always_box_.push_back(b);
            continue;
        }
        largest_half = std::max({largest_half, hx, hz});
        anchor_[2 * i] = cx;
        anchor_[2 * i + 1] = cz;
        const std::uint32_t k = cell_hash(cell_of(cx, kCell), cell_of(cz, kCell)) & mask_;
        slot_of_[i] = k;
        ++start_[k + 1];
    }
    for (std::uint32_t k = 0; k < buckets; ++k) start_[k + 1] += start_[k];
    const std::uint32_t slots = start_[buckets];
    slot_item_.resize(slots);
    slot_box_.resize(slots);
    for (std::size_t i = 0; i < n; ++i) { // fill in position order: deterministic
        if (slot_of_[i] & kNotInCell) continue;
        const std::uint32_t s = start_[slot_of_[i]]++;
        slot_item_[s] = static_cast<std::uint32_t>(i);
        slot_box_[s] = bounds[i];
        slot_of_[i] = s;
    }
    // Each start_[k] now holds its bucket's end: shift back so that start_[k] is the bucket's first slot.
    for (std::uint32_t k = buckets; k > 0; --k) start_[k] = start_[k - 1];
    start_[0] = 0;
    reach_ = largest_half + slack;
    hits_.resize(slots);
}

bool MoverGrid::leaves_cell(std::uint32_t position, const geometry::Aabb& b) const {
    // A query finds the cell of anchor a when a lies within reach_ of its region. For a box overlapping the
    // region that holds when max - reach <= a <= min + reach; the guard covers the float rounding of both
    // sides. Written negated so that a box that is not a number leaves.
    const float ax = anchor_[2 * position], az = anchor_[2 * position + 1];
    const float gx = 1e-6f * (std::abs(ax) + reach_), gz = 1e-6f * (std::abs(az) + reach_);
    return !(b.max.x - reach_ + gx <= ax && ax <= b.min.x + reach_ - gx && b.max.z - reach_ + gz <= az &&
             az <= b.min.z + reach_ - gz);
}

void MoverGrid::update(std::uint32_t position, const geometry::Aabb& bounds) {
    const std::uint32_t s = slot_of_[position];
    if (s & kNotInCell) {
        always_box_[s & ~kNotInCell] = bounds;
    } else if (!leaves_cell(position, bounds)) {
        slot_box_[s] = bounds;
    } else {
        slot_box_[s] = nowhere();
        slot_of_[position] = kNotInCell | static_cast<std::uint32_t>(always_.size());
        always_.push_back(position);
        always_box_.push_back(bounds);
    }
}

std::uint32_t MoverGrid::scan_cells(const geometry::Aabb& region) const {
    const geometry::Aabb wide = region.expanded(reach_);
    bool every =
        !(in_range(wide.min.x) && in_range(wide.max.x) && in_range(wide.min.z) && in_range(wide.max.z));
    int x0 = 0, x1 = -1, z0 = 0, z1 = -1;
    if (!every) {
        x0 = cell_of(wide.min.x, kCell), x1 = cell_of(wide.max.x, kCell);
        z0 = cell_of(wide.min.z, kCell), z1 = cell_of(wide.max.z, kCell);
        every = static_cast<std::int64_t>(x1 - x0 + 1) * (z1 - z0 + 1) > kMaxQueryCells;
    }
    // A local count and array (not members the compiler must assume the stores may change).
    std::uint32_t* const out = hits_.data();
    const geometry::Aabb* const box = slot_box_.data();
    std::uint32_t hits = 0;
    auto scan = [&](std::uint32_t first, std::uint32_t end) {
        for (std::uint32_t s = first; s < end; ++s) {
            out[hits] = s;
            hits += overlaps(box[s], region) ? 1u : 0u;
        }
    };
    if (every) {
        scan(0, static_cast<std::uint32_t>(slot_box_.size()));
        return hits;
    }
    // Cells that hash to one bucket would be read twice: each bucket once (a query has a handful of cells).
    std::uint32_t buckets[kMaxQueryCells];
    int count = 0;
    for (int x = x0; x <= x1; ++x)
        for (int z = z0; z <= z1; ++z) {
            const std::uint32_t k = cell_hash(x, z) & mask_;
            if (std::find(buckets, buckets + count, k) == buckets + count) buckets[count++] = k;
        }
    for (int i = 0; i < count; ++i) scan(start_[buckets[i]], start_[buckets[i] + 1]);
    return hits;
}

} // namespace ks::physics
