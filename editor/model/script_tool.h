#pragma once
// The script language's geometry-tool steps (`tool draw`, `tool polygon`, `tool clip`, `tool measure`,
// `tool vertex`): each line is one whole use of a tool (tool_draw.h, tool_clip.h, tool_measure.h,
// tool_vertex.h), fed the points a mouse would
// click, so scripts and tests drive the same state machines as the viewport. Parsed, run and registered in
// script_tool_parser.cpp.
#include "model/edit_brushes.h"
#include "model/tool_vertex.h"

#include <optional>
#include <variant>
#include <vector>

namespace ks::editor {

struct ScriptContext;

namespace steps {

// Which view the points are clicked in: an axis view (its axis) or the perspective view (nullopt).
struct ToolView {
    std::optional<int> axis;
};

struct ToolDraw {
    ToolView view;
    DVec3 a{0.0}, b{0.0};
    std::optional<double> height;
    Result<void> run(ScriptContext& c) const;
};
struct ToolPolygon {
    ToolView view;
    std::vector<DVec3> points;
    std::optional<double> height;
    Result<void> run(ScriptContext& c) const;
};
struct ToolClip {
    std::optional<int> view_axis; // two points need an axis view
    std::vector<DVec3> points;
    int match_entity = 0, match_face = -1; // `match ID FACE`: the plane of that brush's face
    ClipKeep keep = ClipKeep::back;
    Result<void> run(ScriptContext& c) const;
};
struct ToolMeasure {
    DVec3 a{0.0}, b{0.0};
    std::optional<double> distance, angle; // `is D [A]`: expected, to 1 mm and 0.001 degrees
    Result<void> run(ScriptContext& c) const;
};

// `tool vertex [edge|face] X,Y,Z... by DX,DY,DZ`: the handles at those points selected and dragged by the
// delta (one undo step); `tool vertex split X,Y,Z by D`: the edge whose midpoint is there split;
// `tool vertex remove X,Y,Z...`: those vertices removed. All on the selected brushes.
struct ToolVertex {
    enum class Action { move, split, remove };
    Action action = Action::move;
    VertexMode mode = VertexMode::vertex;
    std::vector<DVec3> handles;
    DVec3 delta{0.0};
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct ToolStep {
    std::variant<steps::ToolDraw, steps::ToolPolygon, steps::ToolClip, steps::ToolMeasure, steps::ToolVertex>
        step;
    Result<void> run(ScriptContext& c) const;
};

} // namespace ks::editor
