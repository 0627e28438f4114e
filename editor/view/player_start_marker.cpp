#include "view/player_start_marker.h"

#include "level/entity_shapes.h"
#include "model/bounds.h"

#include <cmath>

namespace ks::editor {
namespace {
constexpr int kRingSegments = 32;
constexpr float kTau = 6.2831853f;

void ring(const Vec3& centre, float radius, std::vector<MarkerLine>& out) {
    Vec3 previous = centre + Vec3(radius, 0, 0);
    for (int i = 1; i <= kRingSegments; ++i) {
        const float a = static_cast<float>(i) / kRingSegments * kTau;
        const Vec3 p = centre + Vec3(std::cos(a), 0, std::sin(a)) * radius;
        out.push_back({previous, p});
        previous = p;
    }
}

// Half a circle over (or under) `centre` in the upright plane along `across`: a capsule's cap.
void cap(const Vec3& centre, const Vec3& across, float radius, float up, std::vector<MarkerLine>& out) {
    constexpr int kSegments = kRingSegments / 2;
    Vec3 previous = centre + across * radius;
    for (int i = 1; i <= kSegments; ++i) {
        const float a = static_cast<float>(i) / kSegments * (kTau * 0.5f);
        const Vec3 p = centre + across * (std::cos(a) * radius) + Vec3(0, up * std::sin(a) * radius, 0);
        out.push_back({previous, p});
        previous = p;
    }
}

// An arrow from `from` to `tip` with two barbs in the horizontal plane.
void arrow(const Vec3& from, const Vec3& tip, const Vec3& side, float barb, std::vector<MarkerLine>& out) {
    const Vec3 back = glm::normalize(from - tip) * barb;
    out.push_back({from, tip});
    out.push_back({tip, tip + back + side * barb * 0.7f});
    out.push_back({tip, tip + back - side * barb * 0.7f});
}
} // namespace

Vec3 player_start_facing(const level::PlayerStart& start) {
    const float yaw = radians(start.yaw);
    return {-std::sin(yaw), 0.0f, -std::cos(yaw)};
}

void player_start_figure(const level::PlayerStart& start, std::vector<MarkerLine>& out) {
    const float r = level::kPlayerRadius, h = level::kPlayerHeight;
    const Vec3 feet = start.position, forward = player_start_facing(start);
    const Vec3 side(-forward.z, 0.0f, forward.x);
    const Vec3 low = feet + Vec3(0, r, 0), high = feet + Vec3(0, h - r, 0);
    ring(low, r, out);
    ring(high, r, out);
    for (const Vec3& across : {forward, side}) {
        cap(high, across, r, 1.0f, out);
        cap(low, across, r, -1.0f, out);
        out.push_back({low + across * r, high + across * r});
        out.push_back({low - across * r, high - across * r});
    }
    const Vec3 floor = feet + Vec3(0, 0.1f, 0);
    arrow(floor, floor + forward * kStartArrowLength, side, 0.9f, out);
    const Vec3 eye = feet + Vec3(0, kStartEyeHeight, 0);
    arrow(eye + forward * r, eye + forward * (r + 1.2f), side, 0.5f, out);
}

std::optional<float> pick_player_start(const level::PlayerStart& start, const geometry::Ray& ray) {
    const float t = geometry::ray_obb(ray, player_obb(start));
    if (t < 0.0f) return std::nullopt;
    return t;
}

} // namespace ks::editor
