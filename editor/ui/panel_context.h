#pragma once
// What every panel of the editor window works through: the level document (Editor), the log, the status
// file's spots, the asset library (thumbnails) and the sound audition, plus the few services of the window
// around it (WindowServices). A panel keeps its own state in its own object and reaches nothing else;
// EditorApp owns the panels, arranges them and implements WindowServices (docs/architecture.md, "The editor
// window's panels").
#include "model/editor.h"
#include "render/asset_library.h"
#include "ui/editor_log.h"
#include "ui/sound_widgets.h"
#include "ui/ui_spots.h"
#include "view/link_options.h"
#include "view/view_camera.h"

#include <string>

namespace ks::editor::ui {

// What a panel may ask of the window: the viewport's camera and framing, and the logic widgets that are
// tied to the viewport's pick mode (link_list.cpp, link_pick.cpp, objectives_panel.cpp).
class WindowServices {
  public:
    virtual void focus_selection() = 0;                    // F: the viewport frames the selection
    virtual const ViewCamera& viewport_camera() const = 0; // the active view's camera
    virtual void link_list(const LinkOwner& owner, const std::string& spot) = 0; // spot: "link", ...
    virtual void links_tab() = 0;                                                // the inspector's Links tab
    virtual void objectives_tab() = 0; // the inspector's Objectives tab

  protected:
    ~WindowServices() = default;
};

struct PanelContext {
    Editor& editor;
    EditorLog& log;
    UiSpots& spots;
    render::AssetLibrary& assets;
    const SoundAudition& audition; // may be unset: no Audition buttons
    WindowServices& window;

    void report(const Result<void>& result, const char* what) const { log.report(result, what); }
};

} // namespace ks::editor::ui
