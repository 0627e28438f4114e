#pragma once
// The measuring tool, window-free: two points clicked on brush vertices, faces or the grid (the viewport
// snaps them: view/tool_pointer.h); the distance between them and the angle of their line to the horizontal,
// to three decimals (1 mm when a unit is a metre). Until the second click the line follows the mouse; a
// third click starts a new measurement. Tests: tests/editor/test_geometry_tools.cpp.
#include "model/tool_preview.h"

#include <optional>

namespace ks::editor {

struct Measurement {
    DVec3 from{0.0}, to{0.0};
    double distance = 0.0;
    double rise_degrees = 0.0; // the angle to the horizontal: + upward from `from` to `to`, 0 when level
    double horizontal = 0.0;   // the length of its shadow on the ground
    DVec3 delta() const { return to - from; }
};

Measurement measure(const DVec3& from, const DVec3& to);
// "distance 5.000  angle 36.870°  (dx 4.000, dy 3.000, dz 0.000)".
std::string measurement_text(const Measurement& m);

class MeasureTool {
  public:
    void add_point(const DVec3& point);
    // Where the mouse is (the live end while one point is placed); nullopt when it is off the level.
    void hover(std::optional<DVec3> point) { hover_ = point; }
    void reset();

    bool busy() const { return from_.has_value(); }
    bool finished() const { return to_.has_value(); } // both points clicked
    // The finished measurement, else the live one to the hovered point.
    std::optional<Measurement> measurement() const;
    ToolPreview preview() const;

  private:
    std::optional<DVec3> from_, to_, hover_;
};

} // namespace ks::editor
