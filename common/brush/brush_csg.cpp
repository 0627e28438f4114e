#include "brush/brush_csg.h"

#include "brush/brush_build.h"
#include "brush/brush_clip.h"

#include <cmath>

namespace ks::brush {
namespace {

bool apart(const Brush& a, const Brush& b) {
    for (int k = 0; k < 3; ++k)
        if (a.bounds_min()[k] >= b.bounds_max()[k] - kOnPlaneEpsilon ||
            b.bounds_min()[k] >= a.bounds_max()[k] - kOnPlaneEpsilon)
            return true;
    return false;
}

} // namespace

Result<Subtraction> subtract(const Brush& a, const Brush& b, CutOrder order) {
    Subtraction out;
    if (apart(a, b)) {
        out.fragments.push_back(a);
        return out;
    }
    Brush rest = a;
    std::vector<bool> used(b.faces().size(), false);
    for (;;) {
        // The plane of B cutting the largest piece off what is left of A (or the first that cuts).
        int best = -1;
        std::optional<Brush> best_front;
        for (std::size_t i = 0; i < b.faces().size(); ++i) {
            if (used[i]) continue;
            const Face& f = b.faces()[i];
            const PlaneReach where = reach(rest, f.plane);
            if (where == PlaneReach::all_in_front) {
                // What is left lies outside B, and A n B lies in what is left: they do not overlap, and the
                // answer is A whole, not the pieces cut so far.
                out.fragments.assign(1, a);
                return out;
            }
            if (where == PlaneReach::all_behind) {
                used[i] = true; // cuts nothing now, nor any smaller piece later
                continue;
            }
            auto front = clip(rest, f.plane, ClipSide::keep_front, f.attributes);
            if (!front) return front.error();
            if (!best_front || front->volume() > best_front->volume())
                best = static_cast<int>(i), best_front = std::move(*front);
            if (order == CutOrder::in_order) break;
        }
        if (best < 0) break;
        const Face& cut = b.faces()[static_cast<std::size_t>(best)];
        auto back = clip(rest, cut.plane, ClipSide::keep_back, cut.attributes);
        if (!back) return back.error();
        used[static_cast<std::size_t>(best)] = true;
        out.fragments.push_back(std::move(*best_front));
        rest = std::move(*back);
    }
    out.removed = std::move(rest);
    return out;
}

Result<Brush> intersect(const Brush& a, const Brush& b) {
    if (apart(a, b))
        return Error("the brushes do not overlap", Location({}, 0, 0, "b"), "move them so that they overlap");
    std::vector<Face> faces = a.anchored_faces();
    for (Face f : b.faces()) {
        f.plane = f.plane.translated(-a.anchor());
        faces.push_back(std::move(f));
    }
    auto both = Brush::from_anchored_faces(a.anchor(), std::move(faces), RedundantPlanes::drop);
    if (!both)
        return Error("the brushes do not overlap in a volume (" + both.error().message + ")",
                     Location({}, 0, 0, "b"), "move them so that they overlap");
    return both;
}

Result<Brush> intersect_all(std::span<const Brush> brushes) {
    auto at = [](std::size_t i) { return Location({}, 0, 0, "brushes[" + std::to_string(i) + "]"); };
    if (brushes.size() < 2)
        return Error("an intersection needs two or more brushes, got " + std::to_string(brushes.size()),
                     Location({}, 0, 0, "brushes"), "select the brushes whose common part to keep");
    // Every pair first, so a refusal names the two that do not meet rather than a partial result.
    for (std::size_t i = 0; i < brushes.size(); ++i)
        for (std::size_t j = i + 1; j < brushes.size(); ++j)
            if (!intersect(brushes[i], brushes[j]))
                return Error("brushes[" + std::to_string(i) + "] and brushes[" + std::to_string(j) +
                                 "] do not overlap in a volume (apart, or only touching)",
                             at(j), "move them so that they overlap, or leave one out");
    std::vector<Face> faces = brushes.front().anchored_faces();
    const DVec3 anchor = brushes.front().anchor();
    for (const Brush& b : brushes.subspan(1))
        for (Face f : b.faces()) {
            f.plane = f.plane.translated(-anchor);
            faces.push_back(std::move(f));
        }
    auto all = Brush::from_anchored_faces(anchor, std::move(faces), RedundantPlanes::drop);
    if (!all)
        return Error("the brushes overlap two by two but have no volume in common (" + all.error().message +
                         ")",
                     at(brushes.size() - 1), "leave out a brush that misses the common part of the others");
    return all;
}

Result<Brush> merge(const Brush& a, const Brush& b) {
    std::vector<DVec3> points = a.vertices();
    points.insert(points.end(), b.vertices().begin(), b.vertices().end());
    const Brush* sources[] = {&a, &b};
    auto hull = make_hull_of(points, sources);
    if (!hull) return hull.error();
    auto common = intersect(a, b);
    const double union_volume = a.volume() + b.volume() - (common ? common->volume() : 0.0);
    if (hull->volume() > union_volume * (1.0 + 1e-9) + 1e-12)
        return Error("the union is not convex (its hull is " + std::to_string(hull->volume() - union_volume) +
                         " cubic units larger)",
                     Location({}, 0, 0, "b"),
                     "merge brushes whose union is convex, such as two halves of a box");
    return hull;
}

Result<std::vector<Brush>> hollow(const Brush& brush, double thickness) {
    if (!(thickness > 0.0) || !std::isfinite(thickness))
        return Error("the wall thickness must be a positive number", Location({}, 0, 0, "thickness"),
                     "give a thickness above 0");
    std::vector<Face> inner = brush.anchored_faces();
    for (Face& f : inner) f.plane.distance -= thickness;
    auto inside = Brush::from_anchored_faces(brush.anchor(), std::move(inner), RedundantPlanes::drop);
    if (!inside)
        return Error("walls " + std::to_string(thickness) + " thick leave no inside",
                     Location({}, 0, 0, "thickness"), "give a thinner wall");
    auto walls = subtract(brush, *inside);
    if (!walls) return walls.error();
    return std::move(walls->fragments);
}

} // namespace ks::brush
