#pragma once
// What the level viewport shows over the level (View menu: Overlays) and the lines it draws into each view's
// picture in the render pass (viewport_lines.cpp): the ground grid, selection and collision boxes, structure
// outlines, light ranges, robot radii, patrol routes, sound emitters, logic markers, the player start, the
// navigation mesh (built in the background after edits) and the entered group's box. The ImGui pass's
// overlays (axis grid, link arrows, gizmo) are LevelViewport's (viewport.cpp).
#include "model/editor.h"
#include "model/nav_preview.h"
#include "render/debug_draw.h"
#include "ui/logic_overlay.h"
#include "view/sound_marker.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <vector>

namespace ks::editor::ui {

struct Overlays {
    bool grid = true;
    bool collision = false;
    bool lights = true;
    bool robots = true;
    bool player_start = true;
    bool patrols = false;     // every robot's patrol route; the selected robot's is always shown
    bool sound_radii = false; // every sound emitter's radius; the selected one's is always shown
    bool navmesh = false;     // the robots' navigation mesh (built in the background after edits)
    bool outlines =
        true; // in the axis views: walls, doors and stairs outlined, so the plan reads at a glance
    bool ceilings = false; // off by default: ceilings would hide the rooms from an editor camera above them
    bool links = true;     // arrows for the links between entities (the selection's bright and labelled)

    // Drawn and picked: not hidden, and not a ceiling while ceilings are off.
    bool shows(const Document& doc, const level::Entity& e) const;
};

class ViewportLines {
  public:
    // The lines under a tool's (navigation mesh, grid, entities, player start), for the view `view`.
    void draw(render::DebugDraw& debug, const ViewCamera& view, const Editor& editor,
              const Overlays& overlays, LogicOverlay& logic, bool screenshot);
    void open_group_box(render::DebugDraw& debug, const Editor& editor) const; // over a tool's lines
    bool building() const { return nav_preview_.building(); }            // the navigation mesh is being built
    void status(nlohmann::json& status, const Overlays& overlays) const; // "navmesh"

  private:
    void navmesh(render::DebugDraw& debug, const Editor& editor, bool screenshot);
    void entity(render::DebugDraw& debug, const ViewCamera& view, const Document& doc,
                const Overlays& overlays, const level::Entity& e);
    void sound_emitter(render::DebugDraw& debug, const ViewCamera& view, const level::Entity& e,
                       bool selected, bool all_radii);
    void player_start(render::DebugDraw& debug, const Editor& editor);

    NavPreview nav_preview_;
    std::vector<MarkerLine> marker_lines_; // a sound emitter's or the player start's lines, reused
};

} // namespace ks::editor::ui
