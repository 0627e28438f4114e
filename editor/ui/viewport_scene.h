#pragma once
// The level's picture for the viewport (viewport_scene.cpp): the game's renderer, the level scene rebuilt
// when the document or what is shown changed, and the targets of the single view and of the 4-up view's
// panes. Each target keeps its picture until what it shows changes (a key per target), so an idle editor
// draws nothing. The viewport (level_viewport.h) says which cameras to draw and draws its overlay lines
// into each view's debug lines; it reaches the document only through the calls below.
#include "model/editor.h"
#include "render/asset_library.h"
#include "render/background_bake.h"
#include "render/debug_draw.h"
#include "render/level_scene.h"
#include "render/scene_renderer.h"
#include "ui/render_target.h"
#include "view/quad_view.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ks::editor::ui {

class ViewportScene {
  public:
    using Shown = std::function<bool(const level::Entity&)>; // what is in the picture and can be picked
    // Draws the viewport's overlay lines for the view whose camera is given into the frame's debug lines.
    using DrawLines = std::function<void(render::DebugDraw&, const ViewCamera&)>;

    explicit ViewportScene(render::AssetLibrary& assets) : assets_(assets) {}
    Result<void> init(const std::string& gl_renderer); // the renderer, at full resolution
    render::SceneRenderer& renderer() { return *renderer_; }
    render::LevelScene& scene() { return *scene_; }

    // A new level scene when the document, what is hidden or `ceilings` changed, or the light map still
    // waits for the end of a continuous edit.
    // `shown_key` changes whenever what `shown` lets through changes other than by the document (ceilings
    // shown, the section's cut).
    void rebuild_if_changed(const Editor& editor, std::uint64_t shown_key, const Shown& shown);
    // Each view emits the level's instances and lights for its own camera (after the clip preview's pose):
    // every prop (a designer's model, or a shipped one with the asset generator's levels) is drawn at the
    // level of detail the game would draw it at from there (LevelScene::set_view, pick_model_level), so a
    // pane far from a model draws a coarser level while a close one draws it in full. With --status-file,
    // "scene.coarse_models" counts them in the last view.
    // `view` into the single view's target of width x height pixels, unless its picture would not change.
    void render_single(const ViewCamera& view, int width, int height, const DrawLines& lines);
    // `view` into pane `pane`'s target of `size` pixels, unless its picture would not change.
    void render_pane(size_t pane, const ViewCamera& view, Vec2 size, const DrawLines& lines);

    const RenderTarget& single_target() const { return single_target_; }
    const RenderTarget& pane_target(size_t pane) const { return pane_targets_[pane]; }
    unsigned long long pane_renders(size_t pane) const { return pane_renders_[pane]; }
    void status(nlohmann::json& status) const; // "render_scale", "scene"
    std::string bake_label() const; // "  |  lighting 42%" while the bake runs (the status line), else empty

  private:
    // The picture into the bound target; false: skipped, `last_key` says it shows the same.
    bool render_view(const ViewCamera& view, int width, int height, std::uint64_t& last_key,
                     const DrawLines& lines);

    render::AssetLibrary& assets_;
    std::unique_ptr<render::SceneRenderer> renderer_;
    std::unique_ptr<render::LevelScene> scene_;
    std::uint64_t scene_revision_ = ~0ull;
    render::BackgroundBake preview_bake_; // the light map of scene_ at the preview quality, on a worker
    bool scene_baked_ = false; // built with the light-map bake requested (not during a continuous edit)
    struct SceneStats {
        unsigned long long builds = 0, bakes = 0; // bakes: light maps computed and shown
        double last_build_cpu_ms = 0.0;
        int coarse_models = 0; // props the last view drew below their full level of detail
    } scene_stats_;
    std::vector<render::MeshInstance> instances_;
    std::vector<render::Light> lights_;
    std::vector<render::ShadowCaster> casters_; // the movers' contact shadows, as the game draws them
    render::DebugDraw debug_;
    RenderTarget single_target_;
    std::uint64_t single_key_ = 0; // what the single view's picture shows
    std::array<RenderTarget, kQuadPanes> pane_targets_;
    std::array<std::uint64_t, kQuadPanes> pane_keys_{};         // what each pane's picture shows
    std::array<unsigned long long, kQuadPanes> pane_renders_{}; // how often each was drawn (status file)
};

} // namespace ks::editor::ui
