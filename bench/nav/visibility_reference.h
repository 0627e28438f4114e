#pragma once
// The exact shortest path for a disc-shaped agent on a flat floor among axis-aligned box obstacles, computed
// independently of Recast, as the reference `ks_bench nav` measures the mesh's path lengths against: each
// obstacle grown by the agent radius has rounded corners; their arcs are replaced by circumscribed polygons
// (kArcSteps segments per quarter circle, so a path around a corner is at most 0.3% long on that arc),
// every pair of nodes that sees the other is an edge, and Dijkstra finds the shortest.
#include "core/math.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ks::bench::nav_reference {

struct Rect {
    Vec2 min{0.0f}, max{0.0f};
};

inline float point_rect_distance(Vec2 p, const Rect& r) {
    const Vec2 d = glm::max(glm::max(r.min - p, p - r.max), Vec2(0.0f));
    return glm::length(d);
}

inline bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const auto cross = [](Vec2 u, Vec2 v) { return u.x * v.y - u.y * v.x; };
    const float d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c),
                d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

inline float point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(a + ab * t - p);
}

// Distance between a segment and a rectangle (0 when they meet): for two convex sets that do not meet it is
// reached at an end of the segment or a corner of the rectangle.
inline float segment_rect_distance(Vec2 a, Vec2 b, const Rect& r) {
    const Vec2 corners[4] = {r.min, {r.max.x, r.min.y}, r.max, {r.min.x, r.max.y}};
    if (point_rect_distance(a, r) == 0.0f || point_rect_distance(b, r) == 0.0f) return 0.0f;
    for (int i = 0; i < 4; ++i)
        if (segments_cross(a, b, corners[i], corners[(i + 1) % 4])) return 0.0f;
    float best = std::min(point_rect_distance(a, r), point_rect_distance(b, r));
    for (const Vec2& c : corners) best = std::min(best, point_segment_distance(c, a, b));
    return best;
}

class VisibilityGraph {
  public:
    static constexpr int kArcSteps = 8;

    // Free space: inside `bounds` shrunk by the radius, at least `radius` from every obstacle.
    VisibilityGraph(std::vector<Rect> obstacles, Rect bounds, float radius)
        : obstacles_(std::move(obstacles)), bounds_(bounds), radius_(radius) {
        const float step = kHalfPi / kArcSteps;
        const float reach = radius / std::cos(step * 0.5f) * (1.0f + 1e-4f);
        for (const Rect& r : obstacles_) {
            const Vec2 corners[4] = {
                {r.max.x, r.max.y}, {r.min.x, r.max.y}, {r.min.x, r.min.y}, {r.max.x, r.min.y}};
            for (int c = 0; c < 4; ++c)
                for (int i = 0; i <= kArcSteps; ++i) {
                    const float angle = static_cast<float>(c) * kHalfPi + static_cast<float>(i) * step;
                    const Vec2 p = corners[c] + reach * Vec2(std::cos(angle), std::sin(angle));
                    if (free(p)) nodes_.push_back(p);
                }
        }
        const size_t n = nodes_.size();
        sees_.assign(n * n, 0);
        for (size_t i = 0; i < n; ++i)
            for (size_t j = i + 1; j < n; ++j)
                sees_[i * n + j] = sees_[j * n + i] = visible(nodes_[i], nodes_[j]);
    }

    bool free(Vec2 p) const {
        const float lo_x = bounds_.min.x + radius_, hi_x = bounds_.max.x - radius_;
        const float lo_y = bounds_.min.y + radius_, hi_y = bounds_.max.y - radius_;
        if (p.x < lo_x || p.x > hi_x || p.y < lo_y || p.y > hi_y) return false;
        for (const Rect& r : obstacles_)
            if (point_rect_distance(p, r) < radius_ - kTolerance) return false;
        return true;
    }
    bool visible(Vec2 a, Vec2 b) const {
        for (const Rect& r : obstacles_)
            if (segment_rect_distance(a, b, r) < radius_ - kTolerance) return false;
        return true; // the free square is convex, so a segment between free points stays inside it
    }

    // Shortest length from a to b through free space; infinity when none.
    float shortest(Vec2 a, Vec2 b) const {
        if (visible(a, b)) return glm::length(b - a);
        const size_t n = nodes_.size();
        std::vector<float> dist(n, std::numeric_limits<float>::infinity());
        std::vector<char> done(n, 0);
        for (size_t i = 0; i < n; ++i)
            if (visible(a, nodes_[i])) dist[i] = glm::length(nodes_[i] - a);
        float best = std::numeric_limits<float>::infinity();
        for (;;) {
            size_t u = n;
            for (size_t i = 0; i < n; ++i)
                if (!done[i] && (u == n || dist[i] < dist[u])) u = i;
            if (u == n || dist[u] >= best) break;
            done[u] = 1;
            if (visible(nodes_[u], b)) best = std::min(best, dist[u] + glm::length(b - nodes_[u]));
            for (size_t v = 0; v < n; ++v)
                if (!done[v] && sees_[u * n + v])
                    dist[v] = std::min(dist[v], dist[u] + glm::length(nodes_[v] - nodes_[u]));
        }
        return best;
    }
    size_t node_count() const { return nodes_.size(); }

  private:
    static constexpr float kTolerance = 1e-3f;
    static constexpr float kHalfPi = kPi * 0.5f;
    std::vector<Rect> obstacles_;
    Rect bounds_;
    float radius_;
    std::vector<Vec2> nodes_;
    std::vector<char> sees_;
};

} // namespace ks::bench::nav_reference
