#pragma once
// The viewport's preview light bake. The level scene is built with its light map laid out but not computed
// (render::LevelSceneOptions::defer_bake); this computes a copy at the preview quality
// (render::BakeSettings::preview()) on a worker thread (render::BackgroundBake) and hands it to the scene
// when it is done, so an edit never waits for the bake: meanwhile the level geometry is lit per vertex. A
// newer scene cancels the bake of the older one.
#include "render/background_bake.h"

#include <string>

namespace ks::editor::ui {

class PreviewBake {
  public:
    // Starts computing `scene`'s light map (laid out, not computed), for the scene build `build`.
    void start(const render::LevelScene& scene, unsigned long long build) {
        bake_.start(scene, build, render::BakeSettings::preview());
    }
    void cancel() { bake_.cancel(); }
    // Hands a finished bake of `build` to `scene`; true when it did.
    bool finish(render::LevelScene& scene, unsigned long long build) { return bake_.finish(scene, build); }
    bool running() const { return bake_.running(); }
    float progress() const { return bake_.progress(); }
    // " | lighting 42%" while a bake runs, else empty (the viewport's status line).
    std::string label() const;
    double last_wall_ms() const { return bake_.last_wall_ms(); }

  private:
    render::BackgroundBake bake_;
};

} // namespace ks::editor::ui
