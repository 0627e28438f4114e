#pragma once
// The game's render scale: the player's choice (Options: 25 .. 100 %), or, with Auto on a software
// rasteriser, the dynamic resolution controller's pick each frame (render/dynamic_resolution.h): full
// resolution whenever the machine holds the target frame rate, steps down to the automatic scale when it
// must. GPUs draw Auto at full resolution and need no controller; KS_RENDER_SCALE fixes the automatic scale.
#include "render/dynamic_resolution.h"

#include <optional>

namespace ks::render {
class SceneRenderer;
}

namespace ks::runtime {

class RenderScaleControl {
  public:
    // `enabled`: whether Auto may be dynamic (screenshot runs keep a fixed scale unless asked, so their
    // pictures do not depend on the machine's speed); `target_fps`: the frame rate to hold.
    void configure(bool enabled, double target_fps);
    // The option changed (and at start): 0 = automatic.
    void apply(render::SceneRenderer& renderer, float option);
    // Each frame, before drawing: the last frame's work (s) and the time since it (s).
    void frame(render::SceneRenderer& renderer, double previous_work, double frame_seconds);
    bool dynamic() const { return controller_.has_value(); }
    double target_fps() const { return target_fps_; }

  private:
    bool enabled_ = false; // until configure(): the app decides once it knows whether it takes screenshots
    double target_fps_ = 60.0;
    std::optional<render::DynamicResolution> controller_;
};

} // namespace ks::runtime
