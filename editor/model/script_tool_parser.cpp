// The script language's geometry-tool commands (script_tool.h): the `tool` line's parser, its steps' `run`
// (each drives a tool's state machine as the viewport does) and the table entry that registers it
// (script_command.h).
#include "core/log.h"
#include "level/entity_shapes.h"
#include "model/script_command.h"
#include "model/tool_clip.h"
#include "model/tool_draw.h"
#include "model/tool_measure.h"

#include <cmath>

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kToolUsage =
    "tool draw top|front|side|perspective X,Y,Z X,Y,Z [height H] | "
    "tool polygon top|front|side|perspective X,Y,Z X,Y,Z X,Y,Z... [height H] | "
    "tool clip [top|front|side] X,Y,Z X,Y,Z [X,Y,Z] [keep back|front|both] | "
    "tool clip match ID FACE [keep back|front|both] | tool measure X,Y,Z X,Y,Z [is DISTANCE [ANGLE]] | "
    "tool vertex [edge|face] X,Y,Z... by DX,DY,DZ | tool vertex split X,Y,Z by DX,DY,DZ | "
    "tool vertex remove X,Y,Z...";

template <class T>
Result<ScriptStep> tool_step(T step) {
    return step_of<ToolStep>(std::move(step));
}

// "X,Y,Z" as doubles (a measurement keeps its millimetres far from the origin).
bool to_dvec3(std::string_view s, DVec3& out) {
    const size_t first = s.find(','), second = s.find(',', first + 1);
    if (first == std::string_view::npos || second == std::string_view::npos) return false;
    return to_double(s.substr(0, first), out.x) &&
           to_double(s.substr(first + 1, second - first - 1), out.y) &&
           to_double(s.substr(second + 1), out.z) && std::isfinite(out.x) && std::isfinite(out.y) &&
           std::isfinite(out.z);
}

Result<void> point_at(const LineWords& w, size_t i, DVec3& out) {
    if (i >= w.size()) return w.fail(i, "expected a point X,Y,Z", kToolUsage);
    if (!to_dvec3(w.text(i), out))
        return w.fail(i, "expected three numbers separated by commas, got '" + w.word(i) + "'",
                      "write a point without spaces, like 4,0,-2.5");
    return ok();
}

// top, front, side (their axes) or perspective.
bool view_word(std::string_view word, steps::ToolView& out) {
    if (word == "top") return out.axis = 1, true;
    if (word == "front") return out.axis = 2, true;
    if (word == "side") return out.axis = 0, true;
    if (word == "perspective") return out.axis.reset(), true;
    return false;
}

// The optional `height H` at word i (the last words of the line).
Result<void> height_from(const LineWords& w, size_t i, std::optional<double>& height) {
    if (i == w.size()) return ok();
    double h = 0.0;
    if (w.text(i) != "height" || i + 2 != w.size() || !to_double(w.text(i + 1), h) || !(h > 0.0))
        return w.fail(i, "expected 'height H' with a positive H at the end", kToolUsage);
    height = h;
    return ok();
}

Result<ScriptStep> parse_draw(const LineWords& w, bool polygon) {
    steps::ToolView view;
    if (w.size() < 3 || !view_word(w.text(2), view))
        return w.fail(2, "expected the view: top, front, side or perspective", kToolUsage);
    std::vector<DVec3> points;
    size_t i = 3;
    for (; i < w.size() && w.text(i) != "height"; ++i) {
        DVec3 p;
        if (auto r = point_at(w, i, p); !r) return r.error();
        points.push_back(p);
    }
    std::optional<double> height;
    if (auto r = height_from(w, i, height); !r) return r.error();
    if (!polygon) {
        if (points.size() != 2)
            return w.fail(i, "a box is dragged from one corner to another: two points", kToolUsage);
        return tool_step(steps::ToolDraw{view, points[0], points[1], height});
    }
    if (points.size() < 3) return w.fail(i, "a polygon needs at least 3 corners", kToolUsage);
    return tool_step(steps::ToolPolygon{view, std::move(points), height});
}

Result<ScriptStep> parse_clip(const LineWords& w) {
    steps::ToolClip step;
    size_t i = 2, end = w.size();
    if (end >= 2 && w.text(end - 2) == "keep") {
        const std::string_view keep = w.text(end - 1);
        if (keep != "back" && keep != "front" && keep != "both")
            return w.fail(end - 1, "expected back, front or both", kToolUsage);
        step.keep = keep == "back" ? ClipKeep::back : keep == "front" ? ClipKeep::front : ClipKeep::both;
        end -= 2;
    }
    if (i < end && w.text(i) == "match") {
        if (end != 5 || !to_int(w.text(3), step.match_entity) || !to_int(w.text(4), step.match_face))
            return w.fail(3, "expected the brush's id and the face's index", kToolUsage);
        return tool_step(step);
    }
    steps::ToolView view;
    if (i < end && view_word(w.text(i), view)) {
        if (!view.axis) return w.fail(i, "two-point clips need an axis view: top, front or side", kToolUsage);
        step.view_axis = view.axis;
        ++i;
    }
    for (; i < end; ++i) {
        DVec3 p;
        if (auto r = point_at(w, i, p); !r) return r.error();
        step.points.push_back(p);
    }
    if (step.points.size() < 2 || step.points.size() > 3)
        return w.fail(i, "expected 2 or 3 points", kToolUsage);
    return tool_step(step);
}

Result<ScriptStep> parse_measure(const LineWords& w) {
    steps::ToolMeasure step;
    if (auto r = point_at(w, 2, step.a); !r) return r.error();
    if (auto r = point_at(w, 3, step.b); !r) return r.error();
    if (w.size() == 4) return tool_step(step);
    double d = 0.0, a = 0.0;
    if (w.text(4) != "is" || w.size() < 6 || w.size() > 7 || !to_double(w.text(5), d) ||
        (w.size() == 7 && !to_double(w.text(6), a)))
        return w.fail(4, "expected 'is DISTANCE [ANGLE]'", kToolUsage);
    step.distance = d;
    if (w.size() == 7) step.angle = a;
    return tool_step(step);
}

Result<ScriptStep> parse_vertex(const LineWords& w) {
    using Action = steps::ToolVertex::Action;
    steps::ToolVertex step;
    size_t i = 2;
    const std::string_view first = i < w.size() ? w.text(i) : std::string_view();
    if (first == "edge" || first == "face") step.mode = first == "edge" ? VertexMode::edge : VertexMode::face;
    if (first == "split" || first == "remove")
        step.action = first == "split" ? Action::split : Action::remove;
    if (first == "edge" || first == "face" || first == "split" || first == "remove") ++i;
    for (; i < w.size() && w.text(i) != "by"; ++i) {
        DVec3 p;
        if (auto r = point_at(w, i, p); !r) return r.error();
        step.handles.push_back(p);
    }
    if (step.handles.empty()) return w.fail(i, "expected the handles' points X,Y,Z", kToolUsage);
    if (step.action == Action::split && step.handles.size() != 1)
        return w.fail(3, "a split takes one edge's midpoint", kToolUsage);
    if (step.action == Action::remove) {
        if (i != w.size())
            return w.fail(i, "'tool vertex remove' takes only the vertices' points", kToolUsage);
        return tool_step(step);
    }
    if (i + 2 != w.size()) return w.fail(i, "expected 'by DX,DY,DZ' at the end", kToolUsage);
    if (auto r = point_at(w, i + 1, step.delta); !r) return r.error();
    return tool_step(step);
}

Result<ScriptStep> parse_tool(const LineWords& w) {
    if (w.size() < 2) return w.fail(1, "expected which tool", kToolUsage);
    const std::string_view what = w.text(1);
    if (what == "draw" || what == "polygon") return parse_draw(w, what == "polygon");
    if (what == "clip") return parse_clip(w);
    if (what == "measure") return parse_measure(w);
    if (what == "vertex") return parse_vertex(w);
    return w.fail(1, "unknown tool '" + w.word(1) + "'", kToolUsage);
}

constexpr CommandSpec kCommands[] = {
    {"tool", false, kToolUsage,
     "use a geometry tool as the mouse would: drag a box brush or extrude a clicked polygon in a view, clip "
     "the selected brushes by 2 or 3 points or a brush's face, measure between two points, drag the selected "
     "brushes' vertices, edges or faces, split an edge, remove vertices",
     parse_tool},
};

// The plane an axis view's drawing lies on (the range along its axis is the tool's), or in perspective the
// horizontal through the first point, growing up.
DrawPlane plane_in(const steps::ToolView& view, const DVec3& first) {
    if (view.axis) return {*view.axis, first[*view.axis], std::nullopt};
    return {1, first.y, 1};
}

DrawTool draw_tool(const ScriptContext& c, std::optional<double> height) {
    DrawTool tool;
    tool.grid = c.editor.doc().grid.step;
    if (height) tool.set_height(*height);
    return tool;
}

} // namespace

std::span<const CommandSpec> tool_commands() {
    return kCommands;
}

Result<void> ToolStep::run(ScriptContext& c) const {
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

namespace steps {

Result<void> ToolDraw::run(ScriptContext& c) const {
    DrawTool tool = draw_tool(c, height);
    tool.press(plane_in(view, a), a);
    tool.move(b);
    auto placed = tool.release(c.editor);
    if (!placed) return placed.error();
    return ok();
}

Result<void> ToolPolygon::run(ScriptContext& c) const {
    DrawTool tool = draw_tool(c, height);
    tool.shape = DrawShape::polygon;
    for (const DVec3& p : points)
        if (auto added = tool.add_point(plane_in(view, points.front()), p); !added) return added.error();
    auto placed = tool.commit(c.editor);
    if (!placed) return placed.error();
    return ok();
}

Result<void> ToolClip::run(ScriptContext& c) const {
    ClipTool tool;
    tool.set_keep(keep);
    if (match_face >= 0) {
        const level::Entity* e = c.editor.level().find(match_entity);
        if (!e || e->type() != level::EntityType::Brush)
            return Error("Clip: entity " + std::to_string(match_entity) + " is not a brush", Location{},
                         "give the id of a brush entity");
        auto world = level::world_brush(*e);
        if (!world) return world.error();
        if (static_cast<size_t>(match_face) >= world->faces().size())
            return Error("Clip: brush " + std::to_string(match_entity) + " has " +
                             std::to_string(world->faces().size()) + " faces, not " +
                             std::to_string(match_face + 1),
                         Location{}, "give a face index from 0");
        tool.match_face(world->faces()[static_cast<size_t>(match_face)].plane);
    } else {
        if (view_axis) {
            DVec3 direction(0.0);
            direction[*view_axis] = -1.0; // top looks down, front along -z, side along -x
            tool.set_view_direction(direction);
        }
        for (const DVec3& p : points)
            if (auto added = tool.add_point(p); !added) return added.error();
    }
    return tool.apply(c.editor);
}

Result<void> ToolMeasure::run(ScriptContext& c) const {
    MeasureTool tool;
    tool.add_point(a);
    tool.add_point(b);
    const Measurement m = *tool.measurement();
    log::info(c.file_name, ":", c.line, ": ", measurement_text(m));
    if (distance)
        if (auto r = c.expect(std::abs(m.distance - *distance) < 5e-4,
                              "measured " + length_text(m.distance) + ", expected " + length_text(*distance));
            !r)
            return r;
    if (angle)
        return c.expect(std::abs(m.rise_degrees - *angle) < 5e-4, "measured an angle of " +
                                                                      angle_text(m.rise_degrees) +
                                                                      ", expected " + angle_text(*angle));
    return ok();
}

Result<void> ToolVertex::run(ScriptContext& c) const {
    VertexTool tool;
    tool.set_mode(mode);
    if (action == Action::split) {
        if (auto grabbed = tool.grab(c.editor.doc(), handles.front()); !grabbed) return grabbed.error();
    } else {
        for (const DVec3& h : handles)
            if (auto selected = tool.select(c.editor.doc(), h, true); !selected) return selected.error();
        if (action == Action::remove) return tool.remove_selected(c.editor);
        if (auto grabbed = tool.grab(c.editor.doc(), handles.front(), true); !grabbed) return grabbed.error();
    }
    tool.drag(c.editor.doc(), delta);
    return tool.release(c.editor);
}

} // namespace steps
} // namespace ks::editor
