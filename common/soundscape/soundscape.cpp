#include "soundscape/soundscape.h"

#include <algorithm>
#include <cmath>

namespace ks::soundscape {
namespace {

// A robot's motor: a quiet servo hum standing, up to this much louder at full speed.
constexpr float kMotorIdleVolume = 0.12f;
constexpr float kMotorMovingVolume = 0.55f;
constexpr float kMotorFullSpeed = 6.0f;  // units per second (a chasing robot)
constexpr float kMotorSmoothing = 0.15f; // seconds: speed changes are heard over about this long

} // namespace

Listener player_listener(const game::Game& game) {
    const auto& p = game.player();
    Listener l;
    l.position = p.eye();
    l.forward = p.view_direction();
    const Vec3 right(std::cos(p.yaw), 0.0f, -std::sin(p.yaw));
    l.up = glm::cross(right, l.forward);
    return l;
}

audio::PlayParams play_params(const game::SoundCue& cue) {
    audio::PlayParams p;
    p.sound = std::string(cue.sound);
    p.position = cue.position;
    p.positional = cue.positional;
    p.volume = std::clamp(cue.volume, 0.0f, 1.0f);
    p.pitch = cue.pitch;
    p.priority = static_cast<int>(cue.priority);
    p.ref_distance = std::max(cue.reference_distance, 0.5f);
    // Heard out to about 18 reference distances: a shot (8) across the level, a light switch (4) a room away.
    p.max_distance = std::clamp(cue.reference_distance * 18.0f, 40.0f, 200.0f);
    p.bus = audio::Bus::Effects;
    p.game = true;
    return p;
}

Soundscape::Soundscape(audio::AudioEngine& engine, const level::Level& level) : engine_(engine) {
    cues_.reserve(64);
    start_level_sounds(level);
}

Soundscape::~Soundscape() {
    for (const Motor& m : motors_) engine_.stop(m.voice);
    for (audio::VoiceHandle v : level_voices_) engine_.stop(v);
}

void Soundscape::start_level_sounds(const level::Level& level) {
    if (!level.settings.ambient_sound.value.empty()) {
        audio::PlayParams p;
        p.sound = level.settings.ambient_sound.value;
        p.positional = false;
        p.loop = true;
        p.volume = 0.6f;
        p.priority = static_cast<int>(game::SoundPriority::Critical); // never stolen
        p.bus = audio::Bus::Ambience;
        level_voices_.push_back(engine_.play(p));
    }
    for (const level::Entity& e : level.entities) {
        const auto* s = e.try_as<level::SoundProps>();
        if (!s || s->sound.value.empty()) continue;
        audio::PlayParams p;
        p.sound = s->sound.value;
        p.position = e.position;
        p.loop = s->loop;
        p.volume = s->volume;
        p.priority = static_cast<int>(game::SoundPriority::Detail);
        // Full volume within a quarter of the radius, silent beyond it.
        p.ref_distance = std::max(0.5f, s->radius * 0.25f);
        p.max_distance = std::max(p.ref_distance, s->radius);
        p.bus = audio::Bus::Ambience;
        level_voices_.push_back(engine_.play(p));
    }
}

void Soundscape::after_step(const game::Game& game) {
    step_ = game.settings().step;
    for (const game::Event& e : game.events())
        if (e.type == game::EventType::Paused) engine_.set_game_paused(e.amount > 0.5f);
    game::sound_cues(game, game.events(), cues_);
    for (const game::SoundCue& cue : cues_) {
        engine_.play(play_params(cue));
        ++cues_played_;
    }
    keep_motors(game);
}

// One looping motor voice per live robot, following it; its loudness follows the robot's speed (measured from
// its feet, smoothed), and it stops when the robot dies.
void Soundscape::keep_motors(const game::Game& game) {
    const float dt = static_cast<float>(step_);
    const float blend = 1.0f - std::exp(-dt / kMotorSmoothing);
    for (Motor& m : motors_) m.seen = false;
    for (const game::Robot& r : game.robots()) {
        auto it = std::find_if(motors_.begin(), motors_.end(),
                               [&](const Motor& m) { return m.entity == r.entity_id; });
        if (!r.alive()) {
            if (it != motors_.end()) {
                engine_.stop(it->voice);
                motors_.erase(it);
            }
            continue;
        }
        if (it == motors_.end()) {
            Motor m;
            m.entity = r.entity_id;
            m.feet = r.feet;
            motors_.push_back(m);
            it = motors_.end() - 1;
        }
        Motor& m = *it;
        m.seen = true;
        const Vec3 moved = r.feet - m.feet;
        const float speed = std::hypot(moved.x, moved.z) / dt;
        m.feet = r.feet;
        m.speed += (std::min(speed, 3.0f * kMotorFullSpeed) - m.speed) * blend;
        const float volume =
            kMotorIdleVolume + kMotorMovingVolume * std::clamp(m.speed / kMotorFullSpeed, 0.0f, 1.0f);
        const Vec3 centre = r.feet + Vec3(0.0f, 1.0f, 0.0f);
        if (!engine_.is_playing(m.voice)) {
            audio::PlayParams p;
            p.sound = "robot_motor";
            p.position = centre;
            p.loop = true;
            p.volume = volume;
            p.priority = static_cast<int>(game::SoundPriority::Footstep);
            p.ref_distance = 4.0f;
            p.max_distance = 60.0f;
            m.voice = engine_.play(p);
        } else {
            engine_.set_position(m.voice, centre);
            engine_.set_volume(m.voice, volume);
        }
    }
    // Robots gone from the game (a new session reuses nothing, but be safe): stop their motors.
    for (auto it = motors_.begin(); it != motors_.end();) {
        if (!it->seen) {
            engine_.stop(it->voice);
            it = motors_.erase(it);
        } else {
            ++it;
        }
    }
}

void Soundscape::update(const game::Game& game, const Listener& listener, float dt) {
    engine_.set_listener(listener.position, listener.forward, listener.up);
    auto blocked = [&game](Vec3 from, Vec3 to) { return game.line_blocked(from, to); };
    engine_.update(dt, blocked);
}

void Soundscape::set_paused(bool paused) {
    engine_.set_game_paused(paused);
}

int Soundscape::motors_running() const {
    int n = 0;
    for (const Motor& m : motors_) n += engine_.is_playing(m.voice) ? 1 : 0;
    return n;
}

} // namespace ks::soundscape
