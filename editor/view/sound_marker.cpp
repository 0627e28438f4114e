#include "view/sound_marker.h"

#include <cmath>

namespace ks::editor {

void speaker_icon(const Vec3& centre, const Vec3& right, const Vec3& up, float half_size,
                  std::vector<MarkerLine>& out) {
    // In icon units (1 = half_size): u to the right, v up; the horn opens toward +u.
    auto at = [&](float u, float v) { return centre + (right * u + up * v) * half_size; };
    auto line = [&](float u0, float v0, float u1, float v1) { out.push_back({at(u0, v0), at(u1, v1)}); };
    // The magnet: a small rectangle.
    line(-0.9f, -0.3f, -0.4f, -0.3f);
    line(-0.4f, -0.3f, -0.4f, 0.3f);
    line(-0.4f, 0.3f, -0.9f, 0.3f);
    line(-0.9f, 0.3f, -0.9f, -0.3f);
    // The horn: flares from the magnet's face to a wider mouth.
    line(-0.4f, 0.3f, 0.1f, 0.7f);
    line(-0.4f, -0.3f, 0.1f, -0.7f);
    line(0.1f, -0.7f, 0.1f, 0.7f);
    // Two arcs of sound in front of the mouth, a quarter turn each (-45 to +45 degrees).
    constexpr int kArcSegments = 6;
    auto arc_angle = [](int i) { return (-0.25f + 0.5f * static_cast<float>(i) / kArcSegments) * kPi; };
    for (float radius : {0.35f, 0.7f}) {
        for (int i = 0; i < kArcSegments; ++i) {
            const float a0 = arc_angle(i), a1 = arc_angle(i + 1);
            line(0.1f + radius * std::cos(a0), radius * std::sin(a0), 0.1f + radius * std::cos(a1),
                 radius * std::sin(a1));
        }
    }
}

void wire_sphere(const Vec3& centre, float radius, int segments, std::vector<MarkerLine>& out) {
    const Vec3 axes[3][2] = {{{1, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}}};
    for (const auto& plane : axes) {
        Vec3 previous = centre + plane[0] * radius;
        for (int i = 1; i <= segments; ++i) {
            const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
            const Vec3 p = centre + (plane[0] * std::cos(a) + plane[1] * std::sin(a)) * radius;
            out.push_back({previous, p});
            previous = p;
        }
    }
}

} // namespace ks::editor
