#include "render/particles.h"

#include <algorithm>
#include <cmath>

namespace ks::render {

Result<void> validate(const ParticleParams& p) {
    auto bad = [](const char* field, const char* fix) {
        return Error(std::string("particle parameter '") + field + "' is invalid",
                     Location{"particles", 0, 0, field}, fix);
    };
    if (!is_finite(p.position)) return bad("position", "use finite coordinates");
    if (!is_finite(p.spawn_radius) || glm::any(glm::lessThan(p.spawn_radius, Vec3(0.0f))))
        return bad("spawn_radius", "use finite, non-negative radii");
    if (!is_finite(p.size) || p.size <= 0.0f || p.size > 1000.0f)
        return bad("size", "use a size in (0, 1000]");
    if (!is_finite(p.life) || p.life <= 0.0f || p.life > 600.0f)
        return bad("life", "use a life in (0, 600] seconds");
    if (!is_finite(p.velocity)) return bad("velocity", "use finite speeds");
    if (!is_finite(p.drift)) return bad("drift", "use finite speeds");
    if (!is_finite(p.gravity) || std::abs(p.gravity) > 1000.0f)
        return bad("gravity", "use an acceleration in [-1000, 1000] units/s²");
    if (p.per_frame < 0 || p.per_frame > 10000) return bad("per_frame", "use 0..10000 particles per frame");
    if (!is_finite(p.duration)) return bad("duration", "use seconds, or <= 0 for forever");
    if (p.max_particles < 1 || p.max_particles > 1000000) return bad("max_particles", "use 1..1000000");
    if (!is_finite(p.grow) || p.grow <= 0.0f) return bad("grow", "use a positive multiplier");
    if (!is_finite(p.drag) || p.drag < 0.0f) return bad("drag", "use a non-negative fraction per second");
    return ok();
}

ParticleEmitter::ParticleEmitter(ParticleParams params, std::uint64_t seed, std::function<void()> on_finish)
    : params_(std::move(params)), rng_(seed), on_finish_(std::move(on_finish)) {
    if (!validate(params_)) { // a bad emitter finishes at once instead of spreading NaN through the frame
        stopped_ = true;
        params_.max_particles = 1;
    }
    particles_.reserve(static_cast<size_t>(params_.max_particles));
}

bool ParticleEmitter::spawning() const {
    return !stopped_ && (params_.duration <= 0.0f || elapsed_ < params_.duration);
}

void ParticleEmitter::spawn() {
    Particle p;
    Vec3 r(rng_.uniform(-1.0f, 1.0f), rng_.uniform(-1.0f, 1.0f), rng_.uniform(-1.0f, 1.0f));
    p.position = params_.position + r * params_.spawn_radius;
    Vec3 dir(rng_.uniform() < 0.5f ? -1.0f : 1.0f, 1.0f, rng_.uniform() < 0.5f ? -1.0f : 1.0f);
    p.velocity = (params_.velocity * dir + params_.drift) * rng_.uniform(0.5f, 1.0f);
    p.life = params_.life * rng_.uniform(0.25f, 1.0f);
    p.size = params_.size * rng_.uniform(0.5f, 1.0f);
    p.rotation = rng_.uniform(0.0f, 2.0f * kPi);
    p.spin = rng_.uniform(-0.5f, 0.5f);
    particles_.push_back(p);
}

void ParticleEmitter::update(float dt) {
    if (finished_) return;
    if (!is_finite(dt) || dt < 0.0f) dt = 0.0f;
    if (spawning())
        for (int i = 0; i < params_.per_frame && particles_.size() < particles_.capacity(); ++i) spawn();
    elapsed_ += dt;
    const float keep = std::max(0.0f, 1.0f - params_.drag * dt);
    for (auto& p : particles_) {
        p.age += dt;
        p.position += p.velocity * dt;
        p.velocity *= keep;
        p.velocity.y -= params_.gravity * dt;
        p.rotation += p.spin * dt;
        float t = std::clamp(p.age / p.life, 0.0f, 1.0f);
        // Alpha 0 -> 1 (t 0.1) -> 1 (t 0.6) -> 0; size x1 -> x grow (t 0.5) -> x1 (the reference's splines).
        float alpha = t < 0.1f ? t / 0.1f : (t < 0.6f ? 1.0f : 1.0f - (t - 0.6f) / 0.4f);
        float g = t < 0.5f ? 1.0f + (params_.grow - 1.0f) * (t / 0.5f)
                           : params_.grow + (1.0f - params_.grow) * ((t - 0.5f) / 0.5f);
        p.color = Vec4(glm::mix(params_.color_start, params_.color_end, t), alpha);
        p.current_size = p.size * g;
    }
    std::erase_if(particles_, [](const Particle& p) { return p.age >= p.life; });
    if (!spawning() && particles_.empty()) {
        finished_ = true;
        if (on_finish_) on_finish_();
    }
}

} // namespace ks::render
