#pragma once
// What the player sees of a running game: the level scene with the game's door openings and light states,
// the robots posed from their animation poses, pickups floating and spinning, the gas cylinders, the
// first-person rifle with recoil, and the feedback spawned from the game's events: particles (muzzle
// flashes, impact sparks, explosions), muzzle-flash lights, camera shake, damage-direction arcs for the HUD
// and the red flash of a hit robot (event_particles.h, runtime/model/feedback.h). Positions are interpolated
// between the last two fixed steps. Robots, pickups and cylinders are taken out of the level before the
// LevelScene is built: they move or disappear, so this view draws them from the game's state instead.
#include "anim/rig_binding.h"
#include "game/game.h"
#include "level/level.h"
#include "render/asset_library.h"
#include "render/background_bake.h"
#include "render/level_scene.h"
#include "render/particles.h"
#include "render/scene_renderer.h"
#include "runtime/model/feedback.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace ks::runtime {

// The level without the entities the game owns the look of (robots, pickups, gas cylinders).
level::Level static_part(const level::Level& level);

// The Dojo's test robot: where it stands (from its level entity) and the pose the DojoController gives.
struct DojoDummy {
    Vec3 feet{0.0f};
    float yaw = 0.0f; // the entity's yaw (radians); level::robot_model_matrix turns the model to face it
    const anim::Pose* pose = nullptr;
};

class WorldView {
  public:
    // With scene_options.defer_bake the scene's light map is computed on a worker thread, first at the
    // preview quality, then at scene_options.bake's, each taken over by the first fill() after it is done
    // (the live play-test's scenery edits: the edit shows at once, lit per vertex until the preview).
    static std::unique_ptr<WorldView> build(const level::Level& level, const game::Game& game,
                                            render::AssetLibrary& assets,
                                            const render::LevelSceneOptions& scene_options,
                                            std::function<void()> bake_ready = {});

    // The live play-test rebuilt the game on an edit that left the scenery alone (level/scenery.h): this
    // view goes on drawing its scene and light bake, its particles and feedback, for `game` from now on.
    void follow_game(const game::Game& game);

    // Call before each game step (keeps the previous state for interpolation) and after it (events).
    void before_step(const game::Game& game);
    void after_step(const game::Game& game, float dt);

    // Fills the frame for the game's state at `alpha` between the last two steps.
    void fill(const game::Game& game, float alpha, float fov_degrees, const DojoDummy* dummy,
              render::SceneFrame& frame);
    const geometry::Camera& camera() const { return camera_; }
    bool baking() const { return bake_.running(); } // a deferred light map still being computed
    int live_emitters() const { return static_cast<int>(emitters_.size()); }
    // Damage arcs, camera shake and muzzle lights running now (the HUD draws the arcs).
    const feedback::Feedback& feedback() const { return feedback_; }

  private:
    WorldView() = default;
    void spawn(const render::ParticleParams& params);
    void on_event(const game::Game& game, const game::Event& e);

    std::unique_ptr<render::LevelScene> scene_;
    render::BackgroundBake bake_;       // the light map computed on a worker (defer_bake, background_bake)
    unsigned long long bake_build_ = 0; // 1: a live edit's preview is computing, 2: the full bake
    render::BakeSettings final_bake_;   // a live edit's full bake quality
    // The movers' models with their levels of detail (every level has the full model's nodes), and the level
    // each robot, pickup and cylinder (by its index in the game's lists) and the Dojo's dummy was drawn at
    // last, for the hysteresis of render::pick_model_level.
    const render::ModelLevels* robot_model_ = nullptr;
    const render::ModelLevels* cylinder_model_ = nullptr;
    const render::Model* rifle_ = nullptr;
    const render::ModelLevels* pickup_models_[3] = {nullptr, nullptr, nullptr};
    std::vector<int> robot_lods_, pickup_lods_, cylinder_lods_;
    int dummy_lod_ = 0;
    // The level of `levels` to draw at `root` by the last frame's camera on a `height`-pixel view; `lod`
    // (grown to hold `index`) is updated.
    const render::Model& level_for(const render::ModelLevels& levels, const Mat4& root,
                                   std::vector<int>& lods, std::size_t index, int height);
    anim::RigBinding robot_binding_; // the game's robot rig onto robot_model_'s nodes
    render::ModelPose robot_pose_;

    struct Snapshot {
        Vec3 eye{0.0f};
        float yaw = 0.0f, pitch = 0.0f, roll = 0.0f;
        std::vector<Vec3> robot_feet;
        std::vector<float> robot_yaw;
    };
    void capture(const game::Game& game, Snapshot& s) const;
    Snapshot previous_, current_;
    bool have_snapshot_ = false;

    std::vector<render::MeshInstance> instances_;
    std::vector<render::Light> lights_;
    std::vector<render::ShadowCaster> casters_; // robots, pickups, cylinders, the rifle: contact shadows
    void add_rifle_caster(bool grounded);
    std::vector<Mat4> scratch_;
    render::ViewModel view_model_;
    std::vector<std::unique_ptr<render::ParticleEmitter>> emitters_;
    std::vector<const render::ParticleEmitter*> emitter_list_;
    std::uint64_t next_seed_ = 1;
    feedback::Feedback feedback_;
    float step_dt_ = 1.0f / 120.0f; // the last step's length: how far `alpha` reaches past it
    geometry::Camera camera_;
    double time_ = 0.0;
};

} // namespace ks::runtime
