#pragma once
// A level scene's light map computed on a worker thread. The scene is built with its light map laid out
// (render::LevelSceneOptions::defer_bake, or a game start whose bake was not in the disk cache); this
// computes a copy at the given quality and hands it to the scene when it is done, so nothing waits for the
// bake: meanwhile the scene draws what it has (the editor's geometry lit per vertex, the game's direct
// light). The worker runs at the lowest priority (nice 19), so the frames drawn meanwhile are not slowed.
// A newer start, cancel() or the destructor stops the bake before it. Used by the editor's viewport (the
// preview quality after each edit) and the game: the full quality on a cold start (stored in the disk cache
// when done) and after a live play-test edit that changed the scenery (preview first, then full), so the
// edit shows before its lighting is done.
#include "render/level_scene.h"
#include "render/light_bake.h"

#include <atomic>
#include <functional>
#include <memory>
#include <thread>

namespace ks::render {

class BackgroundBake {
  public:
    // Runs on the worker once the bake is complete (not when cancelled): the game stores it in the cache.
    using Done = std::function<void(const LightBake&, const BakeStats&)>;

    ~BackgroundBake() { cancel(); }
    // Starts computing `scene`'s light map (laid out) with `settings`, for the scene build `build`.
    // `on_ready` runs on the worker once finish() can take the bake (the game wakes its idle frame loop).
    void start(const LevelScene& scene, unsigned long long build, const BakeSettings& settings,
               Done on_done = {}, std::function<void()> on_ready = {});
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
