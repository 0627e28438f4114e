#pragma once
// A particle system like the reference's: an emitter spawns `per_frame` particles each update inside a
// box of `spawn_radius` around `position`, each living `life` seconds with `velocity` (randomised by
// direction) plus `drift`, pulled down by `gravity`, fading and growing along fixed curves, until `duration`
// ends (or forever); then `on_finish` is called once. Simulation is plain C++ (tested without GL); the
// renderer draws the particles as camera-facing billboards, additive or alpha blended (sorted back to front).
#include "core/math.h"
#include "core/random.h"
#include "core/result.h"

#include <functional>
#include <string>
#include <vector>

namespace ks::render {

enum class ParticleBlend { Additive, Alpha };

struct ParticleParams {
    Vec3 position{0.0f};
    Vec3 spawn_radius{0.1f};         // half-extent of the spawn box per axis
    float size = 1.0f;               // world units at the start of life
    float life = 0.6f;               // seconds, each particle lives 0.25..1 of this
    Vec3 velocity{0.0f, 2.0f, 0.0f}; // per-axis speed; the sign of each axis is random for x and z
    Vec3 drift{0.0f};                // added to every particle's velocity (a spray along a surface normal)
    float gravity = 0.0f;            // downward acceleration, units/s² (sparks fall)
    int per_frame = 4;               // particles spawned each update while active
    float duration = 0.6f;           // seconds of spawning; <= 0 means forever
    std::string texture = "fire";    // assets/textures/particles/<texture>.png
    ParticleBlend blend = ParticleBlend::Additive;
    Vec3 color_start{1.0f, 1.0f, 0.5f}; // linear, from the reference's 0xFFFF80 ...
    Vec3 color_end{1.0f, 0.5f, 0.5f};   // ... to 0xFF8080
    float grow = 5.0f;                  // size multiplier at mid-life (the reference grows x5 then shrinks)
    float drag = 0.1f;                  // fraction of velocity lost per second
    int max_particles = 512;            // capacity, allocated once
};

// Checks the parameters (finite, positive life/size, sane counts); the error names the field.
Result<void> validate(const ParticleParams& params);

struct Particle {
    Vec3 position;
    Vec3 velocity;
    float age = 0, life = 1, size = 1, rotation = 0, spin = 0;
    Vec4 color; // current linear rgb + alpha (written by update)
    float current_size = 1;
};

class ParticleEmitter {
  public:
    ParticleEmitter(ParticleParams params, std::uint64_t seed, std::function<void()> on_finish = {});

    void update(float dt);
    void set_position(const Vec3& p) { params_.position = p; }
    void stop() { stopped_ = true; } // stop spawning; live particles finish their lives
    bool spawning() const;
    bool finished() const { return finished_; } // no longer spawning and no particle alive
    const std::vector<Particle>& particles() const { return particles_; }
    const ParticleParams& params() const { return params_; }

  private:
    void spawn();
    ParticleParams params_;
    Rng rng_;
    std::function<void()> on_finish_;
    std::vector<Particle> particles_;
    float elapsed_ = 0.0f;
    bool stopped_ = false, finished_ = false;
};

} // namespace ks::render
