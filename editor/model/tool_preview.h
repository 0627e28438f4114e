#pragma once
// What a geometry tool shows while it works (tool_draw.h, tool_clip.h, tool_measure.h), window-free: lines
// in the world, labels at world points, the hint for the next input and the problem that keeps it from
// committing. The viewport draws it (editor/ui/geometry_tools_ui.cpp); tests and the status file read it.
#include "core/math.h"

#include <span>
#include <string>
#include <vector>

namespace ks::editor {

// What a line is, so the viewport colours it: the shape being made, a plane's cut through a brush, or a
// guide (a measuring line, a clip point's marker).
enum class ToolLine { shape, cut, guide };

struct ToolSegment {
    DVec3 a{0.0}, b{0.0};
    ToolLine kind = ToolLine::shape;
};

struct ToolLabel {
    DVec3 at{0.0};
    std::string text;
};

struct ToolPreview {
    std::vector<ToolSegment> segments;
    std::vector<ToolLabel> labels;
    std::string hint;    // what the next input does
    std::string problem; // why the tool cannot commit now; empty when it can (or has nothing yet)

    // The 12 edges of the box lo..hi.
    void box(const DVec3& lo, const DVec3& hi, ToolLine kind = ToolLine::shape);
    // Consecutive points joined, the last back to the first when `closed`.
    void polyline(std::span<const DVec3> points, bool closed, ToolLine kind = ToolLine::shape);
    // The segment a..b with its length labelled at its middle.
    void measured(const DVec3& a, const DVec3& b, ToolLine kind = ToolLine::shape);
};

// A length in level units to three decimals ("12.346"): the measuring tool's 1 mm when a unit is a metre.
std::string length_text(double length);
// An angle in degrees to three decimals with the degree sign ("36.870°").
std::string angle_text(double degrees);

} // namespace ks::editor
