// NavMesh's queries: Detour's nearest polygon, A* corridor, string pulling and surface raycast, with the
// door filter (closed doors' polygons lack the Walk flag) and the scratch buffers sized at build.
#include "nav/nav_mesh.h"

#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>

#include <cfloat>
#include <climits>
#include <cmath>

namespace ks::nav {

std::uint64_t NavMesh::nearest_polygon(const Vec3& p, const Vec3& half_extents, Vec3& on_mesh) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0;
    dtPolyRef ref = 0;
    float nearest[3] = {p.x, p.y, p.z};
    const float centre[3] = {p.x, p.y, p.z};
    const float extents[3] = {half_extents.x, half_extents.y, half_extents.z};
    if (dtStatusFailed(query_->findNearestPoly(centre, extents, filter_.get(), &ref, nearest)) || ref == 0)
        return 0;
    on_mesh = Vec3(nearest[0], nearest[1], nearest[2]);
    return ref;
}

PathStatus NavMesh::corridor(const Vec3& from, const Vec3& to, CorridorMode mode, Vec3& start, Vec3& end,
                             int& polygon_count) {
    polygon_count = 0;
    const dtPolyRef start_ref = static_cast<dtPolyRef>(nearest_polygon(from, settings_.query_extents, start));
    if (start_ref == 0) return PathStatus::StartOffMesh;
    const dtPolyRef end_ref = static_cast<dtPolyRef>(nearest_polygon(to, settings_.query_extents, end));
    if (end_ref == 0) return PathStatus::EndOffMesh;
    dtStatus status = 0;
    const int capacity = static_cast<int>(corridor_.size());
    if (mode == CorridorMode::Shortest && settings_.any_angle_paths) {
        // Plain A* over polygons scores a polygon by its edge midpoints and can pick a corridor that
        // string-pulls longer than the shortest; any-angle search (raycasts while expanding) finds the
        // shortest. One update with no iteration limit runs the search to the end.
        status = query_->initSlicedFindPath(start_ref, end_ref, &start.x, &end.x, filter_.get(),
                                            DT_FINDPATH_ANY_ANGLE);
        if (dtStatusInProgress(status)) status = query_->updateSlicedFindPath(INT_MAX, nullptr);
        if (dtStatusSucceed(status))
            status = query_->finalizeSlicedFindPath(corridor_.data(), &polygon_count, capacity);
    } else {
        status = query_->findPath(start_ref, end_ref, &start.x, &end.x, filter_.get(), corridor_.data(),
                                  &polygon_count, capacity);
    }
    if (dtStatusFailed(status) || polygon_count == 0) {
        polygon_count = 1; // Detour refused: stay on the start polygon
        corridor_[0] = start_ref;
        end = start;
        return PathStatus::Partial;
    }
    const dtPolyRef last = corridor_[static_cast<size_t>(polygon_count - 1)];
    if (last == end_ref && !dtStatusDetail(status, DT_BUFFER_TOO_SMALL)) return PathStatus::Found;
    // The end is cut off (or the corridor ran out of room): head for the nearest point of the last polygon.
    float closest[3];
    if (dtStatusSucceed(query_->closestPointOnPoly(last, &end.x, closest, nullptr)))
        end = Vec3(closest[0], closest[1], closest[2]);
    return PathStatus::Partial;
}

int NavMesh::straighten(const Vec3& start, const Vec3& end, int polygon_count) {
    int corners = 0;
    const int capacity = static_cast<int>(straight_points_.size() / 3);
    if (dtStatusFailed(query_->findStraightPath(&start.x, &end.x, corridor_.data(), polygon_count,
                                                straight_points_.data(), nullptr, nullptr, &corners, capacity,
                                                0)))
        return 0;
    return corners;
}

PathStatus NavMesh::find_path(const Vec3& from, const Vec3& to, std::vector<Vec3>& out) {
    out.clear();
    Vec3 start(0.0f), end(0.0f);
    int polygons = 0;
    const PathStatus status = corridor(from, to, CorridorMode::Shortest, start, end, polygons);
    if (status == PathStatus::StartOffMesh || status == PathStatus::EndOffMesh) return status;
    const int corners = straighten(start, end, polygons);
    if (corners == 0) { // string pulling failed: the snapped end points are still a usable hint
        out.push_back(start);
        return PathStatus::Partial;
    }
    for (int i = 0; i < corners; ++i)
        out.emplace_back(straight_points_[i * 3], straight_points_[i * 3 + 1], straight_points_[i * 3 + 2]);
    return status;
}

std::optional<Vec3> NavMesh::nearest_point(const Vec3& p, const Vec3& half_extents) {
    Vec3 on_mesh(0.0f);
    if (nearest_polygon(p, half_extents, on_mesh) == 0) return std::nullopt;
    return on_mesh;
}

std::optional<float> NavMesh::path_length(const Vec3& from, const Vec3& to) {
    Vec3 start(0.0f), end(0.0f);
    int polygons = 0;
    if (corridor(from, to, CorridorMode::Shortest, start, end, polygons) != PathStatus::Found)
        return std::nullopt;
    const int corners = straighten(start, end, polygons);
    if (corners == 0) return std::nullopt;
    float length = 0.0f;
    for (int i = 1; i < corners; ++i) {
        const float* a = &straight_points_[static_cast<size_t>(i - 1) * 3];
        const float* b = &straight_points_[static_cast<size_t>(i) * 3];
        length += glm::length(Vec3(b[0] - a[0], b[1] - a[1], b[2] - a[2]));
    }
    return length;
}

bool NavMesh::reachable(const Vec3& from, const Vec3& to) {
    Vec3 start(0.0f), end(0.0f);
    int polygons = 0;
    return corridor(from, to, CorridorMode::AnyCorridor, start, end, polygons) == PathStatus::Found;
}

bool NavMesh::walkable_line(const Vec3& from, const Vec3& to) {
    Vec3 start(0.0f), end(0.0f);
    const dtPolyRef start_ref = static_cast<dtPolyRef>(nearest_polygon(from, settings_.query_extents, start));
    if (start_ref == 0 || nearest_polygon(to, settings_.query_extents, end) == 0) return false;
    float hit_t = 0.0f, hit_normal[3];
    int visited = 0;
    const dtStatus status = query_->raycast(start_ref, &start.x, &to.x, filter_.get(), &hit_t, hit_normal,
                                            corridor_.data(), &visited, static_cast<int>(corridor_.size()));
    // FLT_MAX: the ray reached the end without crossing a border of the walkable (and open) surface.
    if (!dtStatusSucceed(status) || dtStatusDetail(status, DT_BUFFER_TOO_SMALL) || hit_t != FLT_MAX ||
        visited == 0)
        return false;
    // The ray is flat: it must also end on the layer `to` is on, not on a floor above or below it.
    float height = 0.0f;
    const dtPolyRef last = corridor_[static_cast<size_t>(visited - 1)];
    if (dtStatusFailed(query_->getPolyHeight(last, &end.x, &height))) return false;
    return std::abs(height - end.y) <= settings_.agent_climb + settings_.cell_height;
}

} // namespace ks::nav
