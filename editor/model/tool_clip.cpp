// The clip tool: tool_clip.h.
#include "model/tool_clip.h"

#include "brush/brush_clip.h"
#include "level/entity_shapes.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {
constexpr const char* kClipWhat = "Clip";
constexpr double kClipSamePoint = 1e-9;

Error clip_error(const std::string& message, const std::string& hint) {
    return Error(std::string(kClipWhat) + ": " + message, Location{}, hint);
}

// Where the unit plane cuts the brush (both in one frame): the crossings of its edges (and its vertices on
// the plane), in order around the normal. Empty when the plane does not pass through the inside.
std::vector<DVec3> cut_outline(const brush::Brush& world, const brush::Plane& plane) {
    const auto& vertices = world.vertices();
    std::vector<double> side(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) side[i] = plane.signed_distance(vertices[i]);
    // A plane touching the brush along a face, an edge or a vertex cuts nothing (brush::split's rule).
    const auto [low, high] = std::minmax_element(side.begin(), side.end());
    if (side.empty() || *low >= -brush::kOnPlaneEpsilon || *high <= brush::kOnPlaneEpsilon) return {};
    std::vector<DVec3> points;
    auto add = [&](const DVec3& p) {
        for (const DVec3& q : points)
            if (glm::length(p - q) <= brush::kWeldDistance) return;
        points.push_back(p);
    };
    for (size_t i = 0; i < vertices.size(); ++i)
        if (std::abs(side[i]) <= brush::kOnPlaneEpsilon) add(vertices[i]);
    for (const brush::Edge& e : world.edges()) {
        const double a = side[static_cast<size_t>(e.v0)], b = side[static_cast<size_t>(e.v1)];
        if ((a < -brush::kOnPlaneEpsilon && b > brush::kOnPlaneEpsilon) ||
            (a > brush::kOnPlaneEpsilon && b < -brush::kOnPlaneEpsilon))
            add(glm::mix(vertices[static_cast<size_t>(e.v0)], vertices[static_cast<size_t>(e.v1)],
                         a / (a - b)));
    }
    if (points.size() < 3) return {};
    DVec3 centre(0.0);
    for (const DVec3& p : points) centre += p;
    centre /= static_cast<double>(points.size());
    // Two axes in the plane; the points sorted by their angle about the centre.
    const DVec3 n = plane.normal;
    const DVec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? DVec3(1, 0, 0) : DVec3(0, 1, 0)));
    const DVec3 v = glm::cross(n, u);
    std::sort(points.begin(), points.end(), [&](const DVec3& p, const DVec3& q) {
        return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
               std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
    });
    return points;
}
} // namespace

const char* clip_keep_name(ClipKeep keep) {
    switch (keep) {
    case ClipKeep::back:
        return "back";
    case ClipKeep::front:
        return "front";
    case ClipKeep::both:
        return "both";
    }
    return "back";
}

Result<void> ClipTool::add_point(const DVec3& point) {
    if (!brush::is_finite(point))
        return clip_error("the point is not a finite number", "click a face or the grid");
    if (points_.size() >= 3) points_.clear();
    for (size_t i = 0; i < points_.size(); ++i)
        if (glm::length(point - points_[i]) <= kClipSamePoint)
            return clip_error("the point repeats point " + std::to_string(i + 1), "click a different point");
    face_.reset();
    points_.push_back(point);
    return ok();
}

void ClipTool::match_face(const brush::Plane& face) {
    points_.clear();
    face_ = face;
}

void ClipTool::cycle_keep() {
    keep_ = keep_ == ClipKeep::back    ? ClipKeep::front
            : keep_ == ClipKeep::front ? ClipKeep::both
                                       : ClipKeep::back;
}

void ClipTool::reset() {
    points_.clear();
    face_.reset();
}

Result<brush::Plane> ClipTool::plane() const {
    if (face_) return *face_;
    if (points_.empty()) return clip_error("no plane yet", "click the first point on a face or the grid");
    if (points_.size() == 1) return clip_error("one point is not a plane", "click a second point");
    const DVec3 &a = points_[0], &b = points_[1];
    if (points_.size() == 2) {
        if (!view_direction_)
            return clip_error("two points make a plane only in an axis view",
                              "click a third point, or match a face");
        const DVec3 n = glm::cross(b - a, *view_direction_);
        if (glm::length(n) <= 1e-12 * std::max(1.0, glm::length(b - a)))
            return clip_error("the two points line up with the view direction",
                              "click points apart on screen");
        const DVec3 unit = glm::normalize(n);
        return brush::Plane{unit, glm::dot(unit, a)};
    }
    const auto plane = brush::plane_from_points(a, b, points_[2]);
    if (!plane) return clip_error("the three points lie on one line", "move the third point off their line");
    return *plane;
}

ToolPreview ClipTool::preview(const Document& doc) const {
    ToolPreview out;
    for (const DVec3& p : points_) { // a small cross at each point
        for (int axis = 0; axis < 3; ++axis) {
            DVec3 d(0.0);
            d[axis] = 0.25;
            out.segments.push_back({p - d, p + d, ToolLine::guide});
        }
    }
    out.polyline(points_, points_.size() == 3, ToolLine::guide);
    const auto plane = this->plane();
    if (!plane) {
        out.problem = plane.error().message.substr(std::string(kClipWhat).size() + 2);
        out.hint = plane.error().hint;
        return out;
    }
    int brushes = 0, cut = 0;
    std::string emptied;
    DVec3 anchor = points_.empty() ? plane->normal * plane->distance : points_.front();
    for (int id : doc.selection) {
        const level::Entity* e = doc.level.find(id);
        if (!e || e->type() != level::EntityType::Brush) continue;
        // In the brush's own frame (its faces derived already): the plane moved there, the outline back.
        const brush::Brush& local = e->as<level::BrushProps>().brush;
        const glm::dmat3 rotation = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e->rotation)));
        const DVec3 position(e->position);
        const brush::Plane in_frame{glm::transpose(rotation) * plane->normal,
                                    plane->distance - glm::dot(plane->normal, position)};
        ++brushes;
        std::vector<DVec3> outline = cut_outline(local, in_frame);
        for (DVec3& p : outline) p = rotation * p + position;
        if (!outline.empty()) {
            if (cut++ == 0) {
                anchor = DVec3(0.0);
                for (const DVec3& p : outline) anchor += p;
                anchor /= static_cast<double>(outline.size());
            }
            out.polyline(outline, true, ToolLine::cut);
            continue;
        }
        const brush::PlaneReach reach = brush::reach(local, in_frame);
        if ((keep_ == ClipKeep::back && reach == brush::PlaneReach::all_in_front) ||
            (keep_ == ClipKeep::front && reach == brush::PlaneReach::all_behind))
            emptied = "the clip would leave nothing of brush " + std::to_string(id);
    }
    out.segments.push_back({anchor, anchor + plane->normal, ToolLine::guide}); // the front side
    out.labels.push_back({anchor + plane->normal, "front"});
    out.labels.push_back({anchor, std::string("keep ") + clip_keep_name(keep_)});
    if (brushes == 0)
        out.problem = "no brush is selected";
    else if (!emptied.empty())
        out.problem = emptied;
    else if (cut == 0)
        out.problem = "the plane misses the selected brushes";
    out.hint = "Enter clips the selected brushes; Tab keeps back, front or both";
    return out;
}

Result<void> ClipTool::apply(Editor& editor) {
    const auto plane = this->plane();
    if (!plane) return plane.error();
    const ToolPreview shown = preview(editor.doc());
    if (shown.problem == "the plane misses the selected brushes")
        return clip_error(shown.problem, "move the points so the plane passes through a selected brush");
    // The plane's point nearest the first clicked point (or the origin), where it is precise.
    const DVec3 from = points_.empty() ? DVec3(0.0) : points_.front();
    const DVec3 point = from - plane->normal * plane->signed_distance(from);
    if (auto clipped = clip_selected_brushes(editor, Vec3(point), Vec3(plane->normal), keep_); !clipped)
        return clipped.error();
    reset();
    return ok();
}

} // namespace ks::editor
