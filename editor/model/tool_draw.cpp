// The draw tool: tool_draw.h.
#include "model/tool_draw.h"

#include "brush/brush_build.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace ks::editor {
namespace {
constexpr const char* kDrawWhat = "Draw";
constexpr double kDrawSamePoint = 1e-9;

std::string draw_axis_name(int axis) {
    return std::string(1, char('x' + axis));
}

Error draw_error(const std::string& message, const std::string& hint) {
    return Error(std::string(kDrawWhat) + ": " + message, Location{}, hint);
}

// The label of a box's size: width (x) × depth (z) × height (y).
std::string dimensions_text(const DVec3& size) {
    return length_text(size.x) + " \xC3\x97 " + length_text(size.z) + " \xC3\x97 " + length_text(size.y);
}

// The point `i` of a polygon error's path "polygon[i]", counted from 1; 0 when the error names none.
size_t polygon_point(const Error& error) {
    const std::string& path = error.where.path;
    const size_t open = path.find('[');
    if (open == std::string::npos) return 0;
    return static_cast<size_t>(std::atoi(path.c_str() + open + 1)) + 1;
}
} // namespace

std::array<double, 2> DrawTool::range_along(const DrawPlane& plane) const {
    const auto& last = last_range_[static_cast<size_t>(plane.axis)];
    if (!plane.grows && reference && (*reference)[1][plane.axis] - (*reference)[0][plane.axis] > 0.0) {
        const double lo = (*reference)[0][plane.axis];
        return {lo, next_height_ ? lo + *next_height_ : (*reference)[1][plane.axis]};
    }
    const double h = next_height_ ? *next_height_ : last ? (*last)[1] - (*last)[0] : grid;
    if (!plane.grows) {
        const double lo = last ? (*last)[0] : 0.0;
        return {lo, lo + h};
    }
    return *plane.grows > 0 ? std::array{plane.level, plane.level + h}
                            : std::array{plane.level - h, plane.level};
}

void DrawTool::press(const DrawPlane& plane, const DVec3& point) {
    cancel();
    plane_ = plane;
    range_ = range_along(plane);
    start_ = end_ = point;
    stage_ = DrawStage::dragging;
}

void DrawTool::move(const DVec3& point) {
    if (stage_ == DrawStage::dragging) end_ = point;
}

std::array<DVec3, 2> DrawTool::drag_box() const {
    DVec3 lo = glm::min(start_, end_), hi = glm::max(start_, end_);
    lo[plane_.axis] = range_[0];
    hi[plane_.axis] = range_[1];
    return {lo, hi};
}

Result<int> DrawTool::release(Editor& editor) {
    if (stage_ != DrawStage::dragging) return draw_error("no box is being dragged", "drag on the grid first");
    const auto [lo, hi] = drag_box();
    for (int axis = 0; axis < 3; ++axis) {
        if (axis == plane_.axis || hi[axis] - lo[axis] > kDrawSamePoint) continue;
        cancel();
        return draw_error("the box has no size along " + draw_axis_name(axis),
                          "drag across the grid to give the box a width and a depth");
    }
    auto placed = place_box_brush(editor, Vec3(lo), Vec3(hi), look);
    if (!placed) {
        cancel();
        return placed.error();
    }
    finish();
    return placed;
}

std::vector<DVec3> DrawTool::polygon_at(double level) const {
    std::vector<DVec3> out = points_;
    for (DVec3& p : out) p[plane_.axis] = level;
    return out;
}

Result<void> DrawTool::add_point(const DrawPlane& plane, const DVec3& point) {
    if (!brush::is_finite(point)) return draw_error("the point is not a finite number", "click on the grid");
    if (stage_ == DrawStage::extruding) return draw_error("the polygon is closed", "press Enter to place it");
    if (stage_ != DrawStage::placing_points) {
        cancel();
        plane_ = plane;
        range_ = range_along(plane);
        points_ = {point};
        stage_ = DrawStage::placing_points;
        return ok();
    }
    DVec3 p = point;
    p[plane_.axis] = points_.front()[plane_.axis];
    if (points_.size() >= 3 && glm::length(p - points_.front()) <= kDrawSamePoint) return close();
    for (size_t i = 0; i < points_.size(); ++i)
        if (glm::length(p - points_[i]) <= kDrawSamePoint)
            return draw_error("the point repeats corner " + std::to_string(i + 1),
                              i + 1 == points_.size() ? "click a different point"
                                                      : "click the first corner to close the polygon");
    points_.push_back(p);
    return ok();
}

void DrawTool::remove_last_point() {
    if (stage_ == DrawStage::extruding) {
        stage_ = DrawStage::placing_points;
        return;
    }
    if (stage_ != DrawStage::placing_points) return;
    points_.pop_back();
    if (points_.empty()) cancel();
}

Result<void> DrawTool::close() {
    if (stage_ != DrawStage::placing_points)
        return draw_error("no polygon is being drawn", "click corners on the grid first");
    if (points_.size() < 3)
        return draw_error("a polygon needs at least 3 corners, it has " + std::to_string(points_.size()),
                          "click more corners");
    DVec3 direction(0.0);
    direction[plane_.axis] = 1.0;
    // The brush module's rule for an extruded polygon: strictly convex, no repeated or collinear corners.
    const auto check = brush::make_extrusion(polygon_at(0.0), direction);
    if (!check) {
        const size_t corner = polygon_point(check.error());
        return draw_error("the polygon cannot be extruded: " + check.error().message +
                              (corner ? " (corner " + std::to_string(corner) + ")" : ""),
                          check.error().hint);
    }
    stage_ = DrawStage::extruding;
    return ok();
}

void DrawTool::extrude_toward(const geometry::Ray& ray) {
    if (stage_ != DrawStage::extruding) return;
    DVec3 centre(0.0);
    for (const DVec3& p : points_) centre += p;
    centre /= static_cast<double>(points_.size());
    DVec3 axis(0.0);
    axis[plane_.axis] = 1.0;
    // The point of the line centre + s * axis nearest the ray (closest points of two lines).
    const DVec3 d = glm::normalize(DVec3(ray.direction)), w = centre - DVec3(ray.origin);
    const double b = glm::dot(axis, d), denom = 1.0 - b * b;
    if (denom < 1e-9) return; // the ray runs along the axis: the mouse cannot show a height
    const double s = (b * glm::dot(d, w) - glm::dot(axis, w)) / denom;
    const double along = s * plane_.grows.value_or(1);
    set_height(grid > 0.0 ? std::round(along / grid) * grid : along);
}

Result<int> DrawTool::commit(Editor& editor) {
    if (stage_ == DrawStage::placing_points)
        if (auto closed = close(); !closed) return closed.error();
    if (stage_ != DrawStage::extruding)
        return draw_error("no polygon is ready to extrude", "click its corners and close it first");
    const int u = plane_.axis == 0 ? 1 : 0, v = plane_.axis == 2 ? 1 : 2;
    std::vector<glm::vec2> flat;
    for (const DVec3& p : points_) flat.push_back({static_cast<float>(p[u]), static_cast<float>(p[v])});
    const bool down = plane_.grows && *plane_.grows < 0;
    auto placed = place_extruded_brush(editor, plane_.axis, static_cast<float>(down ? range_[1] : range_[0]),
                                       static_cast<float>(down ? range_[0] : range_[1]), flat, look);
    if (!placed) return placed.error(); // still extruding: change the height, or Esc
    finish();
    return placed;
}

void DrawTool::set_height(double height) {
    if (!std::isfinite(height)) return;
    height = std::max(height, grid > 0.0 ? grid : 1e-3);
    if (!busy()) {
        next_height_ = height;
        return;
    }
    if (plane_.grows && *plane_.grows < 0)
        range_[0] = range_[1] - height;
    else
        range_[1] = range_[0] + height;
}

void DrawTool::step_height(int steps) {
    set_height(height() + steps * grid);
}

double DrawTool::height() const {
    if (busy()) return range_[1] - range_[0];
    if (next_height_) return *next_height_;
    return last_range_[1] ? (*last_range_[1])[1] - (*last_range_[1])[0] : grid;
}

void DrawTool::cancel() {
    stage_ = DrawStage::idle;
    points_.clear();
}

void DrawTool::finish() {
    if (const auto box = bounds())
        for (int axis = 0; axis < 3; ++axis)
            last_range_[static_cast<size_t>(axis)] = {(*box)[0][axis], (*box)[1][axis]};
    next_height_.reset();
    cancel();
}

std::optional<std::array<DVec3, 2>> DrawTool::bounds() const {
    if (stage_ == DrawStage::dragging) return drag_box();
    if (points_.empty()) return std::nullopt;
    DVec3 lo = points_.front(), hi = points_.front();
    for (const DVec3& p : points_) lo = glm::min(lo, p), hi = glm::max(hi, p);
    lo[plane_.axis] = range_[0];
    hi[plane_.axis] = stage_ == DrawStage::extruding ? range_[1] : range_[0];
    return std::array{lo, hi};
}

std::optional<DVec3> DrawTool::dimensions() const {
    const auto box = bounds();
    if (!box) return std::nullopt;
    return (*box)[1] - (*box)[0];
}

ToolPreview DrawTool::preview() const {
    ToolPreview out;
    const auto box = bounds();
    if (!box) {
        out.hint = shape == DrawShape::box ? "drag on the grid to draw a box brush"
                                           : "click the corners of a convex polygon on the grid";
        return out;
    }
    const auto [lo, hi] = *box;
    out.labels.push_back({DVec3((lo.x + hi.x) * 0.5, hi.y, (lo.z + hi.z) * 0.5), dimensions_text(hi - lo)});
    if (stage_ == DrawStage::dragging) {
        out.box(lo, hi);
        for (int axis = 0; axis < 3; ++axis) { // the lengths of the three edges from the low corner
            DVec3 mid = lo;
            mid[axis] = (lo[axis] + hi[axis]) * 0.5;
            out.labels.push_back({mid, length_text(hi[axis] - lo[axis])});
            if (axis != plane_.axis && hi[axis] - lo[axis] <= kDrawSamePoint && out.problem.empty())
                out.problem = "the box has no size along " + draw_axis_name(axis);
        }
        out.hint = "release to place the box; [ and ] change its height by a grid step";
        return out;
    }
    const std::vector<DVec3> base = polygon_at(range_[0]);
    for (size_t i = 0; i + 1 < base.size() || (stage_ == DrawStage::extruding && i < base.size()); ++i)
        out.measured(base[i], base[(i + 1) % base.size()]);
    if (stage_ == DrawStage::placing_points) {
        out.hint = "click the first corner or press Enter to close the polygon; Backspace removes the last";
        return out;
    }
    const std::vector<DVec3> top = polygon_at(range_[1]);
    out.polyline(top, true);
    for (size_t i = 0; i < base.size(); ++i) out.segments.push_back({base[i], top[i], ToolLine::shape});
    out.labels.push_back({(base.front() + top.front()) * 0.5, length_text(range_[1] - range_[0])});
    out.hint = "move the mouse to set the height ([ and ] by a grid step); click or Enter places the brush";
    return out;
}

} // namespace ks::editor
