// The vertex tool: tool_vertex.h.
#include "model/tool_vertex.h"

#include "model/brush_frame.h"

#include "brush/brush_edit.h"
#include "level/entity_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace ks::editor {
namespace {
constexpr double kSamePlace = 1e-6;

bool same_place(const DVec3& a, const DVec3& b) {
    return std::abs(a.x - b.x) <= kSamePlace && std::abs(a.y - b.y) <= kSamePlace &&
           std::abs(a.z - b.z) <= kSamePlace;
}

bool any_at(const std::vector<DVec3>& points, const DVec3& p) {
    return std::any_of(points.begin(), points.end(), [&](const DVec3& q) { return same_place(p, q); });
}

const brush::Brush& local_of(const level::Entity& e) {
    return e.as<level::BrushProps>().brush;
}

std::string brush_label(const level::Entity& e) {
    return "brush " + std::to_string(e.id) + (e.name.empty() ? "" : " (\"" + e.name + "\")");
}

// The selected brush entities the tool may change.
std::vector<const level::Entity*> editable_brushes(const Document& doc) {
    std::vector<const level::Entity*> out;
    for (int id : doc.selection) {
        const level::Entity* e = doc.level.find(id);
        if (e && e->type() == level::EntityType::Brush && !doc.locked.contains(id)) out.push_back(e);
    }
    return out;
}

// Handles merged by place (one per place and kind), in the order first met.
class HandleSet {
  public:
    explicit HandleSet(std::vector<VertexHandle>& out) : out_(out) {}
    void add(const DVec3& at, std::vector<DVec3> corners, bool split) {
        const std::array<long long, 4> key{std::llround(at.x / kSamePlace), std::llround(at.y / kSamePlace),
                                           std::llround(at.z / kSamePlace), split ? 1 : 0};
        if (!seen_.emplace(key, out_.size()).second) return;
        out_.push_back({at, std::move(corners), split});
    }

  private:
    std::vector<VertexHandle>& out_;
    std::map<std::array<long long, 4>, size_t> seen_;
};

// The local indices of `local`'s vertices at one of the world `corners`.
std::vector<int> vertices_at(const brush::Brush& local, const BrushFrame& frame,
                             const std::vector<DVec3>& corners) {
    std::vector<int> out;
    for (size_t i = 0; i < local.vertices().size(); ++i)
        if (any_at(corners, frame.to_world(local.vertices()[i]))) out.push_back(static_cast<int>(i));
    return out;
}

// A single vertex dragged onto another vertex of its brush merges into it: the brush without it.
std::optional<Result<brush::Brush>> merged_into_neighbour(const brush::Brush& local, int vertex,
                                                          const DVec3& local_delta) {
    const DVec3 target = local.vertices()[static_cast<size_t>(vertex)] + local_delta;
    for (size_t i = 0; i < local.vertices().size(); ++i)
        if (static_cast<int>(i) != vertex && same_place(local.vertices()[i], target)) {
            const int removed[] = {vertex};
            return brush::remove_vertices(local, removed);
        }
    return std::nullopt;
}

// The edge of `local` joining the world points a and b, or -1.
int edge_between(const brush::Brush& local, const BrushFrame& frame, const DVec3& a, const DVec3& b) {
    for (size_t i = 0; i < local.edges().size(); ++i) {
        const DVec3 p = frame.to_world(local.vertices()[static_cast<size_t>(local.edges()[i].v0)]);
        const DVec3 q = frame.to_world(local.vertices()[static_cast<size_t>(local.edges()[i].v1)]);
        if ((same_place(p, a) && same_place(q, b)) || (same_place(p, b) && same_place(q, a)))
            return static_cast<int>(i);
    }
    return -1;
}

Error vertex_error(const std::string& message, const std::string& hint) {
    return Error("Vertex: " + message, Location{}, hint);
}

} // namespace

const char* vertex_mode_name(VertexMode mode) {
    return mode == VertexMode::vertex ? "vertex" : mode == VertexMode::edge ? "edge" : "face";
}

void VertexTool::set_mode(VertexMode mode) {
    mode_ = mode;
    selected_.clear();
    cancel();
}

void VertexTool::cycle_mode() {
    set_mode(mode_ == VertexMode::vertex ? VertexMode::edge
             : mode_ == VertexMode::edge ? VertexMode::face
                                         : VertexMode::vertex);
}

std::vector<VertexHandle> VertexTool::handles(const Document& doc) const {
    std::vector<VertexHandle> out;
    HandleSet set(out);
    std::vector<VertexHandle> splits;
    HandleSet split_set(splits);
    for (const level::Entity* e : editable_brushes(doc)) {
        const BrushFrame frame(*e);
        const brush::Brush& local = local_of(*e);
        std::vector<DVec3> world;
        world.reserve(local.vertices().size());
        for (const DVec3& v : local.vertices()) world.push_back(frame.to_world(v));
        if (mode_ == VertexMode::face) {
            for (const auto& polygon : local.polygons()) {
                std::vector<DVec3> corners;
                DVec3 centre(0.0);
                for (int v : polygon)
                    corners.push_back(world[static_cast<size_t>(v)]), centre += corners.back();
                centre /= static_cast<double>(corners.size()); // before the corners move into the handle
                set.add(centre, std::move(corners), false);
            }
            continue;
        }
        if (mode_ == VertexMode::vertex)
            for (const DVec3& v : world) set.add(v, {v}, false);
        for (const brush::Edge& edge : local.edges()) {
            const DVec3 a = world[static_cast<size_t>(edge.v0)], b = world[static_cast<size_t>(edge.v1)];
            (mode_ == VertexMode::edge ? set : split_set)
                .add((a + b) * 0.5, {a, b}, mode_ == VertexMode::vertex);
        }
    }
    out.insert(out.end(), splits.begin(), splits.end());
    return out;
}

Result<void> VertexTool::select(const Document& doc, const DVec3& at, bool add) {
    const auto all = handles(doc);
    const auto it = std::find_if(all.begin(), all.end(),
                                 [&](const VertexHandle& h) { return !h.split && same_place(h.at, at); });
    if (it == all.end())
        return vertex_error(std::string("there is no ") + vertex_mode_name(mode_) + " handle at that point",
                            "click a handle of a selected brush");
    const auto was = std::find_if(selected_.begin(), selected_.end(),
                                  [&](const DVec3& p) { return same_place(p, it->at); });
    if (!add) selected_.clear();
    if (add && was != selected_.end())
        selected_.erase(was);
    else
        selected_.push_back(it->at);
    return ok();
}

std::vector<DVec3> VertexTool::selected_corners(const Document& doc) const {
    std::vector<DVec3> corners;
    for (const VertexHandle& h : handles(doc))
        if (!h.split && any_at(selected_, h.at))
            for (const DVec3& c : h.corners)
                if (!any_at(corners, c)) corners.push_back(c);
    return corners;
}

Result<void> VertexTool::grab(const Document& doc, const DVec3& at, bool add) {
    cancel();
    problem_.clear();
    for (const VertexHandle& h : handles(doc)) {
        if (!same_place(h.at, at)) continue;
        if (h.split) {
            splitting_ = true;
            corners_ = h.corners;
        } else if (!any_at(selected_, h.at)) {
            if (!add) selected_.clear();
            selected_.push_back(h.at);
        }
        grabbed_ = h.at;
        if (!splitting_) corners_ = selected_corners(doc);
        return ok();
    }
    return vertex_error("there is no handle at that point", "press on a handle of a selected brush");
}

void VertexTool::drag(const Document& doc, const DVec3& delta) {
    if (!grabbed_) return;
    delta_ = delta;
    moved_.clear();
    problem_.clear();
    if (same_place(delta, DVec3(0.0))) return;
    for (const level::Entity* e : editable_brushes(doc)) {
        const BrushFrame frame(*e);
        const brush::Brush& local = local_of(*e);
        std::optional<Result<brush::Brush>> result; // only for the brushes the drag reaches
        if (splitting_) {
            if (edge_between(local, frame, corners_[0], corners_[1]) < 0) continue;
            result = brush::add_vertex(local, frame.to_local(*grabbed_ + delta));
        } else {
            const std::vector<int> moving = vertices_at(local, frame, corners_);
            if (moving.empty()) continue;
            const DVec3 local_delta = frame.local_delta(delta);
            auto merged = mode_ == VertexMode::vertex && moving.size() == 1
                              ? merged_into_neighbour(local, moving.front(), local_delta)
                              : std::nullopt;
            result = merged ? std::move(*merged) : brush::move_vertices(local, moving, local_delta);
        }
        if (!*result) {
            problem_ = brush_label(*e) + ": " + result->error().message;
            moved_.clear();
            return;
        }
        moved_.push_back({e->id, std::move(**result)});
    }
}

Result<void> VertexTool::commit(Editor& editor, const std::string& name) {
    const Document& doc = editor.doc();
    auto change = std::make_unique<LevelChange>();
    change->set_name(name);
    for (const Moved& m : moved_) {
        const level::Entity* e = doc.level.find(m.id);
        if (!e) continue;
        level::Entity after = *e;
        after.as<level::BrushProps>().brush = m.local;
        change->updates.push_back({*e, std::move(after)});
    }
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<void> VertexTool::release(Editor& editor) {
    if (!grabbed_) return ok();
    if (same_place(delta_, DVec3(0.0)) || (moved_.empty() && problem_.empty())) {
        cancel();
        return ok();
    }
    if (!problem_.empty()) {
        const std::string reason = problem_;
        cancel();
        problem_ = reason; // shown until the next drag
        return vertex_error(reason, "drag less far, or another way; nothing was changed");
    }
    const char* name = splitting_                  ? "Split edge"
                       : mode_ == VertexMode::edge ? "Move edges"
                       : mode_ == VertexMode::face ? "Move faces"
                                                   : "Move vertices";
    const DVec3 delta = delta_;
    const DVec3 split_at = *grabbed_ + delta;
    const bool split = splitting_;
    auto committed = commit(editor, name);
    cancel();
    if (!committed) return committed;
    if (split) {
        selected_ = {split_at}; // the new vertex
    } else {
        for (DVec3& p : selected_) p += delta;
        // Handles that merged away (a vertex onto its neighbour) are no longer there.
        const auto now = handles(editor.doc());
        std::erase_if(selected_, [&](const DVec3& p) {
            return std::none_of(now.begin(), now.end(),
                                [&](const VertexHandle& h) { return !h.split && same_place(h.at, p); });
        });
    }
    return ok();
}

void VertexTool::cancel() {
    grabbed_.reset();
    splitting_ = false;
    corners_.clear();
    delta_ = DVec3(0.0);
    moved_.clear();
    problem_.clear();
}

Result<void> VertexTool::remove_selected(Editor& editor) {
    if (mode_ != VertexMode::vertex)
        return vertex_error("only vertices can be removed", "switch to vertex mode (V) and select vertices");
    if (selected_.empty()) return vertex_error("no vertex is selected", "click the vertices to remove");
    cancel();
    for (const level::Entity* e : editable_brushes(editor.doc())) {
        const std::vector<int> gone = vertices_at(local_of(*e), BrushFrame(*e), selected_);
        if (gone.empty()) continue;
        auto result = brush::remove_vertices(local_of(*e), gone);
        if (!result) {
            problem_ = brush_label(*e) + ": " + result.error().message;
            moved_.clear();
            return vertex_error(problem_, result.error().hint);
        }
        moved_.push_back({e->id, std::move(*result)});
    }
    auto committed = commit(editor, "Remove vertices");
    moved_.clear();
    selected_.clear();
    return committed;
}

ToolPreview VertexTool::preview(const Document& doc) const {
    ToolPreview out;
    for (const Moved& m : moved_) {
        const level::Entity* e = doc.level.find(m.id);
        if (!e) continue;
        const BrushFrame frame(*e);
        for (const brush::Edge& edge : m.local.edges())
            out.segments.push_back({frame.to_world(m.local.vertices()[static_cast<size_t>(edge.v0)]),
                                    frame.to_world(m.local.vertices()[static_cast<size_t>(edge.v1)]),
                                    ToolLine::shape});
    }
    if (grabbed_ && !same_place(delta_, DVec3(0.0))) {
        out.segments.push_back({*grabbed_, *grabbed_ + delta_, ToolLine::guide});
        out.labels.push_back({*grabbed_ + delta_, "moved " + length_text(delta_.x) + ", " +
                                                      length_text(delta_.y) + ", " + length_text(delta_.z)});
    }
    out.problem = problem_;
    if (editable_brushes(doc).empty() && out.problem.empty()) out.problem = "no unlocked brush is selected";
    switch (mode_) {
    case VertexMode::vertex:
        out.hint =
            "drag a vertex; Shift adds; a ring splits its edge; onto a neighbour merges; Delete removes";
        break;
    case VertexMode::edge:
        out.hint = "drag an edge's handle; Shift-click adds";
        break;
    case VertexMode::face:
        out.hint = "drag a face's handle; Shift-click adds";
        break;
    }
    return out;
}

} // namespace ks::editor
