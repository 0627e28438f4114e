#pragma once
// The viewport's preview light bake. The level scene is built with its light map laid out but not computed
// (render::LevelSceneOptions::defer_bake); this computes a copy at the preview quality
// (render::BakeSettings::preview()) on a worker thread and hands it to the scene when it is done, so an edit
// never waits for the bake: meanwhile the level geometry is lit per vertex. A newer scene cancels the bake
// of the older one.
#include "render/level_scene.h"
#include "render/light_bake.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

namespace ks::editor::ui {

class PreviewBake {
  public:
    ~PreviewBake() { cancel(); }
    // Starts computing `scene`'s light map (laid out, not computed), for the scene build `build`.
    void start(const render::LevelScene& scene, unsigned long long build);
    void cancel();
    // Hands a finished bake of `build` to `scene`; true when it did.
    bool finish(render::LevelScene& scene, unsigned long long build);
    bool running() const { return job_ != nullptr; }
    float progress() const { return job_ ? job_->progress.done.load() : 1.0f; }
    // " | lighting 42%" while a bake runs, else empty (the viewport's status line).
    std::string label() const;
    double last_wall_ms() const { return last_wall_ms_; }

  private:
    struct Job {
        render::LightBake bake;
        render::BakeStats stats;
        render::BakeProgress progress;
        std::atomic<bool> done{false};
        unsigned long long build = 0;
        std::jthread thread; // last: joined before the rest is destroyed
    };
    std::unique_ptr<Job> job_;
    double last_wall_ms_ = 0.0;
};

} // namespace ks::editor::ui
