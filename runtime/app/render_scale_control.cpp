#include "render_scale_control.h"

#include "render/scene_renderer.h"

namespace ks::runtime {

void RenderScaleControl::configure(bool enabled, double target_fps) {
    enabled_ = enabled;
    target_fps_ = target_fps;
}

void RenderScaleControl::apply(render::SceneRenderer& renderer, float option) {
    renderer.set_render_scale(option); // 0 resolves to the automatic scale
    const bool automatic = !(option > 0.0f) && !(renderer.settings().automatic_render_scale > 0.0f);
    if (!enabled_ || !automatic || renderer.render_scale() >= 1.0f) {
        controller_.reset();
        return;
    }
    render::DynamicResolutionSettings settings;
    settings.target_ms = 1000.0 / target_fps_;
    settings.lowest_scale = renderer.render_scale();
    controller_.emplace(settings);
    renderer.set_render_scale(controller_->scale());
}

void RenderScaleControl::frame(render::SceneRenderer& renderer, double previous_work, double frame_seconds) {
    if (!controller_ || !(previous_work > 0.0)) return;
    const float scale = controller_->update(previous_work * 1000.0, frame_seconds);
    if (scale != renderer.render_scale()) renderer.set_render_scale(scale);
}

} // namespace ks::runtime
