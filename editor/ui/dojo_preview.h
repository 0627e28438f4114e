#pragma once
// The dojo's 3D preview: the posed robot on a tiled floor under two studio lights, orbited by dragging, and
// the onion skin: the poses at the keys before and after the playhead drawn over it, tinted, recomputed when
// either key time or the clips change (never per frame).
#include "anim/rig.h"
#include "anim/rig_binding.h"
#include "render/asset_library.h"
#include "render/debug_draw.h"
#include "render/scene_renderer.h"
#include "ui/dojo_context.h"
#include "ui/dojo_pose_tools.h"
#include "ui/render_target.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace ks::editor::ui {

class DojoPreview {
  public:
    DojoPreview(render::AssetLibrary& assets, render::SceneRenderer& renderer);

    // The robot model (its path holds the rig) and, once its rig is read, the binding of the rig's nodes to
    // the model's; the pose starts at rest.
    const render::Model& model();
    void bind(const anim::Rig& rig);
    // The player's pose into the model's node slots.
    void pose_from(const anim::Player& player);
    const render::ModelPose& pose() const { return pose_; }

    // GL pass: renders the posed robot (and the ghosts) into the preview target, sized for a tab w x h.
    void render(const DojoContext& dojo, float tab_width, float tab_height);
    // The rendered image (drag to orbit, wheel to zoom) with the onion-skin toggle over its corner, the rig
    // and the posing tools over it (dojo_pose_tools.h), the posing bar below it.
    void draw(const DojoContext& dojo, float width, float height);
    DojoPoseTools& pose_tools() { return pose_tools_; }
    const DojoPoseTools& pose_tools() const { return pose_tools_; }
    // The target's size (0 before the first render).
    int target_width() const { return target_.width(); }
    int target_height() const { return target_.height(); }

    bool onion() const { return onion_; }
    void set_onion(bool on) { onion_ = on; }
    int ghost_instances() const { return ghost_instances_; } // drawn in the last render

  private:
    void update_ghosts(const DojoContext& dojo);
    void emit_ghost(const render::ModelPose& ghost, const Vec3& tint, std::size_t main_count);

    render::AssetLibrary& assets_;
    render::SceneRenderer& renderer_;
    const render::Model* model_ = nullptr;
    anim::RigBinding binding_;
    render::ModelPose pose_;
    RenderTarget target_;
    std::vector<Mat4> scratch_;
    std::vector<render::MeshInstance> instances_;
    std::vector<render::Light> lights_;
    std::unique_ptr<render::GpuMesh> floor_;
    const render::Material* floor_material_ = nullptr;
    render::DebugDraw debug_;
    ViewCamera view_; // the last render's camera: the posing tools' rays and projection
    DojoPoseTools pose_tools_;
    float orbit_yaw_ = 0.6f, orbit_pitch_ = 0.25f, orbit_distance_ = 7.0f;
    float width_ = 400, height_ = 300;
    bool orbiting_ = false; // a left drag that began off the rig and the rings

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
