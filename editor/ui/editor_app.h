#pragma once
// The editor window: a fixed ImGui layout (menu bar; outliner left; the inspector's Properties, Links and
// Objectives tabs and validation right; history and log below; the 3D viewport in the middle, or the dojo
// tab) around one Editor session. The panels are objects of their own (inspector.h, outliner.h,
// prefab_palette.h, place_palette.h, bottom_panels.h, logic_panels.h, file_prompts.h, prefab_prompt.h,
// playtest_launcher.h, logic_overlay.h, dojo_panel.h) working through a PanelContext (panel_context.h) or the
// narrower part of it they need; EditorApp owns them, arranges them and runs the frame (docs/architecture.md,
// "The editor window's panels"). Panels only present the model and dispatch Editor calls; every edit goes
// through its commands.
#include "model/autosave.h"
#include "model/editor.h"
#include "model/nav_preview.h"
#include "model/recent_files.h"
#include "render/asset_library.h"
#include "render/debug_draw.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "shell/app_shell.h"
#include "ui/about_box.h"
#include "ui/analysis_view.h"
#include "ui/bottom_panels.h"
#include "ui/clip_preview.h"
#include "ui/face_inspector.h"
#include "ui/file_prompts.h"
#include "ui/gizmo_draw.h"
#include "ui/inspector.h"
#include "ui/logic_overlay.h"
#include "ui/logic_panels.h"
#include "ui/outliner.h"
#include "ui/panel_context.h"
#include "ui/place_palette.h"
#include "ui/playtest_launcher.h"
#include "ui/prefab_palette.h"
#include "ui/prefab_prompt.h"
#include "ui/render_target.h"
#include "ui/sound_widgets.h"
#include "ui/ui_spots.h"
#include "view/link_arrows.h"
#include "view/link_options.h"
#include "view/link_problems.h"
#include "view/patrol_drag.h"
#include "view/picking.h"
#include "view/player_start_marker.h"
#include "view/quad_view.h"
#include "view/sound_marker.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct ImDrawList;

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
};

// What the next viewport click places: an entity type from the palette or a prefab from the Prefabs tab.
struct PlaceTool {
    std::optional<level::EntityType> type;
    std::string prefab; // a prefab's name
    explicit operator bool() const { return type.has_value() || !prefab.empty(); }
    void reset() { type.reset(), prefab.clear(); }
    std::string label() const { return type ? std::string(level::type_name(*type)) : "prefab " + prefab; }
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
    Result<void> apply_start_ui_options(); // --gizmo, --textures

    // frame
    void render_views(const shell::FrameInfo& info);
    void build_ui(const shell::FrameInfo& info);
    bool animating() const; // the shell draws frame after frame while true
    bool poll_background(); // the shell's idle poll; true: something to show
    void handle_shortcuts();
    void update_title();
    void write_status(); // status_report.cpp
    void logic_status(nlohmann::json& status) const;
    void objects_status(nlohmann::json& status) const;
    void structure_status(nlohmann::json& status) const; // groups, layers, prefabs

    // structure_ui.cpp: groups and prefabs from the viewport, the keys and the Edit menu
    void structure_menu_items(); // the Edit menu's group, prefab and layer items
    void draw_open_group_box();  // render pass: the entered group's bounds
    void open_group_hint(ImDrawList* draw, Vec2 origin, Vec2 size, bool pane) const; // "Inside group"

    // editor_app.cpp: menus and files
    void menu_bar();
    // The dojo's unsaved clip edits are asked about before a Quit goes on to files_.
    void request(PendingAction action, std::filesystem::path path = {});
    void report(const Result<void>& result, const char* what) { log_.report(result, what); }

    // viewport.cpp
    void viewport_panel(float x, float y, float w, float h);
    void single_viewport(Vec2 origin, bool& hovered);
    void pane_overlays(ImDrawList* draw, Vec2 origin, bool active);
    void rebuild_scene_if_changed();
    void draw_overlays();
    void draw_navmesh();
    void draw_sound_emitter(const level::Entity& e, bool selected);
    void draw_axis_grid(ImDrawList* draw, Vec2 origin) const;
    void viewport_input(Vec2 origin, bool hovered);
    int pick(const geometry::Ray& ray) const;
    bool shown(const level::Entity& e) const; // not hidden, and not a ceiling while ceilings are off
    Vec3 place_point(const geometry::Ray& ray) const;
    Vec3 selection_pivot() const;
    void focus_selection() override;
    const ViewCamera& viewport_camera() const override { return view_; }
    void set_view(ViewMode mode);
    void level_box(Vec3& lo, Vec3& hi) const; // every entity's bounds (±20 around 0 for an empty level)

    // viewport_panes.cpp: the 4-up view (view/quad_view.h) and the render pass of the level's views
    void render_level_views(int width, int height);
    // view_ into the bound target; with `last_key`, only when the picture would differ from the one it
    // keeps (false: skipped).
    bool render_view(int width, int height, std::uint64_t* last_key = nullptr);
    void quad_viewport(Vec2 origin, Vec2 size);
    void toggle_quad();
    void sync_active_pane(); // view_ is the active pane's camera between frames: write it back
    void panes_status(nlohmann::json& status) const;

    GizmoFrame gizmo_frame() const; // the selection's pivot and the rings' axes in the gizmo's space

    // player_start_ui.cpp: the player start's figure over the level
    void draw_player_start();

    // panels.cpp: the left column (palette; Outliner, Layers and Prefabs tabs), the viewport's tool bar
    void outliner_panel(float x, float y, float w, float h);
    PanelContext context();
    void viewport_toolbar();

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
    std::unique_ptr<render::SceneRenderer> renderer_;
    std::unique_ptr<render::LevelScene> scene_;
    std::uint64_t scene_revision_ = ~0ull;
    bool scene_baked_ = false; // built with the light-map bake requested (not during a continuous edit)
    struct SceneStats {
        unsigned long long builds = 0, bakes = 0; // bakes: builds whose light map was baked
        double last_build_cpu_ms = 0.0;
    } scene_stats_;
    NavPreview nav_preview_;
    std::vector<render::MeshInstance> instances_;
    std::vector<render::Light> lights_;
    render::DebugDraw debug_;
    RenderTarget viewport_target_;
    ViewCamera view_; // the single view's camera; in the 4-up view, the pane's being drawn (between frames:
                      // the active pane's)
    QuadView quad_;
    std::array<RenderTarget, kQuadPanes> pane_targets_;
    std::array<PaneRect, kQuadPanes> pane_rects_{};
    std::array<std::uint64_t, kQuadPanes> pane_keys_{};         // what each pane's picture shows
    std::array<unsigned long long, kQuadPanes> pane_renders_{}; // how often each was drawn (status file)
    std::uint64_t single_key_ = 0;                              // what the single view's picture shows
    PaneRect viewport_area_;                 // the single view's or the four panes' area (window pixels)
    std::optional<geometry::Ray> place_ray_; // the mouse's ray in the active view, while it is hovered
    Overlays overlays_;
    Gizmo gizmo_;
    PatrolDrag patrol_drag_;
    Handle hovered_handle_ = Handle::None;
    Vec2 viewport_origin_{0.0f}, viewport_size_{640.0f, 360.0f};
    bool viewport_hovered_ = false;
    bool flying_ = false;
    float wheel_ = 0.0f;

    // tools
    PlaceTool placing_; // palette or prefab: the next click places one
    bool box_selecting_ = false;
    Vec2 box_start_{0.0f};
    bool click_pending_ = false;

    // panels
    PlacePalette palette_;
    Outliner outliner_;
    PrefabPalette prefabs_;
    Inspector inspector_;
    BrushMenu brush_menu_;
    ValidationPanel validation_;
    HistoryPanel history_panel_;
    LogPanel log_panel_;
    LeftTab start_tab_ = LeftTab::Outliner;      // Layers, Prefabs: brought to the front on the next frame
    LeftTab shown_left_tab_ = LeftTab::Outliner; // the status file reports it
    PrefabPrompt prefab_prompt_;                 // Edit > Save selection as prefab...
    std::vector<MarkerLine> marker_lines_;       // a sound emitter's or the player start's lines, reused
    LogicOverlay logic_overlay_;                 // trigger, spawner and message markers; link arrows
    bool dojo_tab_ = false;
    std::unique_ptr<DojoPanel> dojo_;
    bool dojo_quit_confirmed_ = false; // the dojo's unsaved clip edits were saved or dropped for quitting
    ClipPreview clip_preview_;         // a dojo clip played on the selected level robot
    std::array<Vec2, 2> menu_spots_{}; // status: the File menu's title and its Quit item (while open)

    // level logic
    float palette_height_ = 1e4f; // the place palette's height when last drawn in full
    UiSpots spots_;               // --status-file: where the logic widgets were drawn this frame
    LogicPanels logic_{editor_, log_, spots_, shell_.window()}; // Links and Objectives tabs, pick mode

    FilePrompts files_{editor_, log_, recent_, [this] { set_view(ViewMode::Perspective); }};
    AboutBox about_; // Help > About
    bool close_requested_ = false;
    std::string last_title_;

    PlayTestLauncher play_{log_, options_.executable_dir}; // Play from start / from camera
    AnalysisView analysis_{[this](const std::string& line, bool error) { log_line(line, error); }};

    // --status-file
    std::uint64_t frame_ = 0;
    std::string last_status_;
};

} // namespace ks::editor::ui
