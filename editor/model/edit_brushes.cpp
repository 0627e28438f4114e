// Brush entities: edit_brushes.h. The geometry is common/brush's; this file turns entities into world
// brushes and the results back into entities, and builds one LevelChange per edit.
#include "model/edit_brushes.h"

#include "brush/brush_build.h"
#include "brush/brush_clip.h"
#include "brush/brush_csg.h"
#include "brush/texture_mapping.h"
#include "level/entity_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace ks::editor {
namespace {
using level::Entity;

std::string brush_label(const Entity& e) {
    return "brush " + std::to_string(e.id) + (e.name.empty() ? "" : " (\"" + e.name + "\")");
}

brush::FaceAttributes look_attributes(const BrushLook& look) {
    brush::FaceAttributes attributes;
    attributes.material = look.material.empty() ? std::string(level::kDefaultBrushMaterial) : look.material;
    return attributes;
}

// A world brush as a new entity standing on the bottom centre of its bounds: its faces move into the
// entity's frame with their mapping (the texture starts at the entity, as for the default brush).
Result<Entity> new_brush_entity(const Document& doc, const brush::Brush& world, const std::string& name) {
    const DVec3 lo = world.bounds_min(), hi = world.bounds_max();
    const DVec3 position{(lo.x + hi.x) * 0.5, lo.y, (lo.z + hi.z) * 0.5};
    auto local = brush::translated(world, -position, brush::TextureLock::off);
    if (!local) return local.error();
    Entity e;
    e.id = doc.level.next_id;
    e.name = name;
    e.position = Vec3(position);
    e.props = level::BrushProps{*local};
    return e;
}

Result<int> add_brush(Editor& editor, Result<brush::Brush> world, const BrushLook& look, const char* what) {
    if (!world)
        return Error(std::string(what) + ": " + world.error().message, Location{}, world.error().hint);
    const Document& doc = editor.doc();
    auto e = new_brush_entity(doc, *world, look.name);
    if (!e) return Error(std::string(what) + ": " + e.error().message, Location{}, e.error().hint);
    auto change = std::make_unique<LevelChange>();
    change->set_name(what);
    change->insertions.push_back({doc.level.entities.size(), *e});
    change->next_id = Change<int>{doc.level.next_id, doc.level.next_id + 1};
    editor.execute(std::move(change), {e->id});
    return e->id;
}

// A world brush in `entity`'s frame, keeping its world mapping.
Result<brush::Brush> in_entity_frame(const Entity& entity, const brush::Brush& world) {
    const glm::dmat3 rotation = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(entity.rotation)));
    const glm::dmat3 inverse = glm::transpose(rotation);
    return brush::transformed(world, inverse, -(inverse * DVec3(entity.position)));
}

// The brush entities an edit works on, with their world brushes.
struct WorldBrush {
    const Entity* entity = nullptr;
    brush::Brush world;
};

Result<std::vector<WorldBrush>> selected_brushes(const Document& doc, const char* what) {
    std::vector<WorldBrush> out;
    for (int id : doc.selection) {
        const Entity* e = doc.level.find(id);
        if (!e || e->type() != level::EntityType::Brush) continue;
        if (doc.locked.contains(id))
            return Error(std::string(what) + ": " + brush_label(*e) + " is locked", Location{},
                         "unlock it first");
        auto world = level::world_brush(*e);
        if (!world) return Error(std::string(what) + ": " + world.error().message);
        out.push_back({e, std::move(*world)});
    }
    if (out.empty())
        return Error(std::string(what) + ": no brush is selected", Location{}, "select brushes first");
    return out;
}

// A box around a brush entity's world brush, without deriving it: the brush's vertices carried into the
// world by the entity's frame. The derived world brush's vertices agree with them to rounding (far below
// kBoundsMargin), so a brush whose box is apart from a cutter's by the margin is apart for brush::subtract
// too, which then returns it whole: skipping it changes nothing.
struct WorldBox {
    DVec3 lo, hi;
};
constexpr double kBoundsMargin = 1e-6;

WorldBox world_box(const Entity& e) {
    const glm::dmat3 rotation = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e.rotation)));
    const DVec3 position(e.position);
    WorldBox box{DVec3(1e300), DVec3(-1e300)};
    for (const DVec3& v : e.as<level::BrushProps>().brush.vertices()) {
        const DVec3 w = rotation * v + position;
        box.lo = glm::min(box.lo, w), box.hi = glm::max(box.hi, w);
    }
    return box;
}

bool apart(const WorldBox& a, const brush::Brush& cutter) {
    for (int k = 0; k < 3; ++k)
        if (a.lo[k] - kBoundsMargin >= cutter.bounds_max()[k] ||
            cutter.bounds_min()[k] >= a.hi[k] + kBoundsMargin)
            return true;
    return false;
}

// The pieces that replace brush entities: the first piece keeps the entity (id, name, frame, layer), the
// others are new entities named after it ("Wall 2", "Wall 3"); `removed` entities go.
struct Replacement {
    const Entity* entity;
    std::vector<brush::Brush> world_pieces;
    std::vector<bool> ceilings{}; // per piece, when the edit decides (hollow's top); empty: the entity's flag
};

Result<void> replace_brushes(Editor& editor, const std::string& name,
                             const std::vector<Replacement>& replacements,
                             const std::unordered_set<int>& removed) {
    const Document& doc = editor.doc();
    auto change = std::make_unique<LevelChange>();
    change->set_name(name);
    int next_id = doc.level.next_id;
    std::vector<int> selection_after;
    std::vector<Entity> added;
    for (const Replacement& r : replacements) {
        for (size_t i = 0; i < r.world_pieces.size(); ++i) {
            auto local = in_entity_frame(*r.entity, r.world_pieces[i]);
            if (!local) return Error(name + ": " + brush_label(*r.entity) + ": " + local.error().message);
            Entity piece = *r.entity;
            piece.as<level::BrushProps>().brush = std::move(*local);
            if (i < r.ceilings.size()) piece.as<level::BrushProps>().ceiling = r.ceilings[i];
            if (i > 0) {
                piece.id = next_id++;
                if (!piece.name.empty()) piece.name += " " + std::to_string(i + 1);
                added.push_back(std::move(piece));
                selection_after.push_back(added.back().id);
                continue;
            }
            if (!(piece == *r.entity)) change->updates.push_back({*r.entity, piece});
            selection_after.push_back(piece.id);
        }
    }
    for (size_t i = 0; i < doc.level.entities.size(); ++i)
        if (removed.contains(doc.level.entities[i].id))
            change->removals.push_back({i, doc.level.entities[i]});
    const size_t first_new = doc.level.entities.size() - change->removals.size();
    for (size_t i = 0; i < added.size(); ++i)
        change->insertions.push_back({first_new + i, std::move(added[i])});
    if (next_id != doc.level.next_id) change->next_id = Change<int>{doc.level.next_id, next_id};
    std::sort(selection_after.begin(), selection_after.end());
    editor.execute(std::move(change), selection_after);
    return ok();
}

// A corner-to-corner box, snapped, with positive size.
Result<std::pair<DVec3, DVec3>> snapped_box(const Document& doc, Vec3 a, Vec3 b, const char* what) {
    if (!is_finite(a) || !is_finite(b)) return Error(std::string(what) + ": corners must be finite numbers");
    const DVec3 sa(doc.grid.snap_point(a)), sb(doc.grid.snap_point(b));
    const DVec3 lo = glm::min(sa, sb), hi = glm::max(sa, sb);
    for (int axis = 0; axis < 3; ++axis)
        if (hi[axis] - lo[axis] <= 0.0)
            return Error(std::string(what) + ": the corners snap to a flat box (no size along " +
                             std::string(1, char('x' + axis)) + ")",
                         Location{}, "give the two corners different coordinates on every axis");
    return std::pair{lo, hi};
}

} // namespace

Result<int> place_box_brush(Editor& editor, Vec3 corner_a, Vec3 corner_b, const BrushLook& look) {
    auto box = snapped_box(editor.doc(), corner_a, corner_b, "Place box brush");
    if (!box) return box.error();
    return add_brush(editor, brush::make_box(box->first, box->second, look_attributes(look)), look,
                     "Place box brush");
}

Result<int> place_extruded_brush(Editor& editor, int axis, float from, float to,
                                 std::span<const glm::vec2> points, const BrushLook& look) {
    constexpr const char* kWhat = "Place extruded brush";
    if (axis < 0 || axis > 2) return Error(std::string(kWhat) + ": the axis must be x, y or z");
    if (points.size() < 3)
        return Error(std::string(kWhat) + ": a polygon needs at least 3 points, got " +
                         std::to_string(points.size()),
                     Location{}, "list the corners of a convex polygon in order");
    if (!std::isfinite(from) || !std::isfinite(to) || from == to)
        return Error(std::string(kWhat) + ": the sweep needs two different, finite ends", Location{},
                     "give where the brush starts and ends along the axis");
    // The two other axes, in the order the points give them.
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    std::vector<DVec3> polygon;
    for (const glm::vec2& p : points) {
        DVec3 q{0.0};
        q[axis] = std::min(from, to);
        q[u] = p.x;
        q[v] = p.y;
        polygon.push_back(q);
    }
    DVec3 direction{0.0};
    direction[axis] = std::abs(double(to) - double(from));
    return add_brush(editor, brush::make_extrusion(polygon, direction, look_attributes(look)), look, kWhat);
}

Result<int> place_ramp_brush(Editor& editor, Vec3 corner_a, Vec3 corner_b, RampRise rise,
                             const BrushLook& look) {
    constexpr const char* kWhat = "Place ramp brush";
    if ((rise.axis != 0 && rise.axis != 2) || (rise.sign != 1 && rise.sign != -1))
        return Error(std::string(kWhat) + ": a ramp rises toward +x, -x, +z or -z");
    auto box = snapped_box(editor.doc(), corner_a, corner_b, kWhat);
    if (!box) return box.error();
    const auto [lo, hi] = *box;
    // The profile in the plane across the ramp (at the low end of the other horizontal axis), swept across.
    const int along = rise.axis, across = rise.axis == 0 ? 2 : 0;
    const double low_end = rise.sign > 0 ? lo[along] : hi[along],
                 high_end = rise.sign > 0 ? hi[along] : lo[along];
    DVec3 p0{0.0}, p1{0.0}, p2{0.0};
    p0[across] = p1[across] = p2[across] = lo[across];
    p0[along] = low_end, p0.y = lo.y;
    p1[along] = high_end, p1.y = lo.y;
    p2[along] = high_end, p2.y = hi.y;
    const DVec3 profile[] = {p0, p1, p2};
    DVec3 direction{0.0};
    direction[across] = hi[across] - lo[across];
    return add_brush(editor, brush::make_extrusion(profile, direction, look_attributes(look)), look, kWhat);
}

Result<void> subtract_selected_brushes(Editor& editor) {
    constexpr const char* kWhat = "Subtract";
    const Document& doc = editor.doc();
    auto cutters = selected_brushes(doc, kWhat);
    if (!cutters) return cutters.error();
    std::unordered_set<int> removed;
    for (const WorldBrush& c : *cutters) removed.insert(c.entity->id);
    // Every other unlocked brush near a cutter, cut by each cutter in turn; brushes apart from every cutter
    // are not taken into the world at all.
    std::vector<Replacement> targets;
    for (const Entity& e : doc.level.entities) {
        if (e.type() != level::EntityType::Brush || removed.contains(e.id) || doc.locked.contains(e.id))
            continue;
        const WorldBox box = world_box(e);
        if (std::all_of(cutters->begin(), cutters->end(),
                        [&](const WorldBrush& c) { return apart(box, c.world); }))
            continue;
        auto world = level::world_brush(e);
        if (!world) return Error(std::string(kWhat) + ": " + world.error().message);
        targets.push_back({&e, {std::move(*world)}});
    }
    std::vector<bool> cut(targets.size(), false);
    for (const WorldBrush& cutter : *cutters) {
        bool overlapped = false;
        for (size_t t = 0; t < targets.size(); ++t) {
            std::vector<brush::Brush> pieces;
            for (const brush::Brush& piece : targets[t].world_pieces) {
                auto result = brush::subtract(piece, cutter.world);
                if (!result)
                    return Error(std::string(kWhat) + ": cutting " + brush_label(*targets[t].entity) +
                                     " with " + brush_label(*cutter.entity) + ": " + result.error().message,
                                 Location{}, result.error().hint);
                if (result->removed) overlapped = true, cut[t] = true;
                for (brush::Brush& f : result->fragments) pieces.push_back(std::move(f));
            }
            targets[t].world_pieces = std::move(pieces);
        }
        if (!overlapped)
            return Error(std::string(kWhat) + ": " + brush_label(*cutter.entity) + " overlaps no other brush",
                         Location{}, "move it into the brush to cut, or deselect it");
    }
    std::vector<Replacement> changed;
    for (size_t t = 0; t < targets.size(); ++t) {
        if (!cut[t]) continue;
        // A brush wholly inside the cutters is removed.
        if (targets[t].world_pieces.empty())
            removed.insert(targets[t].entity->id);
        else
            changed.push_back(std::move(targets[t]));
    }
    return replace_brushes(editor, "Subtract brushes", changed, removed);
}

Result<void> hollow_selected_brushes(Editor& editor, float thickness) {
    constexpr const char* kWhat = "Hollow";
    auto brushes = selected_brushes(editor.doc(), kWhat);
    if (!brushes) return brushes.error();
    std::vector<Replacement> changed;
    for (const WorldBrush& b : *brushes) {
        auto walls = brush::hollow(b.world, thickness);
        if (!walls)
            return Error(std::string(kWhat) + ": " + brush_label(*b.entity) + ": " + walls.error().message,
                         Location{}, "use a thickness below half the brush's smallest size");
        // The piece wholly within `thickness` of the brush's top is its ceiling (hidden with the editor's
        // ceilings, no sun shadow), as a designer hollowing a room wants: the top no longer hides the room
        // in the top view or takes its clicks.
        double top = -std::numeric_limits<double>::infinity();
        for (const DVec3& v : b.world.vertices()) top = std::max(top, v.y);
        std::vector<bool> ceilings;
        for (const brush::Brush& wall : *walls) {
            double low = std::numeric_limits<double>::infinity();
            for (const DVec3& v : wall.vertices()) low = std::min(low, v.y);
            ceilings.push_back(low >= top - double(thickness) - 1e-6);
        }
        changed.push_back({b.entity, std::move(*walls), std::move(ceilings)});
    }
    return replace_brushes(editor, "Hollow brushes", changed, {});
}

Result<void> merge_selected_brushes(Editor& editor) {
    constexpr const char* kWhat = "Merge";
    auto brushes = selected_brushes(editor.doc(), kWhat);
    if (!brushes) return brushes.error();
    if (brushes->size() < 2)
        return Error(std::string(kWhat) + ": select two or more brushes", Location{},
                     "add the brushes to merge");
    brush::Brush merged = brushes->front().world;
    std::unordered_set<int> removed;
    for (size_t i = 1; i < brushes->size(); ++i) {
        auto r = brush::merge(merged, (*brushes)[i].world);
        if (!r)
            return Error(std::string(kWhat) + ": " + brush_label(*brushes->front().entity) + " and " +
                             brush_label(*(*brushes)[i].entity) + " do not make one convex brush",
                         Location{},
                         "merge only brushes whose union is convex (side by side along a whole face)");
        merged = std::move(*r);
        removed.insert((*brushes)[i].entity->id);
    }
    return replace_brushes(editor, "Merge brushes", {{brushes->front().entity, {std::move(merged)}}},
                           removed);
}

Result<void> intersect_selected_brushes(Editor& editor) {
    constexpr const char* kWhat = "Intersect";
    auto brushes = selected_brushes(editor.doc(), kWhat);
    if (!brushes) return brushes.error();
    if (brushes->size() < 2)
        return Error(std::string(kWhat) + ": select two or more brushes", Location{},
                     "add the brushes whose common part to keep");
    std::vector<brush::Brush> worlds;
    for (const WorldBrush& b : *brushes) worlds.push_back(b.world);
    auto common = brush::intersect_all(worlds);
    if (!common) {
        // The refusal names brushes[i]: say which entities those are.
        std::string message = common.error().message;
        for (size_t i = worlds.size(); i-- > 0;) {
            const std::string index = "brushes[" + std::to_string(i) + "]";
            for (size_t at = message.find(index); at != std::string::npos; at = message.find(index))
                message.replace(at, index.size(), brush_label(*(*brushes)[i].entity));
        }
        return Error(std::string(kWhat) + ": " + message, Location{}, common.error().hint);
    }
    std::unordered_set<int> removed;
    for (size_t i = 1; i < brushes->size(); ++i) removed.insert((*brushes)[i].entity->id);
    return replace_brushes(editor, "Intersect brushes", {{brushes->front().entity, {std::move(*common)}}},
                           removed);
}

std::string csg_unavailable(const Document& doc, CsgOp op) {
    int selected = 0;
    for (int id : doc.selection) {
        const Entity* e = doc.level.find(id);
        if (!e || e->type() != level::EntityType::Brush) continue;
        if (doc.locked.contains(id)) return brush_label(*e) + " is locked: unlock it first";
        ++selected;
    }
    if (selected == 0) return "select brushes first";
    if ((op == CsgOp::merge || op == CsgOp::intersect) && selected < 2) return "select two or more brushes";
    if (op == CsgOp::subtract) {
        for (const Entity& e : doc.level.entities)
            if (e.type() == level::EntityType::Brush && !doc.is_selected(e.id) && !doc.locked.contains(e.id))
                return {};
        return "there is no other unlocked brush to cut";
    }
    return {};
}

Result<void> clip_selected_brushes(Editor& editor, Vec3 point, Vec3 normal, ClipKeep keep) {
    constexpr const char* kWhat = "Clip";
    if (!is_finite(point) || !is_finite(normal) || glm::length(normal) < 1e-6f)
        return Error(std::string(kWhat) + ": the plane needs a finite point and a non-zero normal");
    auto brushes = selected_brushes(editor.doc(), kWhat);
    if (!brushes) return brushes.error();
    const DVec3 n = glm::normalize(DVec3(normal));
    const brush::Plane plane{n, glm::dot(n, DVec3(point))};
    std::vector<Replacement> changed;
    for (const WorldBrush& b : *brushes) {
        const brush::FaceAttributes cap = b.world.faces().front().attributes;
        auto split = brush::split(b.world, plane, cap);
        if (!split)
            return Error(std::string(kWhat) + ": " + brush_label(*b.entity) + ": " + split.error().message);
        std::vector<brush::Brush> kept;
        if (keep != ClipKeep::front && split->back) kept.push_back(*split->back);
        if (keep != ClipKeep::back && split->front) kept.push_back(*split->front);
        if (kept.empty())
            return Error(
                std::string(kWhat) + ": the plane leaves nothing of " + brush_label(*b.entity), Location{},
                std::string("it lies wholly ") + (keep == ClipKeep::back ? "in front of" : "behind") +
                    " the plane: keep the other side, or move the plane");
        changed.push_back({b.entity, std::move(kept)});
    }
    return replace_brushes(editor, "Clip brushes", changed, {});
}

} // namespace ks::editor
