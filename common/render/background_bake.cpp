// A level scene's light map on a worker thread (background_bake.h).
#include "render/background_bake.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <utility>

namespace ks::render {

namespace {
// The calling thread (and the threads it starts: Linux's nice value is per thread and inherited) yields the
// cores to the rest of the process: the first frames' shader compiles and rendering (llvmpipe's threads)
// go first, the bake takes what they leave. Best effort: a refusal leaves the priority as it was.
void lower_this_thread_priority() {
    (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
}
} // namespace

void BackgroundBake::start(const LevelScene& scene, unsigned long long build, const BakeSettings& settings,
                           Done on_done, std::function<void()> on_ready) {
    cancel();
    if (!scene.light_bake().laid_out()) return;
    job_ = std::make_unique<Job>();
    job_->bake = scene.light_bake(); // a copy: the scene keeps drawing meanwhile
    job_->build = build;
    Job* job = job_.get();
    job->thread = std::jthread([job, settings, env = scene.environment(), lights = scene.bake_lights(),
                                done = std::move(on_done), ready = std::move(on_ready)] {
        lower_this_thread_priority();
        job->stats = job->bake.compute(env, lights, settings, &job->progress);
        if (done && !job->stats.cancelled) done(job->bake, job->stats);
        job->done.store(true, std::memory_order_release);
        if (ready && !job->stats.cancelled) ready();
    });
}

void BackgroundBake::cancel() {
    if (!job_) return;
    job_->progress.cancel = true;
    job_.reset(); // joins
}

bool BackgroundBake::finish(LevelScene& scene, unsigned long long build) {
    if (!job_ || !job_->done.load(std::memory_order_acquire)) return false;
    job_->thread.join();
    const bool ours = job_->build == build && !job_->stats.cancelled;
    if (ours) {
        last_wall_ms_ = job_->stats.wall_ms;
        scene.adopt_light_bake(std::move(job_->bake), job_->stats);
    }
    job_.reset();
    return ours;
}

} // namespace ks::render
