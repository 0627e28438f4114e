#pragma once
// The forward renderer the runtime, the game and the editor call: frustum-culls mesh instances, groups
// repeats into instanced draws (nearest first, so llvmpipe's early depth test skips hidden fragments),
// picks the lights that reach each draw, renders the sun's shadow map only when a shadow caster moved,
// then particles (additive, or alpha-blended back to front), debug lines and the first-person view model.
#include "core/result.h"
#include "render/contact_shadows.h"
#include "render/debug_draw.h"
#include "render/gpu_mesh.h"
#include "render/occlusion.h"
#include "render/particles.h"
#include "render/render_target.h"
#include "render/renderer_settings.h"
#include "render/scene.h"
#include "render/shader_library.h"
#include "render/shader_program.h"
#include "render/shaders.h"
#include "render/view_model_layer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace ks::render {

class TextureCache;

struct ViewModel {
    std::vector<MeshInstance> instances; // in camera space (x right, y up, -z forward)
    float fov_y = radians(50.0f);
};

struct SceneFrame {
    geometry::Camera camera;
    Environment environment;
    const std::vector<MeshInstance>* instances = nullptr;
    const std::vector<Light>* lights = nullptr;
    const std::vector<const ParticleEmitter*>* particles = nullptr;
    const DebugDraw* debug = nullptr;
    const ViewModel* view_model = nullptr;
    // What moves (robots, gas cylinders, pickups, the player's rifle): each darkens its floor from the lights
    // that reach it (contact_shadows.h). nullptr: none.
    const std::vector<ShadowCaster>* shadow_casters = nullptr;
    int width = 1280, height = 720;
};

class SceneRenderer {
  public:
    static Result<std::unique_ptr<SceneRenderer>> create(TextureCache& textures,
                                                         RendererSettings settings = {});
    ~SceneRenderer();

    // Draws into the framebuffer bound now (viewport = frame.width x frame.height).
    FrameStats render(const SceneFrame& frame);
    void invalidate_shadows() { shadow_hash_ = 0; }
    // The settings with Auto values resolved (quality, render_scale, shader_hot_reload).
    const RendererSettings& settings() const { return settings_; }
    // What a game's options screen changes at run time: quality (Auto re-resolves from the GL renderer)
    // and the 3D render scale (clamped to 0.25..1; 0 = automatic).
    void set_quality(RenderQuality quality);
    RenderQuality quality() const { return settings_.quality; }
    void set_render_scale(float scale);
    float render_scale() const { return settings_.render_scale; }

    // Shader hot reload: render() calls this once per frame when enabled (it checks the files at most
    // once a second); tests call it with force. Returns how many programs were rebuilt.
    int poll_shaders(bool force = false);
    // A program's GL name by its ProgramFiles name ("pbr", "fast", ...), 0 if unknown (tests).
    unsigned program_id(const std::string& name) const;

  private:
    SceneRenderer(TextureCache& textures, RendererSettings settings)
        : textures_(textures), settings_(settings) {}
    Result<void> init();
    void cull_and_batch(const SceneFrame& frame, FrameStats& stats);
    void pick_lights(const SceneFrame& frame, FrameStats& stats);
    void render_shadows(const SceneFrame& frame, FrameStats& stats);
    void draw_batches(const Mat4& view_projection, const Vec3& eye, const SceneFrame& frame,
                      FrameStats& stats, bool view_model);
    void draw_batches_fast(const geometry::Camera& camera, const SceneFrame& frame, FrameStats& stats,
                           bool view_model);
    void upload_lights(const ShaderProgram& program, std::uint32_t light_mask, const SceneFrame& frame);
    // Bits of lights_in_view_ whose range reaches `box`, the nearest `cap`; only Light::dynamic ones when
    // `dynamic_only` (a baked surface's other lights are in its light map).
    std::uint32_t light_mask(const SceneFrame& frame, const geometry::Aabb& box, int cap,
                             bool dynamic_only) const;
    struct Batch;
    void draw_instanced(const Batch& b, FrameStats& stats); // one batch: a draw call and its triangles
    // Face state for a shaded batch: back faces culled for a single-sided material, front faces clockwise
    // for a mirrored instance matrix; reset_face_culling before a pass and after it (no culling, CCW).
    void cull_faces_for(const Batch& b);
    void reset_face_culling();
    bool casts_shadow(const MeshInstance& inst) const {
        // The fast path bakes the level's sun shadows; its shadow map (for models, per vertex) holds only
        // static level geometry, so moving robots never force a redraw.
        return inst.casts_shadow && (!fast_ || inst.lightmap != 0);
    }
    void ensure_scale_target(int width, int height);
    void resolve_settings();
    void draw_particles(const SceneFrame& frame, FrameStats& stats);
    void draw_contact_shadows(const SceneFrame& frame, FrameStats& stats);
    void draw_debug(const SceneFrame& frame, FrameStats& stats);
    void ensure_msaa_target(int width, int height);
    geometry::Camera view_model_camera(const SceneFrame& frame) const;
    void draw_view_model(const SceneFrame& frame, FrameStats& stats);
    // The view model drawn into its layer (ViewModelLayer::begin): Drawn (to composite), Empty (nothing on
    // screen) or Unsupported (the driver cannot make the layer; view_model_msaa is now 0 and the caller draws
    // it aliased).
    enum class LayerState { Empty, Drawn, Unsupported };
    LayerState draw_view_model_into_layer(const SceneFrame& frame, FrameStats& stats);
    std::uint64_t shadow_caster_hash(const std::vector<MeshInstance>& instances) const;
    void upload_instances();

    TextureCache& textures_;
    RendererSettings settings_;
    ShaderProgram pbr_, fast_program_, fast_level_, fast_level_lit_, shadow_, particle_, line_,
        contact_shadow_;
    ShaderProgram fast_model_[kFastModelPrograms]; // fast_model_program(i) at [i]
    std::unique_ptr<ShaderLibrary> shaders_;
    std::string gl_renderer_;
    bool fast_ = false;
    int internal_width_ = 0, internal_height_ = 0;
    RenderTarget scale_target_{{ColourStorage::Renderbuffer, 0}}; // the scene below full resolution
    unsigned fast_sampler_ =
        0;                  // the fast path's colour maps: bilinear between mips, sRGB decoded in the shader
    bool raw_srgb_ = false; // fast_sampler_ skips the sampler's sRGB decode (GL_EXT_texture_sRGB_decode)
    unsigned instance_buffer_ = 0, particle_vao_ = 0, particle_quad_ = 0, particle_buffer_ = 0;
    unsigned line_vao_ = 0, line_buffer_ = 0;
    unsigned contact_vao_ = 0, contact_buffer_ = 0;
    unsigned shadow_fbo_ = 0, shadow_texture_ = 0;
    std::unique_ptr<RenderTarget> msaa_target_; // made for settings_.msaa_samples on first use
    ViewModelLayer view_model_layer_;           // the view model's antialiased layer (view_model_msaa)
    ScreenFootprint view_model_footprint_;      // where the layer is composited, refilled each frame
    std::uint64_t shadow_hash_ = 0;
    int face_culling_ = 0; // the GL state cull_faces_for set: 1 back faces culled, 2 fronts clockwise
    Mat4 shadow_matrix_{1.0f};

    // Per-frame scratch, reused (capacity grows to the largest frame, then stays).
    struct Visible {
        const MeshInstance* instance;
        float distance;
        std::uint32_t light_mask;
        geometry::Aabb bounds;
        unsigned lightmap;     // 0 unless the fast path reads this instance's light map
        bool floor_or_ceiling; // baked, and its box spans the eye's x and z (eye_over_or_under)
        bool mirrored;         // its matrix's determinant is negative
    };
    struct Batch {
        const GpuMesh* mesh;
        const Material* material;
        std::uint32_t light_mask;
        int first, count; // into instance_data_
        unsigned lightmap;
        bool floor_or_ceiling; // drawn after the other batches, left out of the depth pre-pass
        bool mirrored;         // the instances' matrices flip handedness: front faces wind clockwise
    };
    std::vector<Visible> visible_;
    std::vector<OccluderFace> occluder_faces_;
    std::vector<Batch> batches_;
    std::vector<InstanceData> instance_data_;
    std::vector<int> lights_in_view_; // indices into frame.lights
    std::vector<MeshInstance> view_world_;
    struct ParticleVertex {
        Vec4 position_size;
        Vec4 color;
        float rotation;
    };
    std::vector<ParticleVertex> particle_vertices_;
    std::vector<std::pair<float, int>> particle_order_;
    std::vector<float> batch_distance_;
    std::vector<int> order_;
    std::vector<Batch> sorted_batches_, shadow_batches_;
    std::vector<const MeshInstance*> shadow_order_;
    ShadowLights contact_lights_;
    std::vector<ContactShadow> contact_shadows_;
    struct ContactVertex {
        Vec3 position;
        Vec2 ellipse;
        Vec2 darkness_feet;
    };
    std::vector<ContactVertex> contact_vertices_;
    std::unordered_map<std::string, unsigned> sprite_ids_;
};

} // namespace ks::render
