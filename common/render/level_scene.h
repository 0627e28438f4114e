#pragma once
// Turns a ks::level::Level into what the SceneRenderer draws: level geometry (walls, floors, ceilings,
// stairs as box brushes, and brush entities) as world-space brush meshes, one per entity and material
// (brush_mesh.h), props as model instances (doors, lights, robots, pickups, cylinders, the control panel)
// and the lights. Door openings and light switches are
// state the game sets; emit() writes the current frame's instances and lights into reused vectors.
#include "level/level.h"
#include "render/asset_library.h"
#include "render/contact_shadows.h"
#include "render/gpu_mesh.h"
#include "render/light_bake.h"
#include "render/lightmap_texture.h"
#include "render/renderer_settings.h"
#include "render/scene.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace ks::render {

struct LightBakeSlot; // light_bake_cache.h

// A wall's, floor's or stair's geometry in world space, drawn from box brushes (exposed for tests: no GL).
MeshData build_surface_mesh(const level::Entity& entity);
// Linear colour from a level's sRGB colour.
Vec3 to_linear(const level::Color& c);
Environment environment_from_settings(const level::Settings& settings);
// The neutral studio light of model previews (the runtime's turntable, the editor's dojo).
Environment preview_environment(float fog_density);
// The player's eye at the level start: feet + 3 (the reference's eye height), looking along the start yaw.
geometry::Camera player_start_camera(const level::Level& level, float aspect);

// What a level scene prepares for the renderer that draws it.
struct LevelSceneOptions {
    // Bake the light map that the fast path reads. false: the fast path lights the level geometry per vertex
    // (the editor's cheap rebuilds while a drag is in progress; a renderer on the full path never reads it).
    bool bake_light_map = true;
    bool lightmap_float = false;              // the texture's encoding: RendererSettings::lightmap_float
    BakeSettings bake = BakeSettings::full(); // the bake's quality (light_bake.h)
    // Lay the light map out (the meshes' light-map coordinates) but leave computing it to the caller, who
    // computes a copy of light_bake() on another thread and hands it back with adopt_light_bake() (the
    // editor's preview bake). Until then the level geometry is lit per vertex.
    bool defer_bake = false;
    // Read the bake from the user's disk cache and write it there (light_bake_cache.h): the game, whose
    // levels are baked again at every launch; not the editor, whose every edit would leave an entry.
    bool cache_bake = false;
    // With cache_bake, when the bake is not in the cache: compute the direct light only (a tenth of the full
    // bake's time) and leave the bake at `bake`'s quality to the caller, who runs it on a worker thread
    // (render/background_bake.h: pending_bake(), pending_bake_store()); the game's interactive start, which
    // then shows its first frame without waiting for the bounce and the occlusion.
    bool background_bake = false;
};
// The options that match a renderer's resolved settings: bake only for the fast path, same encoding.
LevelSceneOptions level_scene_options(const RendererSettings& resolved);

class LevelScene {
  public:
    static std::unique_ptr<LevelScene> build(const level::Level& level, AssetLibrary& assets,
                                             const LevelSceneOptions& options = {});

    void set_light_on(int entity_id, bool on);
    void set_door_open(int entity_id, float fraction); // 0 closed .. 1 open
    // Draws a prop (a robot) in `pose`, its model's node locals, instead of its rest pose: the editor's clip
    // preview in context. nullptr: the rest pose again. The pose must outlive the emit() calls that use it.
    void set_pose(int entity_id, const ModelPose* pose);
    // Door leaves are emitted as occluders (MeshInstance::occluder) unless this is off (benchmarks).
    void set_doors_occlude(bool on) { doors_occlude_ = on; }
    // The view the next emit() draws for: every prop's model (a designer's, or a shipped one with the asset
    // generator's levels) is drawn at the level of detail its size there asks for (pick_model_level, on
    // `viewport_height` pixels; each prop remembers its level for the hysteresis). Without a view, or with
    // LODs off (benchmarks), every model is drawn in full.
    void set_view(const geometry::Camera& camera, int viewport_height);
    void set_model_lods(bool on) { model_lods_ = on; }
    // The level of detail prop `entity_id` was last emitted at (0: full; -1: no such prop).
    int model_lod(int entity_id) const;
    // How many model props the last emit() drew at a coarser level than their full model.
    int coarse_model_count() const;
    // Clears and fills `instances` and `lights` for the current state, and `casters` (when given) with the
    // contact shadow casters of the props the game moves (robots, pickups, gas cylinders).
    void emit(std::vector<MeshInstance>& instances, std::vector<Light>& lights,
              std::vector<ShadowCaster>* casters = nullptr);
    const Environment& environment() const { return environment_; }
    const geometry::Aabb& bounds() const { return bounds_; }
    int surface_count() const { return static_cast<int>(surfaces_.size()); }
    // The level geometry's baked light (the fast path's; see light_bake.h) and what baking it cost. Baked
    // when the options ask (level_scene_options: the renderer's quality is Fast); otherwise empty, and a
    // renderer switched to Fast lights the level geometry per vertex.
    const LightBake& light_bake() const { return bake_; }
    // What a deferred bake computes with: light_bake().compute(environment(), bake_lights(), settings).
    const std::vector<Light>& bake_lights() const { return bake_lights_; }
    // Takes over a bake computed from a copy of light_bake() (this scene's layout), keeping the lights'
    // switches; uploaded on the next emit().
    void adopt_light_bake(LightBake bake, const BakeStats& stats);
    const BakeStats& bake_stats() const { return bake_stats_; }
    // The bake left to the caller (LevelSceneOptions::background_bake on a cache miss): its quality, to give
    // BackgroundBake::start; nullopt when there is none.
    const std::optional<BakeSettings>& pending_bake() const { return pending_bake_; }
    // Stores a finished pending bake in the disk cache (BackgroundBake's Done: runs on its worker; it holds
    // nothing of the scene, which may be gone by then).
    std::function<void(const LightBake&, const BakeStats&)> pending_bake_store() const;
    unsigned lightmap_texture() const { return lightmap_.id(); }

  private:
    explicit LevelScene(const LevelSceneOptions& options) : lightmap_(options.lightmap_float) {}
    struct Surface {
        std::unique_ptr<GpuMesh> mesh;
        const Material* material;
        bool casts_shadow;
        bool occluder = false; // a whole axis-aligned box: its bounds are solid (MeshInstance::occluder)
    };
    struct Prop {
        int entity_id = 0;
        level::EntityType type = level::EntityType::Wall;
        const Model* model = nullptr;
        Mat4 root{1.0f};
        bool light_on = true;
        float door_open = 0.0f;
        const ModelPose* pose = nullptr;     // set_pose
        const ModelLevels* levels = nullptr; // its levels of detail (model: the full one)
        int lod = 0;                         // the level emitted last
        float ground = 0.0f;                 // the entity's height: the floor it stands on
        level::DoorProps door;               // for doors: the leaves slide as level::door_leaf_centre says
        Light light;                         // for floor/top lights
        int bake_light = -1;                 // its index in the light bake
    };
    static Prop make_prop(const level::Entity& e, const ModelLevels& levels, const Mat4& root);
    // background_bake: the cached bake, or the direct light now and pending_bake_ set.
    void restore_or_start_bake(const std::vector<BakeSurface>& surfaces, const BakeSettings& settings);
    std::vector<Surface> surfaces_;
    std::vector<Prop> props_;
    Environment environment_;
    geometry::Aabb bounds_ = geometry::Aabb::empty();
    LightBake bake_;
    BakeStats bake_stats_;
    std::vector<Light> bake_lights_;
    std::optional<BakeSettings> pending_bake_;
    std::shared_ptr<const LightBakeSlot> pending_slot_; // where pending_bake_store() stores it
    bool lightmap_stale_ = false;                       // a bake adopted since the last upload
    LightmapTexture lightmap_;
    std::vector<Mat4> scratch_;
    ModelPose pose_;
    bool doors_occlude_ = true;
    bool model_lods_ = true;
    std::optional<geometry::Camera> view_;
    int view_height_ = 0;
    void pick_model_lod(Prop& p) const;
};

} // namespace ks::render
