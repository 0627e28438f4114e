#pragma once
// What a running game sounds like: the bridge from the headless game to the audio engine. Each step's events
// become sound cues (game/sound_cues.h) played as voices; each robot has a motor loop that swells with its
// speed; the level's ambient loop and its `sound` emitters play from the start; the listener follows the
// camera; a wall between the listener and a sound muffles it (Game::line_blocked). The game never sees this:
// it only emits events and exposes plain state (docs/audio.md).
#include "audio/audio_engine.h"
#include "game/game.h"
#include "game/sound_cues.h"
#include "level/level.h"

#include <vector>

namespace ks::soundscape {

struct Listener {
    Vec3 position{0.0f};
    Vec3 forward{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
};

// The player's ears: the eye, looking along the view (the headless recorder's listener).
Listener player_listener(const game::Game& game);

// How a cue becomes a voice (exposed for tests): its bus, distances and priority.
audio::PlayParams play_params(const game::SoundCue& cue);

class Soundscape {
  public:
    // Starts the level's ambient loop and emitters on `engine`, which must outlive this object.
    Soundscape(audio::AudioEngine& engine, const level::Level& level);
    ~Soundscape(); // stops every voice it started
    Soundscape(const Soundscape&) = delete;
    Soundscape& operator=(const Soundscape&) = delete;

    // After each game step: plays the step's cues, keeps one motor loop per live robot.
    void after_step(const game::Game& game);
    // Once per frame (or per step when recording): listener, motor volumes, occlusion and the engine update.
    void update(const game::Game& game, const Listener& listener, float dt);
    // Pauses the game's voices (ambience and effects); menu sounds go on.
    void set_paused(bool paused);

    int cues_played() const { return cues_played_; }
    int motors_running() const;

  private:
    struct Motor {
        int entity = -1;
        audio::VoiceHandle voice;
        Vec3 feet{0.0f};
        float speed = 0.0f; // smoothed, units per second
        bool seen = false;
    };
    void start_level_sounds(const level::Level& level);
    void keep_motors(const game::Game& game);

    audio::AudioEngine& engine_;
    std::vector<game::SoundCue> cues_;
    std::vector<Motor> motors_;
    std::vector<audio::VoiceHandle> level_voices_; // ambience and emitters
    int cues_played_ = 0;
    double step_ = 1.0 / 120.0;
};

} // namespace ks::soundscape
