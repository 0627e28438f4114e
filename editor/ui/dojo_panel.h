#pragma once
// The dojo tab for animators: the robot model, lit and textured, posed by anim::Player in its own preview;
// the clip list; play/pause/stop/loop/step/speed; a scrubbable timeline with key markers; the per-phase key
// table (rotations in degrees, positions, duration, easing with its curve drawn); a transition tester (from,
// to, switch time, blend time); and Save to assets/animations/robot.json through anim::clip_io (validated,
// atomic), the file the runtime's Dojo and robots load.
#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rig_binding.h"
#include "model/dojo_keys.h"
#include "render/asset_library.h"
#include "render/debug_draw.h"
#include "render/scene_renderer.h"
#include "ui/render_target.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ks::editor::ui {

using LogFn = std::function<void(const std::string&, bool error)>;

class DojoPanel {
  public:
    DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer,
              std::filesystem::path clip_file = {});

    // GL pass (before ImGui): renders the posed robot into the preview target for a tab of w x h.
    void render(float width, float height, double dt);
    // The ImGui tab itself, at (x, y) with size w x h.
    void panel(float x, float y, float width, float height, const LogFn& log);

    bool dirty() const { return dirty_; }
    // The dojo's own history (key add/remove, field edits; a dragged field is one step). Ctrl+Z / Ctrl+Y
    // in the Dojo tab act here. False when there is nothing to undo / redo.
    bool undo();
    bool redo();
    // For the status file (input tests): history depth, keys in the shown phase, the clip's phase count and
    // the shown phase, the Add key and Duplicate key buttons' centres in window pixels (0, 0 before drawn).
    struct Status {
        std::size_t undo = 0, redo = 0, keys = 0, phases = 0, phase = 0;
        float add_key_x = 0, add_key_y = 0;
        float duplicate_key_x = 0, duplicate_key_y = 0;
    };
    Status status() const;

  private:
    void load(const LogFn* log);
    void recompile(); // after an edit: validate and rebuild the clip set and player
    void restart_at(double seconds);
    void evaluate_pose();
    void timeline(float width);
    void key_table(const LogFn& log);
    bool phase_timing(anim::PhaseDef& phase);
    bool target_rows(anim::PhaseDef& phase, std::string& remove_node);
    bool add_key_row(const LogFn& log);
    void save_row(const LogFn& log);
    // Duplicate / Remove / Earlier / Later for the shown key (phase); true when the file changed.
    bool phase_buttons(const LogFn& log);
    void transition_tester();
    void curve(const anim::Ease& ease, float size);
    void begin_edit(const std::string& name); // records the file before the first change of an edit

    render::AssetLibrary& assets_;
    render::SceneRenderer& renderer_;
    std::filesystem::path clip_file_;
    const render::Model* model_ = nullptr;

    anim::AnimationFile file_;
    std::vector<anim::Issue> issues_;
    std::string compile_error_;
    anim::Rig rig_;            // the robot model's, from its glTF
    anim::RigBinding binding_; // rig_ onto model_'s nodes
    anim::ClipSet clips_;
    std::unique_ptr<anim::Player> player_;
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
};

// The preview's share of the tab: the left half, above the transport and timeline.
void dojo_preview_size(float tab_width, float tab_height, float& w, float& h);

} // namespace ks::editor::ui
