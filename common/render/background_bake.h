#pragma once
// A level scene's light map computed on a worker thread. The scene is built with its light map laid out
// but not computed (LevelSceneOptions::defer_bake); start() computes a copy at the given quality on
// another thread while the scene is drawn (its level geometry lit per vertex meanwhile), finish() hands the
// result to the scene. A newer start(), cancel() or the destructor stops the older bake. Used by the
// editor's viewport (a preview bake after each edit) and by the game's live play-test (the full bake after
// an edit that changed the scenery, so the edit shows before its lighting is done).
#include "render/level_scene.h"
#include "render/light_bake.h"

#include <atomic>
#include <memory>
#include <thread>

namespace ks::render {

class BackgroundBake {
  public:
    BackgroundBake() = default;
    BackgroundBake(const BackgroundBake&) = delete;
    BackgroundBake& operator=(const BackgroundBake&) = delete;
    ~BackgroundBake() { cancel(); }
    // Starts computing `scene`'s light map (laid out, not computed) for the scene build `build`; nothing
    // when the scene's light map is not laid out (no bake asked).
    void start(const LevelScene& scene, unsigned long long build, const BakeSettings& settings);
    void cancel();
    // Hands a finished bake of `build` to `scene`; true when it did.
    bool finish(LevelScene& scene, unsigned long long build);
    bool running() const { return job_ != nullptr; }
    float progress() const { return job_ ? job_->progress.done.load() : 1.0f; }
    double last_wall_ms() const { return last_wall_ms_; }

  private:
    struct Job {
        LightBake bake;
        BakeStats stats;
        BakeProgress progress;
        std::atomic<bool> done{false};
        unsigned long long build = 0;
        std::jthread thread; // last: joined before the rest is destroyed
    };
    std::unique_ptr<Job> job_;
    double last_wall_ms_ = 0.0;
};

} // namespace ks::render
