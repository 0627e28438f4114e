#include "model/xz_grid.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {
bool finite_box(const geometry::Aabb& b) {
    return std::isfinite(b.min.x) && std::isfinite(b.min.z) && std::isfinite(b.max.x) &&
           std::isfinite(b.max.z);
}
constexpr int kMaxCellsPerAxis = 1024;
// Items are indexed a little larger than their boxes: the rules' exact tests (a point inside an oriented
// box, an overlap with tolerance) may accept what rounding puts a hair outside the box's AABB.
constexpr float kMargin = 0.1f;
geometry::Aabb inflated(const geometry::Aabb& b) {
    return {b.min - Vec3(kMargin), b.max + Vec3(kMargin)};
}
} // namespace

XzGrid::XzGrid(const std::vector<geometry::Aabb>& boxes) {
    float x0 = 3e38f, z0 = 3e38f, x1 = -3e38f, z1 = -3e38f;
    int finite = 0;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        const geometry::Aabb b = inflated(boxes[static_cast<size_t>(i)]);
        if (!finite_box(b)) {
            everywhere_.push_back(i);
            continue;
        }
        x0 = std::min(x0, b.min.x), z0 = std::min(z0, b.min.z);
        x1 = std::max(x1, b.max.x), z1 = std::max(z1, b.max.z);
        ++finite;
    }
    if (finite == 0) return;
    // About one cell per item (levels are mostly flat and spread out), no smaller than 4 units.
    const double area = std::max(static_cast<double>(x1 - x0) * (z1 - z0), 1.0);
    cell_ = static_cast<float>(std::max(4.0, std::sqrt(area / finite)));
    cell_ = std::max({cell_, (x1 - x0) / kMaxCellsPerAxis, (z1 - z0) / kMaxCellsPerAxis});
    origin_x_ = x0, origin_z_ = z0;
    columns_ = std::max(1, static_cast<int>(std::floor((x1 - x0) / cell_)) + 1);
    rows_ = std::max(1, static_cast<int>(std::floor((z1 - z0) / cell_)) + 1);
    // Two passes (count, then fill) into one contiguous array.
    std::vector<int> count(static_cast<size_t>(columns_) * rows_ + 1, 0);
    auto for_cells = [&](const geometry::Aabb& b, auto&& visit) {
        int c0, c1, r0, r1;
        if (!cell_range(b, c0, c1, r0, r1)) return;
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) visit(static_cast<size_t>(r) * columns_ + c);
    };
    for (const geometry::Aabb& box : boxes)
        if (const geometry::Aabb b = inflated(box); finite_box(b))
            for_cells(b, [&](size_t k) { ++count[k + 1]; });
    for (size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
    cell_start_ = count;
    items_.resize(static_cast<size_t>(count.back()));
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        const geometry::Aabb b = inflated(boxes[static_cast<size_t>(i)]);
        if (finite_box(b)) for_cells(b, [&](size_t k) { items_[static_cast<size_t>(count[k]++)] = i; });
    }
}

bool XzGrid::cell_range(const geometry::Aabb& box, int& c0, int& c1, int& r0, int& r1) const {
    if (columns_ == 0 || !finite_box(box)) return false;
    auto index = [&](float v, float origin, int n) {
        const float f = std::floor((v - origin) / cell_);
        return static_cast<int>(std::clamp(f, -1.0f, static_cast<float>(n)));
    };
    c0 = index(box.min.x, origin_x_, columns_), c1 = index(box.max.x, origin_x_, columns_);
    r0 = index(box.min.z, origin_z_, rows_), r1 = index(box.max.z, origin_z_, rows_);
    if (c1 < 0 || r1 < 0 || c0 >= columns_ || r0 >= rows_) return false;
    c0 = std::max(c0, 0), r0 = std::max(r0, 0);
    c1 = std::min(c1, columns_ - 1), r1 = std::min(r1, rows_ - 1);
    return true;
}

void XzGrid::query(const geometry::Aabb& box, std::vector<int>& out) const {
    out.assign(everywhere_.begin(), everywhere_.end());
    int c0, c1, r0, r1;
    if (!finite_box(box)) { // a non-finite query box: everything, as a plain loop would test everything
        for (int i : items_) out.push_back(i);
    } else if (cell_range(box, c0, c1, r0, r1)) {
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const size_t k = static_cast<size_t>(r) * columns_ + c;
                out.insert(out.end(), items_.begin() + cell_start_[k], items_.begin() + cell_start_[k + 1]);
            }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

void XzGrid::query_point(float x, float z, std::vector<int>& out) const {
    query(geometry::Aabb{Vec3(x, 0.0f, z), Vec3(x, 0.0f, z)}, out);
}

} // namespace ks::editor
