#pragma once
// The vertex tool, window-free: TrenchBroom's vertex, edge and face modes on the selected brushes. Each mode
// shows handles (a vertex, an edge's midpoint, a face's centre, in world space); clicks select them (alone,
// or added with Shift); a drag moves every selected handle's corners by one delta through
// common/brush/brush_edit.h (move_vertices and its refusal rule), in every selected brush that has a corner
// there, so a vertex shared by several brushes moves in all of them. In vertex mode each edge also shows a
// split handle at its midpoint: dragging it adds a vertex there (add_vertex). A vertex dragged onto another
// vertex of its brush merges into it (remove_vertices), and Delete removes the selected vertices, each brush
// rebuilt as the hull of the rest. The drag is previewed; its release commits the moved brushes as one
// undo step, or is refused with the reason (preview().problem) and changes nothing. The caller snaps the
// delta (view/vertex_handles.h). Tests: tests/editor/test_vertex_tool.cpp.
#include "brush/brush.h"
#include "model/editor.h"
#include "model/tool_preview.h"

#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

enum class VertexMode { vertex, edge, face };
const char* vertex_mode_name(VertexMode mode);

// A handle the tool shows. Those of several selected brushes at one place are one handle.
struct VertexHandle {
    DVec3 at{0.0};
    std::vector<DVec3> corners; // the world vertices it moves: one, an edge's two, a face's
    bool split = false;         // an edge's midpoint in vertex mode: dragging it adds a vertex
};

class VertexTool {
  public:
    VertexMode mode() const { return mode_; }
    void set_mode(VertexMode mode); // drops the selection and any drag
    void cycle_mode();              // vertex, edge, face, vertex...

    // The handles of the selected unlocked brushes in this mode (vertex mode: the split handles after the
    // vertices).
    std::vector<VertexHandle> handles(const Document& doc) const;
    // The handle at `at` (within 1e-6) selected alone, or with `add` toggled. Refused when there is none.
    Result<void> select(const Document& doc, const DVec3& at, bool add);
    void clear_selection() { selected_.clear(); }
    const std::vector<DVec3>& selected() const { return selected_; }

    // Starts a drag at the handle at `at`: an unselected one is selected alone first (with `add`, added); a
    // split handle splits its edge. Refused when there is no handle there.
    Result<void> grab(const Document& doc, const DVec3& at, bool add = false);
    bool dragging() const { return grabbed_.has_value(); }
    // Where the grabbed handle started.
    std::optional<DVec3> grabbed() const { return grabbed_; }
    // The drag so far: the selected handles moved by `delta` (world); the moved brushes or why not.
    void drag(const Document& doc, const DVec3& delta);
    DVec3 delta() const { return delta_; }
    // Ends the drag: the moved brushes as one undo step, the selection following the handles. Refused (the
    // reason, nothing changed, no undo step) when the drag is invalid; nothing happens for a zero drag.
    Result<void> release(Editor& editor);
    void cancel();
    // Delete in vertex mode: the selected vertices removed, each brush rebuilt as the hull of the rest.
    Result<void> remove_selected(Editor& editor);

    // While dragging, the moved brushes' edges; the selected handles' corners; the problem and the hint.
    ToolPreview preview(const Document& doc) const;
    // The brushes the current drag would change (id and new brush in the entity's frame).
    struct Moved {
        int id = 0;
        brush::Brush local;
    };
    const std::vector<Moved>& moved() const { return moved_; }

  private:
    std::vector<DVec3> selected_corners(const Document& doc) const;
    Result<void> commit(Editor& editor, const std::string& name);

    VertexMode mode_ = VertexMode::vertex;
    std::vector<DVec3> selected_; // the selected handles' positions
    std::optional<DVec3> grabbed_;
    bool splitting_ = false;
    std::vector<DVec3>
        corners_; // what the drag moves (world): the selected corners, or the split edge's ends
    DVec3 delta_{0.0};
    std::vector<Moved> moved_;
    std::string problem_;
};

} // namespace ks::editor
