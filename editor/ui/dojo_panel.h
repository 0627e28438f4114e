#pragma once
// The dojo tab for animators: the robot model, lit and textured, posed by anim::Player in its own preview
// (onion-skin ghosts of the previous and next keys on request); the clip list; play/pause/stop/loop/step/
// speed; a scrubbable timeline with key markers; the per-phase key table (rotations in degrees, positions,
// duration, easing with its curve drawn); a transition tester (from, to, switch time, blend time); Save to
// the clip file (assets/animations/robot.json unless --dojo-file names another) through anim::clip_io
// (validated, atomic), and Reload of changes made outside. The same player poses a level robot in the level
// viewport (preview in context, EditorApp::clip_preview_overlay).
//
// The class is split by job: dojo_panel.cpp (loading, playback, history, layout), dojo_preview.cpp (the 3D
// preview and onion skin), dojo_timeline.cpp (transport and timeline), dojo_key_table.cpp (the selected
// key's table), dojo_transition.cpp (the transition tester), dojo_file.cpp (save, reload, changes on disk).
#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rig_binding.h"
#include "model/disk_fingerprint.h"
#include "model/dojo_keys.h"
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

// Where the dojo starts (--dojo-view): the clip shown, the playhead, paused or playing, onion skin.
struct DojoView {
    std::string clip;   // empty: the file's first clip
    double time = -1.0; // >= 0: paused at this many seconds
    bool onion = false;
};
// Parses "clip=shooting,time=0.25,onion=1"; the error names the unknown key or bad value and lists the keys.
Result<DojoView> parse_dojo_view(const std::string& text);

class DojoPanel {
  public:
    DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer,
              std::filesystem::path clip_file = {}, SoundAudition audition = {});

    // GL pass (before ImGui): advances playback by dt and renders the posed robot into the preview target
    // for a tab of w x h.
    void render(float width, float height, double dt);
    // The ImGui tab itself, at (x, y) with size w x h.
    void panel(float x, float y, float width, float height, const LogFn& log);
    // Applies a start view (--dojo-view); an unknown clip is logged and the first clip shown.
    void apply_view(const DojoView& view, const LogFn& log);

    bool dirty() const { return dirty_; }
    const std::filesystem::path& clip_file() const { return clip_file_; }
    // The dojo's own history (key add/remove, field edits; a dragged field is one step). Ctrl+Z / Ctrl+Y
    // in the Dojo tab act here. False when there is nothing to undo / redo.
    bool undo();
    bool redo();
    // Ctrl+S in the Dojo tab: validates and writes the clip file (asks first when it changed on disk).
    void save(const LogFn& log);
    // Reads the clip file again; with unsaved edits it asks first.
    void reload(const LogFn& log);

    // Preview in context: the level viewport shows a level robot posed by this player. load() runs first
    // if the tab was never shown; tick() advances playback (the dojo tab's render() does it otherwise).
    void ensure_loaded(const LogFn& log);
    void tick(double dt);
    const render::ModelPose& pose() const { return model_pose_; }
    const std::vector<anim::Clip>& clips() const { return clips_.clips; }
    int clip() const { return clip_; }
    void show_clip(int index); // plays it from the start (leaves the transition test)
    bool playing() const { return playing_; }
    void set_playing(bool on) { playing_ = on; }
    double time() const { return time_; }

    // For the status file (input tests): history depth, keys in the shown phase, the clip's phase count and
    // the shown phase, the Add key and Duplicate key buttons' centres in window pixels (0, 0 before drawn),
    // the clip file's state.
    struct Status {
        std::size_t undo = 0, redo = 0, keys = 0, phases = 0, phase = 0;
        float add_key_x = 0, add_key_y = 0;
        float duplicate_key_x = 0, duplicate_key_y = 0;
        std::size_t clips = 0;
        std::string clip;
        bool dirty = false, changed_on_disk = false, onion = false;
        int ghosts = 0; // onion-skin ghost instances drawn in the last preview
    };
    Status status() const;

  private:
    // dojo_panel.cpp
    void load(const LogFn* log);
    void recompile(); // after an edit: validate and rebuild the clip set and player
    void restart_at(double seconds);
    void advance(double dt);
    void evaluate_pose();
    void begin_edit(const std::string& name); // records the file before the first change of an edit
    void after_edit();                        // marks dirty and recompiles
    void clip_list();

    // dojo_preview.cpp
    void draw_preview_image(float w, float h);
    void update_ghosts();
    void emit_ghost(const render::ModelPose& ghost, const Vec3& tint, std::size_t main_first,
                    std::size_t main_count);

    // dojo_timeline.cpp
    void transport();
    void timeline(float width);
    double timeline_length() const;

    // dojo_transition.cpp
    void transition_tester();
    void test_transition(int from, int to); // loops from -> to with the file's blend time

    // dojo_key_table.cpp
    void key_table(const LogFn& log);
    bool phase_timing(anim::PhaseDef& phase);
    bool target_rows(anim::PhaseDef& phase, std::string& remove_node);
    bool add_key_row(const LogFn& log);
    // Duplicate / Remove / Earlier / Later for the shown key (phase); true when the file changed.
    bool phase_buttons(const LogFn& log);

    // dojo_file.cpp
    void file_row(const LogFn& log);
    void watch_disk();
    void file_prompts(const LogFn& log);
    void write_file(const LogFn& log);
    void remember_disk();

    render::AssetLibrary& assets_;
    render::SceneRenderer& renderer_;
    std::filesystem::path clip_file_;
    SoundAudition audition_;
    const render::Model* model_ = nullptr;

    anim::AnimationFile file_;
    std::vector<anim::Issue> issues_;
    std::string compile_error_;
    anim::Rig rig_;            // the robot model's, from its glTF
    anim::RigBinding binding_; // rig_ onto model_'s nodes
    anim::ClipSet clips_;
    std::unique_ptr<anim::Player> player_;
    std::uint64_t revision_ = 0; // counts recompiles: the onion skin's ghosts follow it
    bool loaded_ = false;
    bool dirty_ = false;
    DojoHistory history_;
    bool edit_open_ = false; // a field drag in progress (already recorded)
    int add_node_ = 0;       // the "Add key" combo's choice among the unkeyed nodes
    float add_key_x_ = 0, add_key_y_ = 0;
    float duplicate_key_x_ = 0, duplicate_key_y_ = 0;

    int clip_ = 0;
    bool playing_ = true;
    bool loop_ = true;
    float speed_ = 1.0f;
    double time_ = 0.0; // seconds into the clip (or into the transition test)
    int selected_phase_ = 0;

    bool transition_mode_ = false;
    int from_clip_ = 0, to_clip_ = 0;
    float switch_time_ = 0.5f, blend_time_ = 0.2f;

    // The clip file on disk: what it was when loaded or saved, and whether it has changed since.
    DiskFingerprint disk_;
    double next_disk_check_ = 0.0; // ImGui time of the next look at the file
    bool changed_on_disk_ = false;
    bool ask_reload_ = false, ask_overwrite_ = false;

    // Preview
    RenderTarget target_;
    render::ModelPose model_pose_;
    std::vector<Mat4> scratch_;
    std::vector<render::MeshInstance> instances_;
    std::vector<render::Light> lights_;
    std::unique_ptr<render::GpuMesh> floor_;
    const render::Material* floor_material_ = nullptr;
    render::DebugDraw debug_;
    float orbit_yaw_ = 0.6f, orbit_pitch_ = 0.25f;
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
