#pragma once
// What a SceneRenderer is asked to do (quality path, resolution, MSAA, shadows, shader folder) and the
// automatic choices made from the GL renderer's name where a setting is left at "automatic".
#include "render/scene.h"
#include "render/shaders.h"

#include <functional>
#include <string>
#include <vector>

namespace ks::render {

// Full: per-pixel PBR for everything (GPUs). Fast (software rasterisers): the level geometry reads its
// baked light map (MeshInstance::lightmap; ambient, sun shadows and every level light), models are lit per
// vertex with the same lights, and the fragment shader is a few texture fetches. Auto picks from the GL
// renderer string like MSAA, or automatic_quality where that is set (KS_RENDER_QUALITY=full|fast).
enum class RenderQuality { Auto, Full, Fast };

inline constexpr float kSoftwareRenderScale = 0.5f;

struct RendererSettings {
    int msaa_samples = 0; // 0: draw straight into the bound framebuffer; 2/4/8: multisampled target
    // The first-person view model's own layer at the target's full resolution, blended over the scene
    // (render/view_model_layer.h) whenever the scene itself is not multisampled at full size: smooth rifle
    // edges at a reduced render scale. 1: one sample per pixel and a silhouette filter (the default: cheap on
    // llvmpipe); 2/4/8: multisampled; 0: drawn into the scene's target, aliased
    // (KS_VIEW_MODEL_MSAA=0|1|2|4|8).
    int view_model_msaa = 1;
    // When the scene is drawn at the target's size without MSAA, the view model's layer is drawn first and
    // its opaque pixels go into the scene's depth buffer at the near plane (ViewModelLayer::
    // write_depth_mask): the scene is not shaded under what the composite covers. Off: the scene is drawn
    // everywhere and the layer over it (the bench's "scene under the rifle" row).
    bool view_model_depth_mask = true;
    // Back faces of single-sided materials (Material::double_sided false: glTF's default, every generated
    // model) culled in the shaded passes; off: every face drawn (the bench's "no back-face culling" row and
    // the test that culling hides nothing).
    bool cull_single_sided = true;
    int shadow_map_size = 2048;
    bool shadows = true;
    // Movers' contact shadows on the floor (SceneFrame::shadow_casters; contact_shadows.h), both paths.
    bool contact_shadows = true;
    bool surface_detail = true; // normal and bump (height) maps; off: the geometric normal only
    int max_lights_per_draw = kMaxLightsPerDraw; // nearest point/spot lights shading each object, 0..8
    RenderQuality quality = RenderQuality::Auto;
    // Fast path: baked surfaces read Material::fast_base_map (base x occlusion) instead of base + ORM maps.
    bool fast_occluded_base = true;
    // Fast path: instances hidden behind an occluder box (MeshInstance::occluder, e.g. a wall) are not
    // drawn: no vertex shading or binning for the robots in the next room.
    bool occlusion_culling = true;
    // Fast path: the baked level geometry (few triangles, most of the screen) is first drawn depth-only,
    // then models and the level are shaded against that depth, so each pixel runs the fragment shader
    // about once (without it, the floor and ceiling are shaded where the walls later cover them).
    bool depth_prepass = true;
    // Fast path: the pre-pass leaves out the baked floors and ceilings the eye stands over or under (a box
    // that spans the eye's x and z): they can hide only what lies beyond their own plane, so they are drawn
    // last instead, against the walls' depth. The pre-pass then costs the walls' pixels, not the whole
    // screen.
    bool prepass_skips_floors = true;
    // Fast path: baked level surfaces use fast_level (two texture lookups, no branches) instead of the
    // general fast shader, whose uniform branches llvmpipe executes on both sides (ORM and emissive lookups
    // on every pixel).
    bool fast_level_shader = true;
    // Fast path: models (robots, props, the rifle) drawn by programs whose ORM and emissive lookups are fixed
    // at compile time (fast_model_program) instead of the general fast shader, which looks up the light map,
    // ORM and emissive maps on every pixel whether the draw has them or not.
    bool fast_model_shaders = true;
    // Fast path: colour maps sample the nearest mip level only (one bilinear lookup; a faint seam runs across
    // floors and ceilings where the level switches). true: blend the two nearest (trilinear): no seam and a
    // little closer to the full path (4.1 vs 4.3/255), for ~0.9 ms median and ~2 ms p99 more per 1280x720
    // frame on llvmpipe, which costs the 60 fps tail (docs/performance.md, "Trilinear mips").
    bool fast_trilinear = false;
    // The 3D scene is drawn at this fraction of the target's width and height, then scaled up (bilinear)
    // into the target, so a HUD drawn afterwards stays sharp. 0: automatic (1 on GPUs,
    // software_render_scale on software rasterisers; automatic_render_scale where that is set).
    float render_scale = 0.0f;
    // The automatic render scale on software rasterisers: the game's half resolution; the editor asks for 1
    // (its viewport is smaller and its one-pixel overlays must stay sharp).
    float software_render_scale = kSoftwareRenderScale;
    // What "automatic" resolves to instead of the GL renderer's choice, where set: the environment's
    // KS_RENDER_QUALITY=full|fast and KS_RENDER_SCALE=0.25..1, for screenshots and measurements. A quality or
    // scale chosen explicitly (an option, a menu) still wins.
    RenderQuality automatic_quality = RenderQuality::Auto; // Auto: from the GL renderer
    float automatic_render_scale = 0.0f;                   // 0: from the GL renderer
    std::string shader_dir; // empty: default_shader_dir() (assets/shaders); KS_SHADER_DIR sets it
    // 1: re-read changed shader files once a second; 0: never; -1: default_shader_hot_reload() (Debug
    // builds). KS_SHADER_HOT_RELOAD=0|1 sets it.
    int shader_hot_reload = -1;
    // The fast path's light map as exact RGB16F instead of sqrt-encoded RGBA8 (KS_LIGHTMAP_FLOAT=1). The
    // level scene that fills the texture and the renderer that decodes it must agree: build scenes with
    // level_scene_options(renderer.settings()).
    bool lightmap_float = false;
};

// Where an environment variable is read from: std::getenv in the executables, a table in tests.
using EnvironmentLookup = std::function<const char*(const char*)>;
// The renderer's environment overrides, parsed in one place: KS_RENDER_QUALITY=full|fast and KS_RENDER_SCALE
// (0.25..1) set automatic_quality and automatic_render_scale; KS_LIGHTMAP_FLOAT=0|1, KS_SHADER_DIR=FOLDER
// and KS_SHADER_HOT_RELOAD=0|1 set lightmap_float, shader_dir and shader_hot_reload.
// A bad value leaves its field as it was and adds a warning naming the variable and what it accepts.
std::vector<std::string> apply_environment_overrides(RendererSettings& settings,
                                                     const EnvironmentLookup& lookup);
// What the executables call once at start-up: the process environment applied to `settings`, warnings
// logged. Command-line options and saved options are applied after it, so they win.
RendererSettings renderer_settings_from_environment(RendererSettings settings = {});

// MSAA 4x on real GPUs, none on software rasterisers (llvmpipe, softpipe, SwiftShader), where every
// sample is CPU time; see docs/rendering.md for the measurements behind this.
int default_msaa_for(const std::string& gl_renderer);
// Fast on software rasterisers, Full on GPUs.
RenderQuality default_quality_for(const std::string& gl_renderer);
// 1 on GPUs, `software_scale` on software rasterisers (clamped 0.25..1).
float default_render_scale_for(const std::string& gl_renderer, float software_scale = kSoftwareRenderScale);

} // namespace ks::render
