#pragma once
// The geometry tools in the window (docs/editor.md, "Geometry tools"): a bar over the viewport with the Draw,
// Clip, Measure and Vertex buttons and the active tool's options, the keys (B, C, M, V; Esc leaves), the
// viewport's mouse routed to it (snapped points from view/tool_pointer.h), its preview and labels drawn over
// each view, and its state for the status file. The tools themselves are window-free (model/tool_draw.h,
// tool_clip.h, tool_measure.h, tool_vertex.h); this only feeds them and shows what they say (the vertex
// tool through vertex_tool_ui.h).
#include "model/editor.h"
#include "model/tool_clip.h"
#include "model/tool_draw.h"
#include "model/tool_measure.h"
#include "ui/editor_log.h"
#include "ui/ui_spots.h"
#include "ui/vertex_tool_ui.h"
#include "view/tool_pointer.h"

#include <nlohmann/json_fwd.hpp>

struct ImDrawList;

namespace ks::editor::ui {

enum class GeometryTool { none, draw, clip, measure, vertex };

class GeometryToolsUi {
  public:
    GeometryTool active() const { return active_; }
    // Chooses a tool (the same one again, or none, leaves it); what the others were doing is dropped.
    void choose(GeometryTool tool);

    // The tools' bar over the viewport's bottom right (`origin`, `size`: the viewport, window pixels), above
    // its status line: the Draw, Clip, Measure and Vertex buttons (spots tool.draw, .clip, .measure,
    // .vertex), then the active tool's options (shape and height; keep side, match face, Apply) and what it
    // says (problem, hint).
    void bar(Editor& editor, EditorLog& log, Vec2 origin, Vec2 size, UiSpots& spots);
    // The viewport's mouse in the view the mouse works in (`mouse` in its pixels).
    void mouse(Editor& editor, EditorLog& log, const ViewCamera& view, Vec2 mouse, bool hovered,
               const ShownFn& shown);
    // The vertex tool's handles on screen in the active view, for the status file.
    void status_on_screen(nlohmann::json& status, const Document& doc, const ViewCamera& view,
                          Vec2 origin) const;
    // B, C, M, V choose; with a tool active Esc, Enter, Tab, Backspace, [ and ] (the vertex tool: V, Delete).
    // True when a key was used.
    bool keys(Editor& editor, EditorLog& log, bool ctrl);
    // The preview, labels and the point under the mouse over one view at `origin`.
    void draw(ImDrawList* draw, Vec2 origin, const ViewCamera& view, const Document& doc) const;
    void status(nlohmann::json& status, const Document& doc) const;

  private:
    void buttons(UiSpots& spots);
    ToolPreview preview(const Document& doc) const;
    void enter(Editor& editor, EditorLog& log); // Enter: close, extrude or clip
    void draw_mouse(Editor& editor, EditorLog& log, const ViewCamera& view, Vec2 mouse, bool hovered,
                    const ShownFn& shown);

    GeometryTool active_ = GeometryTool::none;
    DrawTool draw_;
    ClipTool clip_;
    MeasureTool measure_;
    VertexToolUi vertex_;
    bool match_face_ = false;        // the next clip click takes the plane of the face under it
    std::optional<ToolPoint> hover_; // the point under the mouse
};

} // namespace ks::editor::ui
