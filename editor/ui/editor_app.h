#pragma once
// The editor window: a fixed ImGui layout (menu bar; outliner left; the inspector's Properties, Links and
// Objectives tabs and validation right; history and log below; the 3D viewport in the middle, or the dojo
// tab) around one Editor session. The panels are objects of their own (inspector.h, outliner.h,
// prefab_palette.h, place_palette.h, bottom_panels.h, logic_panels.h, file_prompts.h, prefab_prompt.h,
// playtest_launcher.h, level_viewport.h, viewport_scene.h, dojo_panel.h) working through a PanelContext
// (panel_context.h) or the narrower part of it they need; EditorApp owns them, arranges them and runs the
// frame (docs/architecture.md, "The editor window's panels"). Panels only present the model and dispatch
// Editor calls; every edit goes through its commands.
#include "model/autosave.h"
#include "model/editor.h"
#include "model/recent_files.h"
#include "render/asset_library.h"
#include "shell/app_shell.h"
#include "ui/about_box.h"
#include "ui/analysis_view.h"
#include "ui/bottom_panels.h"
#include "ui/clip_preview.h"
#include "ui/face_inspector.h"
#include "ui/file_prompts.h"
#include "ui/inspector.h"
#include "ui/level_viewport.h"
#include "ui/logic_panels.h"
#include "ui/model_browser.h"
#include "ui/outliner.h"
#include "ui/panel_context.h"
#include "ui/place_palette.h"
#include "ui/playtest_launcher.h"
#include "ui/prefab_palette.h"
#include "ui/prefab_prompt.h"
#include "ui/sound_widgets.h"
#include "ui/ui_spots.h"
#include "ui/viewport_scene.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace ks::editor::ui {

class DojoPanel;

struct AppOptions {
    std::optional<std::filesystem::path> level;
    bool start_in_dojo = false;
    bool show_navmesh = false;                       // View > Navigation mesh on from the start
    std::optional<std::filesystem::path> run_script; // run inside the window session before the first frame
    std::optional<std::string> camera;               // x,y,z,yaw,pitch (degrees) for the viewport
    std::filesystem::path executable_dir;            // where killswitch (the runtime) is looked for
    std::optional<ViewMode> view;                    // --view top|front|side|perspective
    bool quad_view = false;                          // --view 4up: the 4-up view from the start
    std::optional<std::filesystem::path> report;     // --report: a play-test report to show
    int analysis_runs = 20;                          // --runs: how many runs Analyze plays
    std::optional<InspectorTab> inspector_tab;       // --inspector: the tab shown first
    // --status-file: a JSON snapshot of the session rewritten whenever it changes (status_report.cpp), so
    // tests that drive the window with real input wait on state rather than on time.
    std::optional<std::filesystem::path> status_file;
    // Plays a sound for the inspector's Audition buttons (sound_widgets.h) and the dojo's clip events;
    // unset, the buttons are hidden and the events silent.
    SoundAudition audition;
    std::filesystem::path
        dojo_file; // --dojo-file: the dojo's clip file (default assets/animations/robot.json)
    std::optional<std::string> dojo_view; // --dojo-view: where the dojo starts (ui/dojo_panel.h, DojoView)
    // --gizmo MODE[,local]: the gizmo's mode (move, rotate, scale) and rotation space at start-up.
    std::optional<std::string> gizmo;
    std::optional<LeftTab> left_tab; // --left-tab: the left column's tab shown first
    bool texture_browser = false;    // --textures: the texture browser open for the selection at start-up
};

// Owns the panels (each with its own state, working through a PanelContext), arranges them in the fixed
// layout and runs the frame; it is also the WindowServices the panels may call.
class EditorApp final : private WindowServices {
  public:
    static Result<std::unique_ptr<EditorApp>> create(shell::AppShell& shell, const AppOptions& options);
    ~EditorApp();
    int run();

    void log_line(std::string line, bool error = false) { log_.line(std::move(line), error); }

  private:
    EditorApp(shell::AppShell& shell, const AppOptions& options);
    Result<void> init();
    Result<void> apply_start_ui_options(); // --view, --camera, --4up, --gizmo, --textures

    // frame
    void render_views(const shell::FrameInfo& info);
    void build_ui(const shell::FrameInfo& info);
    bool animating() const; // the shell draws frame after frame while true
    bool poll_background(); // the shell's idle poll; true: something to show
    void handle_shortcuts();
    void update_title();
    void write_status(); // status_report.cpp: each panel writes its own part

    // structure_ui.cpp: groups and prefabs from the viewport, the keys and the Edit menu
    void structure_menu_items(); // the Edit menu's group, prefab and layer items

    // editor_app.cpp: menus and files
    void menu_bar();
    // The dojo's unsaved clip edits are asked about before a Quit goes on to files_.
    void request(PendingAction action, std::filesystem::path path = {});
    void report(const Result<void>& result, const char* what) { log_.report(result, what); }

    // panels.cpp: the left column (palette; Outliner, Layers and Prefabs tabs)
    void outliner_panel(float x, float y, float w, float h);
    PanelContext context();

    // WindowServices: the viewport's camera and framing
    void focus_selection() override { viewport_.focus_selection(); }
    const ViewCamera& viewport_camera() const override { return viewport_.camera(); }

    // WindowServices: the logic widgets live in logic_ (logic_panels.h)
    void links_tab() override { logic_.links_tab(); }
    void link_list(const LinkOwner& owner, const std::string& spot) override {
        logic_.link_list(owner, spot);
    }
    void objectives_tab() override { logic_.objectives_tab(); }

    shell::AppShell& shell_;
    AppOptions options_;
    Editor editor_;
    EditorLog log_; // the Log panel's lines; the model's log goes here too
    RecentFiles recent_;
    Autosaver autosaver_;

    render::AssetLibrary assets_;
    ViewportScene scene_{assets_}; // the renderer, the level scene and the views' targets
    // panels
    PlacePalette palette_;
    Outliner outliner_;
    PrefabPalette prefabs_;
    ModelBrowser models_; // the Models tab
    Inspector inspector_;
    BrushMenu brush_menu_;
    ValidationPanel validation_;
    HistoryPanel history_panel_;
    LogPanel log_panel_;
    LeftTab start_tab_ = LeftTab::Outliner;      // Layers, Prefabs: brought to the front on the next frame
    LeftTab shown_left_tab_ = LeftTab::Outliner; // the status file reports it
    PrefabPrompt prefab_prompt_;                 // Edit > Save selection as prefab...
    bool dojo_tab_ = false;
    std::unique_ptr<DojoPanel> dojo_;
    bool dojo_quit_confirmed_ = false; // the dojo's unsaved clip edits were saved or dropped for quitting
    ClipPreview clip_preview_;         // a dojo clip played on the selected level robot
    std::array<Vec2, 2> menu_spots_{}; // status: the File menu's title and its Quit item (while open)

    // level logic
    float palette_height_ = 1e4f; // the place palette's height when last drawn in full
    UiSpots spots_;               // --status-file: where the logic widgets were drawn this frame
    LogicPanels logic_{editor_, log_, spots_, shell_.window()}; // Links and Objectives tabs, pick mode

    PlayTestLauncher play_{log_, options_.executable_dir}; // Play from start / from camera
    AnalysisView analysis_{[this](const std::string& line, bool error) { log_line(line, error); }};
    LevelViewport viewport_{ViewportContext{editor_, log_, spots_, logic_, analysis_, shell_}, scene_};

    FilePrompts files_{editor_, log_, recent_, [this] { viewport_.set_view(ViewMode::Perspective); }};
    AboutBox about_; // Help > About
    bool close_requested_ = false;
    std::string last_title_;

    // --status-file
    std::uint64_t frame_ = 0;
    std::string last_status_;
};

} // namespace ks::editor::ui
