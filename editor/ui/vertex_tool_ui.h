#pragma once
// The vertex tool in the window (docs/editor.md, "Vertex, edge and face editing"), part of the geometry
// tools (geometry_tools_ui.h): the active view's mouse fed to model/tool_vertex.h through
// view/vertex_handles.h (press on a handle: select and drag; Shift: add, Shift-click a selected one drops
// it; press elsewhere: box select), the handles drawn over every view, the mode buttons, the keys (V again:
// the next mode, Delete: remove vertices, Esc: the drag, then the selection) and the status file's part.
#include "model/editor.h"
#include "model/tool_vertex.h"
#include "ui/editor_log.h"
#include "ui/ui_spots.h"
#include "view/vertex_handles.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>

struct ImDrawList;

namespace ks::editor::ui {

class VertexToolUi {
  public:
    VertexTool& tool() { return tool_; }
    const VertexTool& tool() const { return tool_; }
    void reset(); // the tool chosen or left: no drag, no selection
    // The mode buttons (spots tool.vertex_mode.vertex, .edge, .face) after the tool buttons.
    void options(UiSpots& spots);
    void mouse(Editor& editor, EditorLog& log, const ViewCamera& view, Vec2 mouse, bool hovered);
    // V (the next mode), Delete, Esc. True when a key was used.
    bool keys(Editor& editor, EditorLog& log, bool v_pressed);
    void draw(ImDrawList* draw, Vec2 origin, const ViewCamera& view, const Document& doc) const;
    void status(nlohmann::json& tool, const Document& doc) const;
    // The handles on screen in the active view (window pixels), so real-input tests can aim at them.
    void status_on_screen(nlohmann::json& tool, const Document& doc, const ViewCamera& view,
                          Vec2 origin) const;

  private:
    VertexTool tool_;
    VertexDrag drag_;
    std::optional<VertexHandle> hover_;
    std::optional<Vec2> box_from_; // a box select under way (view pixels)
    Vec2 box_to_{0.0f};
    int view_id_ = -1; // which view's pixels box_from_ is in (its mode)
};

} // namespace ks::editor::ui
