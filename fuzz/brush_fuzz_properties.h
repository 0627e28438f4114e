#pragma once
// The brush fuzz target's properties (fuzz/fuzz_brush_ops.cpp), shared with the GCC regression test that
// replays its kept inputs (tests/brush/test_brush_fuzz_regressions.cpp): convex brushes from arbitrary planes
// (near-parallel, near-duplicate, far from the origin, unbounded sets) and CSG on pairs of them. Beyond "no
// sanitizer report": a refused brush says why, a made brush is a closed convex polyhedron on its own planes,
// and subtract/intersect/merge keep volume as they must (A = fragments + A n B; A n B no larger than either;
// the convex union no smaller than either); a brush placed in the world by carrying its geometry
// (brush::placed, as a level places its brush entities) has exactly the faces that deriving again gives
// (transformed), is valid wherever that is, and is valid.
#include "brush/brush_csg.h"
#include "brush/texture_mapping.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace ks::fuzz::brush_properties {

struct Broken {
    std::string what;
};
[[noreturn]] inline void broken(const char* what, std::string_view detail = {}) {
    throw Broken{detail.empty() ? std::string(what) : std::string(what) + ": " + std::string(detail)};
}

using ks::DVec3;
using ks::brush::Brush;
using ks::brush::Face;

struct Bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    int next() { return at < size ? data[at++] : 0; }
    int next_signed() { return static_cast<std::int8_t>(static_cast<std::uint8_t>(next())); }
    int next_short() { return static_cast<std::int16_t>(static_cast<std::uint16_t>(next() | (next() << 8))); }
};

// Whole-number normals (many exactly or nearly parallel) and distances in 1/64 units about `centre`.
inline std::vector<Face> faces_from(Bytes& bytes, int count, const DVec3& centre) {
    std::vector<Face> faces;
    for (int i = 0; i < count; ++i) {
        Face f;
        f.plane.normal = DVec3(bytes.next_signed(), bytes.next_signed(), bytes.next_signed());
        f.plane.distance = bytes.next_short() / 64.0 + glm::dot(f.plane.normal, centre);
        f.attributes.material = i % 2 ? "wall" : "floor";
        faces.push_back(f);
    }
    return faces;
}

inline double size_of(const Brush& b) {
    double s = 1.0;
    for (int a = 0; a < 3; ++a) s = std::max({s, std::abs(b.bounds_min()[a]), std::abs(b.bounds_max()[a])});
    return s;
}

// The tests' audit (tests/brush/brush_checks.h) with a tolerance relative to the brush's place: gross
// errors (wrong topology, a vertex off its plane by more than rounding allows) are findings, rounding is not.
inline void audit(const Brush& b, const char* what) {
    const double tolerance = 1e-7 * size_of(b);
    const auto& v = b.vertices();
    const auto& polys = b.polygons();
    if (b.faces().size() < 4 || polys.size() != b.faces().size() || v.size() < 4)
        broken(what, "fewer than 4 faces or vertices");
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t f = 0; f < polys.size(); ++f) {
        if (polys[f].size() < 3) broken(what, "a face with fewer than 3 vertices");
        for (std::size_t k = 0; k < polys[f].size(); ++k) {
            const int a = polys[f][k], c = polys[f][(k + 1) % polys[f].size()];
            if (std::abs(b.faces()[f].plane.signed_distance(v[a])) > tolerance)
                broken(what, "a vertex off its face's plane");
            ++directed[{a, c}];
        }
    }
    for (const auto& [e, n] : directed)
        if (n != 1 || directed.count({e.second, e.first}) != 1) broken(what, "not a closed surface");
    const long long euler = static_cast<long long>(v.size()) - static_cast<long long>(directed.size() / 2) +
                            static_cast<long long>(polys.size());
    if (euler != 2) broken(what, "Euler characteristic not 2");
    for (const DVec3& p : v) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken(what, "NaN vertex");
        for (const Face& f : b.faces())
            if (f.plane.signed_distance(p) > tolerance) broken(what, "not convex");
    }
    if (!(b.volume() > 0)) broken(what, "no volume");
}

template <class T>
inline bool made(const ks::Result<T>& r) {
    if (!r.ok() && r.error().message.empty()) broken("refused without a message");
    return r.ok();
}

inline void check_csg(const Brush& a, const Brush& b) {
    const double scale = std::max(a.volume(), b.volume());
    auto cut = ks::brush::subtract(a, b);
    if (made(cut)) {
        double sum = cut->removed ? cut->removed->volume() : 0.0;
        for (const Brush& piece : cut->fragments) {
            audit(piece, "subtract: a fragment is not a valid brush");
            sum += piece.volume();
        }
        if (cut->removed) audit(*cut->removed, "subtract: the removed part is not a valid brush");
        if (std::abs(sum - a.volume()) > 1e-6 * scale) broken("subtract lost or made volume");
    }
    auto both = ks::brush::intersect(a, b);
    if (made(both)) {
        audit(*both, "intersect: not a valid brush");
        if (both->volume() > std::min(a.volume(), b.volume()) + 1e-6 * scale)
            broken("intersect larger than an input");
    }
    auto hull = ks::brush::merge(a, b);
    if (made(hull)) {
        audit(*hull, "merge: not a valid brush");
        if (hull->volume() < scale * (1 - 1e-6)) broken("merge smaller than an input");
    }
}

inline double shortest_edge(const Brush& b) {
    double shortest = std::numeric_limits<double>::max();
    for (const ks::brush::Edge& e : b.edges())
        shortest = std::min(shortest, glm::length(b.vertices()[static_cast<std::size_t>(e.v1)] -
                                                  b.vertices()[static_cast<std::size_t>(e.v0)]));
    return shortest;
}

// A level's placement: a turn of whole degrees about the three axes and a move in 1/8 units.
inline void check_placement(const Brush& a, Bytes& bytes) {
    const DVec3 degrees(bytes.next_short() % 360, bytes.next_short() % 360, bytes.next_short() % 360);
    const glm::dmat3 turn = glm::mat3_cast(glm::dquat(glm::radians(degrees)));
    const DVec3 move(bytes.next_short() / 8.0, bytes.next_short() / 8.0, bytes.next_short() / 8.0);
    auto derived = ks::brush::transformed(a, turn, move, ks::brush::TextureLock::on);
    auto carried = ks::brush::placed(a, turn, move);
    (void)made(derived);
    if (!made(carried)) {
        if (derived.ok()) broken("placed refused a placement that deriving again made");
        return;
    }
    audit(*carried, "placed: not a valid brush");
    if (!derived.ok()) return;
    if (!(*carried == *derived)) broken("placed and transformed differ in faces");
    // Deriving again may merge the ends of an edge near the 1e-8 tolerance that carrying keeps (a 5-face
    // brush of 7 corners turned 42 degrees came back with 6; the volumes agreed to 1e-11): both are valid
    // brushes of the same planes. The corners and edges must match only when no edge is that short.
    const double size = glm::length(a.bounds_max() - a.bounds_min());
    if (std::min(shortest_edge(*carried), shortest_edge(*derived)) > 1e-6 * size) {
        if (carried->vertices().size() != derived->vertices().size() ||
            carried->edges().size() != derived->edges().size())
            broken("placed and transformed differ in topology");
    } else {
        // Same planes, both valid: the volumes differ by rounding only. That grows with the brush's place
        // and, for a sliver of near-parallel faces, beyond its own tiny volume (a 0.058-unit sliver 270 units
        // long, 30 000 from the origin, differed by 8e-9): a millionth of the volume or a 1e-9-thick skin
        // over the brush's size squared, whichever is larger.
        const double tolerance =
            std::max(1e-6 * std::max(carried->volume(), derived->volume()), 1e-9 * size * size);
        if (std::abs(carried->volume() - derived->volume()) > tolerance)
            broken("placed and transformed differ in volume");
    }
}

// Every property over one input: empty when they all hold, else the first that broke.
inline std::string check(const std::uint8_t* data, std::size_t size) {
    try {
        Bytes bytes{data, size};
        static const DVec3 kCentres[4] = {DVec3(0.0), DVec3(1000.5, -3.25, 20.0),
                                          DVec3(30000.25, 100.0, -30000.0), DVec3(-60000.0, 0.0, 60000.0)};
        const DVec3 centre = kCentres[bytes.next() % 4];
        const int count_a = 4 + bytes.next() % 9, count_b = 4 + bytes.next() % 9;
        std::vector<Face> faces_a = faces_from(bytes, count_a, centre);
        std::vector<Face> faces_b = faces_from(bytes, count_b, centre);

        auto strict = Brush::from_faces(faces_a, ks::brush::RedundantPlanes::refuse);
        auto a = Brush::from_faces(faces_a, ks::brush::RedundantPlanes::drop);
        if (made(strict)) {
            audit(*strict, "from_faces: not a valid brush");
            if (!a.ok() || !(*a == *strict))
                broken("dropping redundant planes changed a brush that had none");
        }
        auto b = Brush::from_faces(faces_b, ks::brush::RedundantPlanes::drop);
        if (made(a)) audit(*a, "from_faces (drop): not a valid brush");
        if (made(b)) audit(*b, "from_faces (drop): not a valid brush");
        if (a.ok() && b.ok()) check_csg(*a, *b);
        if (a.ok()) check_placement(*a, bytes);
    } catch (const Broken& b) {
        return b.what;
    }
    return {};
}

} // namespace ks::fuzz::brush_properties
