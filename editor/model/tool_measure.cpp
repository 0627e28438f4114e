// The measuring tool: tool_measure.h.
#include "model/tool_measure.h"

#include <cmath>

namespace ks::editor {

Measurement measure(const DVec3& from, const DVec3& to) {
    Measurement m;
    m.from = from;
    m.to = to;
    const DVec3 d = to - from;
    m.distance = glm::length(d);
    m.horizontal = std::hypot(d.x, d.z);
    m.rise_degrees = m.distance > 0.0 ? glm::degrees(std::atan2(d.y, m.horizontal)) : 0.0;
    return m;
}

std::string measurement_text(const Measurement& m) {
    const DVec3 d = m.delta();
    return "distance " + length_text(m.distance) + "  angle " + angle_text(m.rise_degrees) + "  (dx " +
           length_text(d.x) + ", dy " + length_text(d.y) + ", dz " + length_text(d.z) + ")";
}

void MeasureTool::add_point(const DVec3& point) {
    if (!from_ || to_) {
        from_ = point;
        to_.reset();
        return;
    }
    to_ = point;
}

void MeasureTool::reset() {
    from_.reset();
    to_.reset();
}

std::optional<Measurement> MeasureTool::measurement() const {
    if (!from_) return std::nullopt;
    if (to_) return measure(*from_, *to_);
    if (hover_) return measure(*from_, *hover_);
    return std::nullopt;
}

ToolPreview MeasureTool::preview() const {
    ToolPreview out;
    const auto m = measurement();
    if (!m) {
        out.hint = from_ ? "click the second point" : "click the first point on a vertex, a face or the grid";
        return out;
    }
    out.segments.push_back({m->from, m->to, ToolLine::guide});
    // Its shadow on the horizontal through the first point and the rise, so the angle reads.
    const DVec3 level(m->to.x, m->from.y, m->to.z);
    if (m->horizontal > 0.0 && std::abs(m->to.y - m->from.y) > 0.0) {
        out.segments.push_back({m->from, level, ToolLine::shape});
        out.segments.push_back({level, m->to, ToolLine::shape});
    }
    out.labels.push_back({(m->from + m->to) * 0.5, measurement_text(*m)});
    out.hint = to_ ? "click to start a new measurement" : "click the second point";
    return out;
}

} // namespace ks::editor
