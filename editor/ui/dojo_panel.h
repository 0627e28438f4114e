#pragma once
// The dojo tab for animators. Left: the robot model, lit and textured, posed by anim::Player in its own
// preview (onion-skin ghosts of the previous and next keys on request); play/pause/stop/loop/step/speed; a
// scrubbable timeline with key markers and the clip's events; a transition tester. Right: the clip list
// with its management (new empty or from the pose, duplicate, rename, delete, loop mode), then pages for
// the selected key's table, the curve view, the blend grid and the event list; Save (validated, atomic) and
// Reload of the clip file (assets/animations/robot.json unless --dojo-file names another), with a notice
// when it changes outside the editor. The same player poses a level robot in the level viewport (preview
// in context, EditorApp::clip_preview_overlay).
//
// Every edit is one step of the dojo's history through the window-free model (model/dojo_keys.h,
// model/dojo_clips.h, model/dojo_curves.h); a drag is one step. The class is split by job:
// dojo_panel.cpp (loading, playback, history, layout), dojo_preview.cpp (3D preview, onion skin),
// dojo_timeline.cpp (transport, timeline), dojo_events.cpp (event markers and list), dojo_clip_list.cpp
// (clip management), dojo_key_table.cpp (the key's table), dojo_curve_view.cpp, dojo_blend_grid.cpp,
// dojo_transition.cpp (the transition tester), dojo_file.cpp (save, reload, changes on disk).
#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rig_binding.h"
#include "model/disk_fingerprint.h"
#include "model/dojo_clips.h"
#include "model/dojo_curves.h"
#include "model/dojo_keys.h"
#include "model/dojo_playback.h"
#include "render/asset_library.h"
#include "render/debug_draw.h"
#include "render/scene_renderer.h"
#include "ui/render_target.h"
#include "ui/sound_widgets.h"

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ks::editor::ui {

using LogFn = std::function<void(const std::string&, bool error)>;

// The right-hand pages of the dojo tab.
enum class DojoPage : std::uint8_t { Keys, Curves, Blends, Events, Count };

// Where the dojo starts (--dojo-view): the clip shown, the page, the curve's node and channel, the playhead
// (paused there), onion skin.
struct DojoView {
    std::string clip; // empty: the file's first clip
    DojoPage page = DojoPage::Keys;
    std::string node; // the curve view's node (empty: the first the clip keys)
    CurveChannel channel = CurveChannel::RotX;
    double time = -1.0; // >= 0: paused at this many seconds
    bool onion = false;
    int robot = 0; // > 0: the level robot with this id plays the clip in the level tab (preview in context)
    std::string blend_from, blend_to; // a blend cell selected (its transition plays in the tester)
};
// Parses "clip=shooting,page=curves,node=arm_r,channel=rot.z,time=0.25,onion=1"; the error names the
// unknown key or bad value and lists the keys.
Result<DojoView> parse_dojo_view(const std::string& text);

struct DojoSetup {
    std::filesystem::path clip_file; // empty: assets/animations/robot.json
    SoundAudition audition;          // plays the events' sounds as the playhead passes them; may be unset
    LogFn log;                       // the editor's log panel
};

// Places the status file reports (window pixels), for tests that click them.
enum class DojoSpot : std::uint8_t {
    AddKey,
    DuplicateKey,
    NewClip,
    ClipNameField,
    ClipDialogOk,
    PageKeys,
    PageCurves,
    PageBlends,
    PageEvents,
    Save,
    Reload,
    ReloadNotice,
    AddEvent,
    QuitCancel,
    QuitDiscard,
    Count
};
const char* dojo_spot_name(DojoSpot spot);

class DojoPanel {
  public:
    DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer, DojoSetup setup);

    // GL pass (before ImGui): advances playback by dt and renders the posed robot into the preview target
    // for a tab of w x h.
    void render(float width, float height, double dt);
    // Before the frame's ImGui calls: forgets where things were drawn last frame (the status file's spots).
    void begin_frame();
    // The ImGui tab itself, at (x, y) with size w x h.
    void panel(float x, float y, float width, float height);
    // Applies a start view (--dojo-view); an unknown clip or node is logged and the default kept.
    void apply_view(const DojoView& view);

    bool dirty() const { return dirty_; }
    const std::filesystem::path& clip_file() const { return clip_file_; }
    // The dojo's own history (every edit; a drag is one step). Ctrl+Z / Ctrl+Y in the Dojo tab act here.
    // False when there is nothing to undo / redo.
    bool undo();
    bool redo();
    const DojoHistory& history() const { return history_; }
    // Ctrl+S in the Dojo tab: validates and writes the clip file (asks first when it changed on disk).
    void save();
    // Reads the clip file again; with unsaved edits it asks first.
    void reload();
    // Delete in the Dojo tab: removes the selected event; false when none is selected.
    bool delete_selected();
    // The dojo's questions (reload over unsaved edits, save over outside changes, quit with unsaved edits),
    // drawn whichever tab is shown.
    void prompts();
    // Quitting with unsaved clip edits: asks Save / Discard / Cancel. take_quit_answer() returns Go once
    // the edits are saved or dropped, Stay when cancelled (or the save refused), Pending until then.
    enum class QuitAnswer : std::uint8_t { Pending, Go, Stay };
    void ask_before_quit() { ask_quit_ = true; }
    QuitAnswer take_quit_answer();

    // Preview in context: the level viewport shows a level robot posed by this player. ensure_loaded()
    // reads the clip file if the tab was never shown; tick() advances playback (render() does in the tab).
    void ensure_loaded();
    void tick(double dt);
    const render::ModelPose& pose() const { return model_pose_; }
    const std::vector<anim::Clip>& clips() const { return clips_.clips; }
    int clip() const { return clip_; }
    void show_clip(int index); // plays it from the start (leaves the transition test)
    bool playing() const { return playing_; }
    void set_playing(bool on) { playing_ = on; }
    double time() const { return time_; }

    // For the status file (input tests).
    struct Status {
        std::size_t undo = 0, redo = 0;
        std::size_t keys = 0, phases = 0, phase = 0; // keys in the shown phase, the clip's phases, the phase
        std::size_t clips = 0, events = 0;           // the file's clips, the shown clip's events
        std::string clip, page, undo_name, message;  // message: the last refused edit's reason
        bool dirty = false, changed_on_disk = false, onion = false, transition = false;
        int ghosts = 0;                     // onion-skin ghost instances drawn in the last preview
        int auditioned = 0;                 // event sounds played as the playhead passed them
        int blend_from = -1, blend_to = -1; // the selected blend cell
        std::array<Vec2, static_cast<size_t>(DojoSpot::Count)> spots{}; // centres; (0, 0): not drawn
        std::vector<std::string> blend_clips; // the blend grid's rows and columns, while it is shown
        std::vector<Vec2> blend_centres;      // its cells' centres, row-major ((0, 0): not drawn)
        std::vector<Vec2> curve_keys;         // the curve view's key handles, while it is shown
        std::vector<Vec2> event_flags;        // the event lane's flags (the event's time on the lane)
    };
    Status status() const;

  private:
    // dojo_panel.cpp
    void load();
    void recompile(); // after an edit: validate and rebuild the clip set and player
    DojoPlayPlan play_plan() const; // what the transport plays, from the panel's choices
    void restart_at(double seconds);
    void advance(double dt);
    void evaluate_pose();
    void begin_edit(const std::string& name); // records the file before the first change of a drag
    void after_edit();                        // marks dirty and recompiles
    // One undo step through the model: runs `edit` on the file; on success records it and recompiles, on
    // an error keeps the file and shows the model's message.
    template <class Edit>
    bool apply(std::string name, Edit&& edit) {
        auto result = apply_dojo_edit(file_, history_, std::move(name), std::forward<Edit>(edit));
        if (!result) {
            refuse(result.error());
            return false;
        }
        message_.clear();
        after_edit();
        return true;
    }
    void refuse(const Error& error);
    void mark(DojoSpot spot); // the last item's centre into spots_
    double clip_time() const; // the playhead within the shown clip (a loop's pass)
    const anim::ClipDef* shown_def() const;
    void right_pages();

    // dojo_preview.cpp
    void draw_preview_image(float w, float h);
    void update_ghosts();
    void emit_ghost(const render::ModelPose& ghost, const Vec3& tint, std::size_t main_count);

    // dojo_timeline.cpp
    void transport();
    void timeline(float width);
    double timeline_length() const;

    // dojo_events.cpp
    void event_lane(Vec2 origin, float width, float height, double length);
    void event_list();
    void add_event_popup();
    void open_add_event(double seconds);

    // dojo_clip_list.cpp
    void clip_toolbar();
    void clip_list();
    void loop_row();
    void clip_dialog();
    void open_clip_dialog(int kind);

    // dojo_transition.cpp
    void transition_tester();
    void test_transition(int from, int to); // loops from -> to with the file's blend time

    // dojo_key_table.cpp
    void key_table();
    bool phase_timing(anim::PhaseDef& phase);
    bool target_rows(anim::PhaseDef& phase, std::string& remove_node);
    bool add_key_row();
    bool phase_buttons(); // Duplicate / Remove / Earlier / Later for the shown key (phase)

    // dojo_curve_view.cpp
    void curve_view();
    void curve_picker();
    bool refresh_curve(int samples);
    void fit_curve_axes();
    void curve_drag(std::size_t key, double time, double value, bool shift);

    // dojo_blend_grid.cpp
    void blend_grid();
    void blend_cell(std::size_t from, std::size_t to, const BlendCell& cell, float width);
    void blend_details(const BlendGrid& grid);

    // dojo_file.cpp
    void file_row();
    void watch_disk();
    void quit_prompt();
    void write_file();
    void remember_disk();

    render::AssetLibrary& assets_;
    render::SceneRenderer& renderer_;
    std::filesystem::path clip_file_;
    SoundAudition audition_;
    bool event_sounds_ = true; // the transport's Sounds toggle: play events' sounds as the playhead passes
    int auditioned_ = 0;       // event sounds played so far (status)
    LogFn log_;
    const render::Model* model_ = nullptr;

    anim::AnimationFile file_;
    std::vector<anim::Issue> issues_;
    std::string compile_error_;
    std::string message_;      // the last refused edit's reason, shown until the next edit succeeds
    anim::Rig rig_;            // the robot model's, from its glTF
    anim::RigBinding binding_; // rig_ onto model_'s nodes
    anim::ClipSet clips_;
    std::unique_ptr<anim::Player> player_;
    std::uint64_t revision_ = 0; // counts recompiles: cached ghosts and curves follow it
    bool loaded_ = false;
    bool dirty_ = false;
    DojoHistory history_;
    bool edit_open_ = false; // a drag in progress (already recorded)
    int add_node_ = 0;       // the "Add key" combo's choice among the unkeyed nodes
    std::array<Vec2, static_cast<size_t>(DojoSpot::Count)> spots_{};

    int clip_ = 0;
    bool playing_ = true;
    bool loop_ = true;
    float speed_ = 1.0f;
    double time_ = 0.0; // seconds into the clip (or into the transition test)
    int selected_phase_ = 0;
    DojoPage page_ = DojoPage::Keys;
    bool page_requested_ = false; // select page_'s tab on the next frame

    bool transition_mode_ = false;
    int from_clip_ = 0, to_clip_ = 0;
    float switch_time_ = 0.5f, blend_time_ = 0.2f;

    // Clip management: the New / Rename dialog.
    enum ClipDialog : int { kNoDialog, kNewEmpty, kNewFromPose, kRename };
    int clip_dialog_ = kNoDialog;
    bool open_dialog_ = false;
    char clip_name_[64] = {};

    // Events: the selected one, the drag in progress, the Add event popup's fields.
    int selected_event_ = -1;
    bool event_drag_ = false, event_drag_moved_ = false; // a flag on the lane held / moved since pressed
    int editing_event_ = -1;                             // the Events page row whose time is being dragged
    double editing_event_time_ = 0.0;
    bool open_add_event_ = false;
    double add_event_time_ = 0.0;
    char event_name_[64] = {};
    std::string event_sound_;
    std::vector<std::string> sound_names_; // offered by the sound lists (sound_widgets.h)

    // Curve view: node and channel, the sampled curve (cached), the key being dragged.
    int curve_node_ = -1; // index into file_.rig
    CurveChannel curve_channel_ = CurveChannel::RotX;
    ClipCurve curve_;
    std::string curve_error_;
    struct CurveKeyStamp {
        std::uint64_t revision = ~0ull;
        int clip = -1, node = -1, samples = 0;
        CurveChannel channel = CurveChannel::RotX;
        bool operator==(const CurveKeyStamp&) const = default;
    } curve_stamp_;
    struct CurveDrag {
        bool active = false;
        std::size_t key = 0;
        double time = 0, value = 0, target = 0; // the key at the drag's start
        bool keyed = false;
        anim::AnimationFile origin;            // the file at the drag's start: each frame edits from it
        double t0 = 0, t1 = 1, v0 = 0, v1 = 1; // the axes, frozen while dragging
    } curve_drag_;

    // Blend grid: the selected cell (its transition plays in the tester).
    int blend_from_ = -1, blend_to_ = -1;
    std::vector<Vec2> blend_centres_; // status: each cell's centre this frame, row-major
    std::vector<Vec2> curve_handles_; // status: the curve view's key handles this frame
    std::vector<Vec2> event_flags_;   // status: the event lane's flags this frame

    // The clip file on disk: what it was when loaded or saved, and whether it has changed since.
    DiskFingerprint disk_;
    double next_disk_check_ = 0.0; // ImGui time of the next look at the file
    bool changed_on_disk_ = false;
    bool ask_reload_ = false, ask_overwrite_ = false, ask_quit_ = false;
    QuitAnswer quit_answer_ = QuitAnswer::Pending;

    // Preview
    RenderTarget target_;
    render::ModelPose model_pose_;
    std::vector<Mat4> scratch_;
    std::vector<render::MeshInstance> instances_;
    std::vector<render::Light> lights_;
    std::unique_ptr<render::GpuMesh> floor_;
    const render::Material* floor_material_ = nullptr;
    render::DebugDraw debug_;
    float orbit_yaw_ = 0.6f, orbit_pitch_ = 0.25f, orbit_distance_ = 7.0f;
    float preview_w_ = 400, preview_h_ = 300;

    // Onion skin: the poses at the keys before and after the playhead, recomputed when either key time or
    // the clips change (never per frame).
    bool onion_ = false;
    struct Ghost {
        double time = -1.0;
        std::uint64_t revision = ~0ull;
        int clip = -1;
        render::ModelPose pose;
        bool shown = false;
    };
    std::array<Ghost, 2> ghosts_; // previous key, next key
    int ghost_instances_ = 0;
};

// The preview's share of the tab: the left half, above the transport and timeline.
void dojo_preview_size(float tab_width, float tab_height, float& w, float& h);

} // namespace ks::editor::ui
