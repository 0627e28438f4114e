// The level's picture for the viewport: the renderer, the level scene and the views' targets
// (viewport_scene.h).
#include "ui/viewport_scene.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <type_traits>

namespace ks::editor::ui {

namespace {
// FNV-1a over the bytes of plain values (no padding in any of them).
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    template <class T>
    void add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    }
};

// Everything a view's picture is made of: a view whose key has not changed keeps the picture it has, so an
// idle editor draws nothing, and the 4-up view (the level four times) redraws only the panes that change:
// one of four while it is navigated. `scene_builds` stands for the level scene's meshes, light map and
// environment.
std::uint64_t picture_key(const render::SceneFrame& frame, unsigned long long scene_builds) {
    Fnv key;
    key.add(scene_builds);
    key.add(frame.camera);
    key.add(frame.width);
    key.add(frame.height);
    for (const render::MeshInstance& m : *frame.instances) {
        key.add(m.mesh);
        key.add(m.material);
        key.add(m.world);
        key.add(m.emissive_scale);
        key.add(m.tint);
        key.add(m.lightmap);
        key.add(static_cast<unsigned char>(m.casts_shadow));
    }
    for (const render::Light& l : *frame.lights) {
        key.add(l.type);
        key.add(l.position);
        key.add(l.direction);
        key.add(l.color);
        key.add(l.intensity);
        key.add(l.range);
        key.add(l.cos_outer);
        key.add(l.cos_inner);
    }
    for (const render::DebugVertex& v : frame.debug->vertices()) {
        key.add(v.position);
        key.add(v.color);
    }
    return key.h;
}
} // namespace

Result<void> ViewportScene::init(const std::string& gl_renderer) {
    render::RendererSettings settings = render::renderer_settings_from_environment();
    settings.msaa_samples = render::default_msaa_for(gl_renderer);
    // Full resolution on software rasterisers too (the game's automatic choice there is 0.5): thin overlays
    // (eye radii, grid, gizmo) at half resolution turn to stairs, and the viewport is about 40 % of the
    // window (21.2-23.1 vs 17.6-22.3 ms per editor frame on llvmpipe: docs/performance.md, "Viewport
    // resolution"). KS_RENDER_SCALE still overrides (automatic_render_scale).
    settings.software_render_scale = 1.0f;
    auto renderer = render::SceneRenderer::create(assets_.textures(), settings);
    if (!renderer) return renderer.error();
    renderer_ = std::move(*renderer);
    return ok();
}

void ViewportScene::rebuild_if_changed(const Editor& editor, std::uint64_t shown_key, const Shown& shown) {
    const std::uint64_t revision =
        editor.revision() ^ (static_cast<std::uint64_t>(editor.doc().hidden.size()) << 48) ^ shown_key;
    // While a continuous edit is in progress (a gizmo drag: an open history transaction; an inspector field
    // dragged: an active ImGui item, its edits merged into one step) the scene is rebuilt every changed frame
    // without the light-map bake (most of a rebuild's cost on a software rasteriser); the bake runs once when
    // the edit ends, even if nothing changed since.
    const bool continuous = editor.history().in_transaction() ||
                            (ImGui::GetCurrentContext() != nullptr && ImGui::IsAnyItemActive());
    const bool bake = !continuous;
    if (scene_ && preview_bake_.finish(*scene_, scene_stats_.builds)) ++scene_stats_.bakes;
    if (scene_ && revision == scene_revision_ && (scene_baked_ || !bake)) return;
    preview_bake_.cancel(); // its scene is about to go
    const std::clock_t cpu_start = std::clock();
    render::LevelSceneOptions options = render::level_scene_options(renderer_->settings());
    options.bake_light_map = options.bake_light_map && bake;
    options.defer_bake = true; // computed by preview_bake_, on another thread
    options.bake = render::BakeSettings::preview();
    const auto& entities = editor.level().entities;
    if (std::all_of(entities.begin(), entities.end(), shown)) {
        scene_ = render::LevelScene::build(editor.level(), assets_, options);
    } else { // hidden entities (and ceilings, unless shown) are left out of the picture and of picking
        level::Level visible = editor.level();
        std::erase_if(visible.entities, [&](const level::Entity& e) { return !shown(e); });
        scene_ = render::LevelScene::build(visible, assets_, options);
    }
    scene_stats_.last_build_cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    ++scene_stats_.builds;
    preview_bake_.start(*scene_, scene_stats_.builds,
                        options.bake); // nothing when not laid out (no bake asked)
    renderer_->invalidate_shadows();
    scene_revision_ = revision;
    scene_baked_ = bake;
}

std::string ViewportScene::bake_label() const {
    if (!preview_bake_.running()) return {};
    char text[32];
    std::snprintf(text, sizeof(text), "  |  lighting %d%%",
                  static_cast<int>(preview_bake_.progress() * 100.0f));
    return text;
}

bool ViewportScene::render_view(const ViewCamera& view, int width, int height, std::uint64_t& last_key,
                                const DrawLines& lines) {
    debug_.clear();
    lines(debug_, view);
    render::SceneFrame frame;
    frame.camera = view.camera;
    frame.camera.aspect = static_cast<float>(width) / static_cast<float>(std::max(1, height));
    scene_->set_view(frame.camera, height);
    scene_->emit(instances_, lights_, &casters_);
    scene_stats_.coarse_models = scene_->coarse_model_count();
    frame.environment = scene_->environment();
    frame.instances = &instances_;
    frame.lights = &lights_;
    frame.shadow_casters = &casters_;
    frame.debug = &debug_;
    frame.width = width;
    frame.height = height;
    const std::uint64_t key = picture_key(frame, scene_stats_.builds + (scene_stats_.bakes << 32));
    if (key == last_key) return false;
    last_key = key;
    renderer_->render(frame);
    return true;
}

void ViewportScene::render_single(const ViewCamera& view, int width, int height, const DrawLines& lines) {
    single_target_.ensure(width, height);
    single_target_.bind();
    render_view(view, width, height, single_key_, lines);
}

void ViewportScene::render_pane(size_t pane, const ViewCamera& view, Vec2 size, const DrawLines& lines) {
    const int w = static_cast<int>(size.x), h = static_cast<int>(size.y);
    pane_targets_[pane].ensure(w, h);
    pane_targets_[pane].bind();
    if (render_view(view, w, h, pane_keys_[pane], lines)) ++pane_renders_[pane];
}

void ViewportScene::status(nlohmann::json& s) const {
    s["render_scale"] = renderer_ ? renderer_->render_scale() : 0.0f;
    s["scene"] = {{"builds", scene_stats_.builds},
                  {"bakes", scene_stats_.bakes},
                  {"bake_running", preview_bake_.running()},
                  {"last_bake_wall_ms", preview_bake_.last_wall_ms()},
                  {"last_build_cpu_ms", scene_stats_.last_build_cpu_ms},
                  {"coarse_models", scene_stats_.coarse_models}};
}

} // namespace ks::editor::ui
