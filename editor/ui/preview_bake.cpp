// The viewport's preview light bake on a worker thread (preview_bake.h).
#include "ui/preview_bake.h"

#include <cstdio>

namespace ks::editor::ui {

void PreviewBake::start(const render::LevelScene& scene, unsigned long long build) {
    cancel();
    if (!scene.light_bake().laid_out()) return;
    job_ = std::make_unique<Job>();
    job_->bake = scene.light_bake(); // a copy: the scene keeps drawing meanwhile
    job_->build = build;
    Job* job = job_.get();
    job->thread = std::jthread([job, env = scene.environment(), lights = scene.bake_lights()] {
        job->stats = job->bake.compute(env, lights, render::BakeSettings::preview(), &job->progress);
        job->done.store(true, std::memory_order_release);
    });
}

void PreviewBake::cancel() {
    if (!job_) return;
    job_->progress.cancel = true;
    job_.reset(); // joins
}

bool PreviewBake::finish(render::LevelScene& scene, unsigned long long build) {
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

std::string PreviewBake::label() const {
    if (!job_) return {};
    char text[32];
    std::snprintf(text, sizeof(text), "  |  lighting %d%%", static_cast<int>(progress() * 100.0f));
    return text;
}

} // namespace ks::editor::ui
