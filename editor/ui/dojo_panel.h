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
// Every edit is one step of the dojo's history through the window-free model (model/dojo_edits.h over
// model/dojo_keys.h, dojo_clips.h, dojo_curves.h); a drag is one step. DojoPanel owns what the parts share
// (the edits, the playback, the selection: dojo_context.h), loads the clip file and the robot's rig, and
// arranges the parts, each an object with its own state: DojoPreview (3D preview, onion skin), DojoTimeline
// (transport, timeline) and the transition tester, DojoEvents (event lane, list, popup), DojoClipList,
// DojoKeyTable, DojoCurveView, DojoBlendGrid and DojoFile (save, reload, changes on disk, the questions).
#include "model/dojo_clipboard.h"
#include "model/dojo_curves.h"
#include "ui/dojo_blend_grid.h"
#include "ui/dojo_clip_list.h"
#include "ui/dojo_context.h"
#include "ui/dojo_curve_view.h"
#include "ui/dojo_events.h"
#include "ui/dojo_file.h"
#include "ui/dojo_gltf_prompt.h"
#include "ui/dojo_key_table.h"
#include "ui/dojo_preview.h"
#include "ui/dojo_timeline.h"
#include "ui/sound_widgets.h"

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ks::editor::ui {

using LogFn = DojoLogFn;

// Where the dojo starts (--dojo-view): the clip shown, the page, the curve's node and channel, the playhead
// (paused there), onion skin.
struct DojoView {
    std::string clip; // empty: the file's first clip
    DojoPage page = DojoPage::Keys;
    std::string node; // the curve view's node (empty: the first the clip keys), selected in the preview
    CurveChannel channel = CurveChannel::RotX;
    double time = -1.0; // >= 0: paused at this many seconds
    bool onion = false;
    int robot = 0; // > 0: the level robot with this id plays the clip in the level tab (preview in context)
    std::string blend_from, blend_to; // a blend cell selected (its transition plays in the tester)
    int key = 0; // > 0: key N selected (the key table's, and the graph's on the channel changing most)
};
// Parses "clip=shooting,page=curves,node=arm_r,channel=rot.z,key=1,time=0.25,onion=1"; the error names the
// unknown key or bad value and lists the keys.
Result<DojoView> parse_dojo_view(const std::string& text);

struct DojoSetup {
    std::filesystem::path clip_file; // empty: assets/animations/robot.json
    SoundAudition audition;          // plays the events' sounds as the playhead passes them; may be unset
    LogFn log;                       // the editor's log panel
};

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

    bool dirty() const { return edits_.dirty(); }
    const std::filesystem::path& clip_file() const { return file_.path(); }
    // The dojo's own history (every edit; a drag is one step). Ctrl+Z / Ctrl+Y in the Dojo tab act here.
    // False when there is nothing to undo / redo.
    bool undo();
    bool redo();
    const DojoHistory& history() const { return edits_.history(); }
    // Ctrl+S in the Dojo tab: validates and writes the clip file (asks first when it changed on disk).
    void save();
    // Reads the clip file again; with unsaved edits it asks first.
    void reload();
    // Delete in the Dojo tab: removes the selected event; false when none is selected.
    bool delete_selected();
    // Ctrl+C: the shown key's values; Ctrl+Shift+C: the pose at the playhead. Ctrl+V pastes them into the
    // shown key, Ctrl+Shift+V mirrored left <-> right (model/dojo_clipboard.h); each paste one undo step.
    void copy(bool pose);
    void paste(bool mirror);
    // K in the Dojo tab: keys the nodes turned in the preview (or the selected one) at the playhead.
    void key_pose();
    // The dojo's questions (reload over unsaved edits, save over outside changes, quit with unsaved edits),
    // drawn whichever tab is shown.
    void prompts();
    // Quitting with unsaved clip edits: asks Save / Discard / Cancel. take_quit_answer() returns Go once
    // the edits are saved or dropped, Stay when cancelled (or the save refused), Pending until then.
    using QuitAnswer = DojoQuitAnswer;
    void ask_before_quit() { file_.ask_before_quit(); }
    QuitAnswer take_quit_answer() { return file_.take_quit_answer(); }

    // Preview in context: the level viewport shows a level robot posed by this player. ensure_loaded()
    // reads the clip file if the tab was never shown; tick() advances playback (render() does in the tab).
    void ensure_loaded();
    void tick(double dt);
    const render::ModelPose& pose() const { return preview_.pose(); }
    const std::vector<anim::Clip>& clips() const { return playback_.clips().clips; }
    int clip() const { return playback_.clip(); }
    void show_clip(int index); // plays it from the start (leaves the transition test)
    bool playing() const { return playback_.playing(); }
    void set_playing(bool on) { playback_.set_playing(on); }
    double time() const { return playback_.time(); }

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
        DojoSpots spots{};
        std::map<std::string, Vec2> named;    // DojoContext::named, reported among the spots
        std::vector<std::string> blend_clips; // the blend grid's rows and columns, while it is shown
        std::vector<Vec2> blend_centres;      // its cells' centres, row-major ((0, 0): not drawn)
        std::vector<Vec2> curve_keys;         // the curve view's key handles, while it is shown
        std::size_t curve_selected = 0;       // how many of its keys are selected
        std::vector<Vec2> event_flags;        // the event lane's flags (the event's time on the lane)
        std::string node;                     // the node selected in the preview
        std::size_t pose_edits = 0;           // nodes turned and not keyed yet
        bool auto_key = false;
        bool ik = false;
        std::vector<std::pair<std::string, Vec2>> joints; // the rig's joints on screen
        std::array<Vec2, 3> rings{};                      // a point on each gizmo ring ((0, 0): none)
    };
    Status status() const;

  private:
    void load();
    void advance(double dt); // playback, with the events' sounds as the playhead passes them
    DojoContext context();
    void right_pages(const DojoContext& dojo);
    void pose_status(Status& st) const;

    SoundAudition audition_;
    LogFn log_;
    bool loaded_ = false;
    int auditioned_ = 0; // event sounds played so far (status)
    DojoPlayback playback_;
    DojoEdits edits_;
    DojoSelection selection_;
    DojoSpots spots_{};
    UiSpots named_spots_;

    DojoPreview preview_;
    DojoTimeline timeline_;
    DojoEvents events_;
    DojoClipList clip_list_;
    DojoKeyTable key_table_;
    DojoCurveView curve_view_;
    DojoBlendGrid blend_grid_;
    DojoFile file_;
    DojoGltfPrompt gltf_;
    DojoKeyClipboard clipboard_;
};

} // namespace ks::editor::ui
