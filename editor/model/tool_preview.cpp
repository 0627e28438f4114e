// Geometry tools' previews: tool_preview.h.
#include "model/tool_preview.h"

#include <cmath>
#include <cstdio>

namespace ks::editor {

void ToolPreview::box(const DVec3& lo, const DVec3& hi, ToolLine kind) {
    auto corner = [&](int i) { return DVec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) segments.push_back({corner(i), corner(i | bit), kind});
}

void ToolPreview::polyline(std::span<const DVec3> points, bool closed, ToolLine kind) {
    for (size_t i = 0; i + 1 < points.size(); ++i) segments.push_back({points[i], points[i + 1], kind});
    if (closed && points.size() > 2) segments.push_back({points.back(), points.front(), kind});
}

void ToolPreview::measured(const DVec3& a, const DVec3& b, ToolLine kind) {
    segments.push_back({a, b, kind});
    labels.push_back({(a + b) * 0.5, length_text(glm::length(b - a))});
}

std::string length_text(double length) {
    char text[48];
    // Rounded first, so that -0.0004 reads 0.000 and not -0.000.
    const double mm = std::round(length * 1000.0) / 1000.0;
    std::snprintf(text, sizeof(text), "%.3f", mm == 0.0 ? 0.0 : mm);
    return text;
}

std::string angle_text(double degrees) {
    return length_text(degrees) + "\xC2\xB0";
}

} // namespace ks::editor
