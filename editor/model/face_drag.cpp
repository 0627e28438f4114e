// Dragging textures on the selected faces: face_drag.h.
#include "model/face_drag.h"

#include "brush/texture_mapping.h"
#include "model/edit_faces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace ks::editor {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;
constexpr const char* kMergeKey = "face:texture-drag";
// Scale drags snap their ratio to eighths: halving and doubling land exactly.
constexpr double kScaleSnap = 0.125;
// Closer to a face's centre than this, a point gives no reliable angle or distance.
constexpr double kMinArm = 1e-6;

// The mean of face `face`'s corners, in the brush's frame.
DVec3 face_centre(const brush::Brush& b, int face) {
    DVec3 c(0.0);
    const auto& polygon = b.polygons()[static_cast<size_t>(face)];
    for (int v : polygon) c += b.vertices()[static_cast<size_t>(v)];
    return c / double(polygon.size());
}

// `turned` and `scaled` applied to `start` so that the texel at `pivot` (on the face) stays where it is.
brush::FaceAttributes about_pivot(const brush::Plane& plane, const brush::FaceAttributes& start,
                                  const DVec3& pivot, double turned, double scaled) {
    const glm::dvec2 kept = brush::texture_coordinates({plane, start}, pivot);
    brush::FaceAttributes at = start;
    at.rotation_degrees += turned;
    at.scale *= scaled;
    const brush::TextureAxes axes = brush::texture_axes({plane, at});
    at.offset = kept - glm::dvec2(glm::dot(pivot, axes.u) / at.scale.x, glm::dot(pivot, axes.v) / at.scale.y);
    return at;
}

double snapped(double value, double step, bool snap) {
    return snap && step > 0.0 ? std::round(value / step) * step : value;
}

} // namespace

FaceDragMode face_drag_mode(bool ctrl, bool shift) {
    if (ctrl) return FaceDragMode::rotate;
    if (shift) return FaceDragMode::scale;
    return FaceDragMode::move;
}

bool FaceDrag::begin(Editor& editor, int entity, int face, const DVec3& world_point, FaceDragMode mode) {
    const Document& doc = editor.doc();
    const bool selected = std::any_of(doc.faces.begin(), doc.faces.end(),
                                      [&](const FaceRef& f) { return f.entity == entity && f.face == face; });
    const level::Entity* e = doc.level.find(entity);
    if (!selected || !e || !e->try_as<level::BrushProps>() || doc.locked.contains(entity)) return false;
    const brush::Brush& b = e->as<level::BrushProps>().brush;
    if (face < 0 || face >= static_cast<int>(b.faces().size())) return false;
    const glm::dmat3 rotation = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e->rotation)));
    grab_ = {};
    grab_.entity = entity;
    grab_.face = face;
    grab_.to_local = glm::transpose(rotation);
    grab_.centre = rotation * face_centre(b, face) + DVec3(e->position);
    grab_.normal = rotation * b.faces()[static_cast<size_t>(face)].plane.normal;
    // The pick's point, onto the plane exactly (the pick measures its distance in float).
    grab_.point = world_point - grab_.normal * glm::dot(world_point - grab_.centre, grab_.normal);
    start_.clear();
    for (const SelectedFace& f : selected_faces(doc)) start_[{f.entity->id, f.index}] = f.face.attributes;
    editor.end_merging(); // the drag is a step of its own
    mode_ = mode;
    dragging_ = true;
    changed_ = false;
    moved_ = glm::dvec2(0.0);
    turned_ = 0.0;
    ratio_ = 1.0;
    return true;
}

Result<void> FaceDrag::drag(Editor& editor, const geometry::Ray& ray) {
    if (!dragging_) return ok();
    const DVec3 origin(ray.origin), direction(ray.direction);
    const double along = glm::dot(direction, grab_.normal);
    if (std::abs(along) < 1e-9) return ok();
    const double t = glm::dot(grab_.point - origin, grab_.normal) / along;
    if (!(t > 0.0) || !std::isfinite(t)) return ok();
    return apply(editor, origin + direction * t);
}

Result<void> FaceDrag::drag_to(Editor& editor, const DVec3& world_point) {
    if (!dragging_) return ok();
    if (!is_finite(world_point)) return Error("Texture drag: the point must be finite");
    return apply(editor, world_point - grab_.normal * glm::dot(world_point - grab_.point, grab_.normal));
}

Result<void> FaceDrag::apply(Editor& editor, const DVec3& world_point) {
    const Document& doc = editor.doc();
    const level::Entity* e = doc.level.find(grab_.entity);
    const auto start = start_.find({grab_.entity, grab_.face});
    if (!e || !e->try_as<level::BrushProps>() || start == start_.end())
        return Error("Texture drag: the grabbed face is gone", Location{},
                     "release the mouse and grab again");
    const brush::Plane& plane =
        e->as<level::BrushProps>().brush.faces()[static_cast<size_t>(grab_.face)].plane;
    const GridSettings& grid = doc.grid;
    const DVec3 from = grab_.to_local * (grab_.point - grab_.centre);
    const DVec3 to = grab_.to_local * (world_point - grab_.centre);
    if (mode_ == FaceDragMode::move) {
        const brush::TextureAxes axes = brush::texture_axes({plane, start->second});
        const DVec3 delta = to - from;
        moved_ = {snapped(glm::dot(delta, axes.u), grid.step, grid.snap),
                  snapped(glm::dot(delta, axes.v), grid.step, grid.snap)};
    } else if (glm::length(from) < kMinArm || glm::length(to) < kMinArm) {
        return ok(); // at the centre: no angle, no ratio
    } else if (mode_ == FaceDragMode::rotate) {
        const brush::TextureAxes base = brush::base_texture_axes(plane.normal);
        const double swept = std::atan2(glm::dot(to, base.v), glm::dot(to, base.u)) -
                             std::atan2(glm::dot(from, base.v), glm::dot(from, base.u));
        turned_ = snapped(std::remainder(swept * kDegrees, 360.0), grid.rotation_step, grid.snap);
    } else {
        const double ratio = glm::length(to) / glm::length(from);
        ratio_ = grid.snap ? std::max(kScaleSnap, std::round(ratio / kScaleSnap) * kScaleSnap) : ratio;
    }
    const char* name = mode_ == FaceDragMode::move     ? "Drag texture"
                       : mode_ == FaceDragMode::rotate ? "Turn texture"
                                                       : "Scale texture";
    const std::uint64_t revision = editor.revision();
    auto r = edit_selected_faces(
        editor, name,
        [&](const level::Entity& owner, const brush::Brush& b, int face,
            brush::FaceAttributes& at) -> Result<void> {
            const auto was = start_.find({owner.id, face});
            if (was == start_.end()) return ok(); // selected after the press: left as it is
            const brush::FaceAttributes& s = was->second;
            if (mode_ == FaceDragMode::move) {
                at = s;
                at.offset -= moved_ / s.scale;
                return ok();
            }
            const double scaled = mode_ == FaceDragMode::scale ? ratio_ : 1.0;
            for (int k = 0; k < 2; ++k)
                if (std::abs(s.scale[k] * scaled) < kMinTextureScale ||
                    std::abs(s.scale[k] * scaled) > kMaxTextureScale)
                    return Error("the scale would leave " + std::to_string(kMinTextureScale) + " .. " +
                                     std::to_string(kMaxTextureScale),
                                 Location{}, "drag back toward the grab point");
            at = about_pivot(b.faces()[static_cast<size_t>(face)].plane, s, face_centre(b, face),
                             mode_ == FaceDragMode::rotate ? turned_ : 0.0, scaled);
            return ok();
        },
        kMergeKey);
    if (editor.revision() != revision) changed_ = true;
    return r;
}

void FaceDrag::end(Editor& editor) {
    if (dragging_) editor.end_merging();
    dragging_ = false;
}

void FaceDrag::cancel(Editor& editor) {
    if (!dragging_) return;
    editor.end_merging();
    if (changed_) editor.undo();
    dragging_ = changed_ = false;
}

std::string FaceDrag::describe() const {
    char text[96];
    if (mode_ == FaceDragMode::move)
        std::snprintf(text, sizeof text, "texture move %.2f, %.2f", moved_.x, moved_.y);
    else if (mode_ == FaceDragMode::rotate)
        std::snprintf(text, sizeof text, "texture turn %.1f deg", turned_);
    else
        std::snprintf(text, sizeof text, "texture scale x%.3f", ratio_);
    return text;
}

} // namespace ks::editor
