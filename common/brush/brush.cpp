#include "brush/brush.h"

#include "brush/brush_derive.h"
#include "brush/brush_validate.h"

#include <algorithm>
#include <map>

namespace ks::brush {
namespace {

// The smallest volume a brush may have, in cubic units (a 1e-4 sliver of one square unit has 1e-4).
constexpr double kMinVolume = 1e-12;

std::vector<Edge> build_edges(const std::vector<std::vector<int>>& polygons) {
    std::map<std::pair<int, int>, int> first_face; // (low, high) -> the face that used it first
    std::vector<Edge> edges;
    for (std::size_t f = 0; f < polygons.size(); ++f)
        for (std::size_t k = 0; k < polygons[f].size(); ++k) {
            const int a = polygons[f][k], b = polygons[f][(k + 1) % polygons[f].size()];
            const auto key = std::pair{std::min(a, b), std::max(a, b)};
            const auto [it, inserted] = first_face.emplace(key, static_cast<int>(f));
            if (!inserted) edges.push_back({a, b, it->second, static_cast<int>(f)});
        }
    return edges;
}

} // namespace

double polyhedron_volume(const std::vector<DVec3>& vertices, const std::vector<std::vector<int>>& polygons) {
    if (vertices.empty()) return 0.0;
    DVec3 centre(0.0);
    for (const DVec3& v : vertices) centre += v;
    centre /= double(vertices.size());
    double six_volume = 0.0;
    for (const auto& poly : polygons)
        for (std::size_t k = 1; k + 1 < poly.size(); ++k)
            six_volume += glm::dot(vertices[poly[0]] - centre,
                                   glm::cross(vertices[poly[k]] - centre, vertices[poly[k + 1]] - centre));
    return six_volume / 6.0;
}

Result<Brush> Brush::from_faces(std::vector<Face> faces, RedundantPlanes redundant) {
    return from_anchored_faces(DVec3(0.0), std::move(faces), redundant);
}

Result<Brush> Brush::from_anchored_faces(const DVec3& anchor, std::vector<Face> local_faces,
                                         RedundantPlanes redundant) {
    if (!is_finite(anchor) || glm::any(glm::greaterThan(glm::abs(anchor), DVec3(kMaxCoordinate))))
        return Error("the anchor is not finite or lies beyond the world", Location({}, 0, 0, "anchor"),
                     "give a point near the brush");
    auto valid = validate_faces(std::move(local_faces), redundant);
    if (!valid) return valid.error();
    std::vector<Plane> planes;
    for (const Face& f : *valid) planes.push_back(f.plane);
    auto derived = derive_geometry(planes);
    if (!derived) return derived.error();
    Brush brush;
    brush.anchor_ = anchor;
    for (std::size_t i = 0; i < valid->size(); ++i) {
        if (!derived->polygons[i].empty()) {
            brush.local_planes_.push_back(planes[i]);
            brush.faces_.push_back(std::move((*valid)[i]));
            brush.faces_.back().plane = planes[i].translated(anchor);
            brush.polygons_.push_back(std::move(derived->polygons[i]));
        } else if (redundant == RedundantPlanes::refuse && !derived->vertices.empty()) {
            return Error("the plane contributes no face (it lies outside the brush or only touches it)",
                         face_location(i), "remove this face");
        }
    }
    for (DVec3& v : derived->vertices) v += anchor;
    brush.vertices_ = std::move(derived->vertices);
    brush.volume_ = polyhedron_volume(brush.vertices_, brush.polygons_);
    if (brush.faces_.size() < 4 || !(brush.volume_ > kMinVolume))
        return Error("the planes enclose no volume (the spaces behind them do not overlap, or only in a "
                     "point, line or plane)",
                     Location({}, 0, 0, "faces"), "move the planes so that they enclose a solid");
    brush.edges_ = build_edges(brush.polygons_);
    brush.bounds_min_ = brush.bounds_max_ = brush.vertices_[0];
    for (const DVec3& v : brush.vertices_) {
        brush.bounds_min_ = glm::min(brush.bounds_min_, v);
        brush.bounds_max_ = glm::max(brush.bounds_max_, v);
    }
    const DVec3 reach = glm::max(glm::abs(brush.bounds_min_), glm::abs(brush.bounds_max_));
    if (std::max({reach.x, reach.y, reach.z}) > kMaxCoordinate)
        return Error("the brush reaches beyond +-65536 units", Location({}, 0, 0, "faces"),
                     "keep brushes within the world");
    return brush;
}

Result<Brush> Brush::with_attributes(std::vector<FaceAttributes> attributes) const {
    if (attributes.size() != faces_.size())
        return Error("the brush has " + std::to_string(faces_.size()) + " faces, not " +
                         std::to_string(attributes.size()),
                     Location({}, 0, 0, "faces"), "give one set of attributes per face");
    for (std::size_t i = 0; i < attributes.size(); ++i)
        if (auto r = check_attributes(attributes[i], i); !r) return r.error();
    Brush out = *this;
    for (std::size_t i = 0; i < attributes.size(); ++i) out.faces_[i].attributes = std::move(attributes[i]);
    return out;
}

Result<Brush> Brush::carried(const glm::dmat3& rotation, const DVec3& translation,
                             std::vector<FaceAttributes> attributes) const {
    if (auto rigid = check_rigid_motion(rotation, translation); !rigid) return rigid.error();
    if (!attributes.empty() && attributes.size() != faces_.size())
        return Error("the brush has " + std::to_string(faces_.size()) + " faces, not " +
                         std::to_string(attributes.size()),
                     Location({}, 0, 0, "faces"), "give one set of attributes per face");
    // The anchor and planes as transformed() moves them, so both give the same faces.
    const DVec3 moved_anchor = rotation * anchor_ + translation;
    const DVec3 anchor = glm::round(moved_anchor);
    if (!is_finite(anchor) || glm::any(glm::greaterThan(glm::abs(anchor), DVec3(kMaxCoordinate))))
        return Error("the brush reaches beyond +-65536 units", Location({}, 0, 0, "faces"),
                     "keep brushes within the world");
    const DVec3 remainder = moved_anchor - anchor;
    Brush out;
    out.anchor_ = anchor;
    out.faces_ = faces_;
    out.local_planes_.reserve(local_planes_.size());
    for (std::size_t i = 0; i < faces_.size(); ++i) {
        Plane plane = local_planes_[i];
        plane.normal = glm::normalize(rotation * plane.normal);
        plane.distance += glm::dot(plane.normal, remainder);
        out.local_planes_.push_back(plane);
        out.faces_[i].plane = plane.translated(anchor);
        if (attributes.empty()) continue;
        if (auto r = check_attributes(attributes[i], i); !r) return r.error();
        out.faces_[i].attributes = std::move(attributes[i]);
    }
    // Each vertex through the motion relative to the anchors, where the numbers are small.
    out.vertices_.reserve(vertices_.size());
    for (const DVec3& v : vertices_) out.vertices_.push_back(rotation * (v - anchor_) + remainder + anchor);
    out.polygons_ = polygons_;
    out.edges_ = edges_;
    out.volume_ = volume_; // a rigid motion keeps it
    out.bounds_min_ = out.bounds_max_ = out.vertices_[0];
    for (const DVec3& v : out.vertices_) {
        out.bounds_min_ = glm::min(out.bounds_min_, v);
        out.bounds_max_ = glm::max(out.bounds_max_, v);
    }
    const DVec3 reach = glm::max(glm::abs(out.bounds_min_), glm::abs(out.bounds_max_));
    if (!(std::max({reach.x, reach.y, reach.z}) <= kMaxCoordinate))
        return Error("the brush reaches beyond +-65536 units", Location({}, 0, 0, "faces"),
                     "keep brushes within the world");
    return out;
}

DVec3 Brush::vertex_centre() const {
    DVec3 c(0.0);
    for (const DVec3& v : vertices_) c += v;
    return c / double(vertices_.size());
}

std::vector<Face> Brush::anchored_faces() const {
    std::vector<Face> out = faces_;
    for (std::size_t i = 0; i < out.size(); ++i) out[i].plane = local_planes_[i];
    return out;
}

int Brush::find_face(const Plane& plane) const {
    for (std::size_t i = 0; i < faces_.size(); ++i)
        if (same_plane(faces_[i].plane, plane)) return static_cast<int>(i);
    return -1;
}

} // namespace ks::brush
