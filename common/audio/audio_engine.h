#pragma once
// The sound output: plays the SoundBank's sounds as voices, 3D-positioned around a listener (the camera),
// attenuated by distance (attenuation.h), muffled when a wall is in between (occlusion.h), within a voice
// limit (voice_pool.h). The only code that talks to OpenAL.
//
// open_device() never fails: without an output device (servers, CI) it returns an engine that accepts every
// call and plays nothing, after one notice line. open_loopback() renders into memory instead of a sound card
// (tests, benchmarks, recordings); the same calls in the same order render the same samples.
//
// Call update() once per frame: it measures occlusion, applies gains and starts the voices play() asked for
// (a voice starts at the next update, so sounds triggered in one frame start together).
#include "audio/attenuation.h"
#include "audio/occlusion.h"
#include "audio/sound_bank.h"
#include "audio/voice_pool.h"
#include "core/math.h"
#include "core/result.h"

#include <cstdint>
#include <memory>
#include <string>

namespace ks::audio {

// Which volume slider a voice follows (besides master).
enum class Bus : std::uint8_t { Effects, Ambience, Ui };

struct PlayParams {
    std::string sound;      // a SoundBank name, e.g. "rifle_shot"
    Vec3 position{0.0f};    // level units, when positional
    bool positional = true; // false: heard at the listener (UI, music, the player's own weapon)
    bool loop = false;
    float volume = 1.0f; // 0..1
    float pitch = 1.0f;  // playback speed, clamped to 0.25..4
    int priority = 0;    // higher survives the voice limit longer
    float ref_distance = kDefaultRefDistance;
    float max_distance = kDefaultMaxDistance;
    Bus bus = Bus::Effects;
    bool game = true; // paused with the game (set_game_paused); false for menu sounds
};

struct Volumes {
    float master = 1.0f;
    float effects = 1.0f;
    float ambience = 1.0f;
    bool muted = false;
};

struct AudioStats {
    bool output = false; // false: the silent engine
    bool efx = false;    // occlusion uses a low-pass filter (else gain only)
    int active_voices = 0;
    int voice_limit = 0;
    int stolen = 0;  // voices taken over by a more important sound, since open
    int dropped = 0; // sounds not played because every voice was more important, since open
    int rays_this_update = 0;
};

struct EngineSettings {
    int voices = VoicePool::kDefaultVoices;
    OcclusionSettings occlusion;
};

// A fully blocked sound (occlusion amount 1) through the EFX low-pass filter: broadband gain 0.5, and the
// highs (the filter's 5 kHz reference) at 0.15 on top of that. Partly blocked sounds interpolate linearly.
inline constexpr float kBlockedGain = 0.5f;
inline constexpr float kBlockedGainHf = 0.15f;
// Without EFX, a fully blocked sound is only made quieter, by about what the filter takes from broadband
// noise.
inline constexpr float kBlockedGainWithoutEfx = 0.3f;

class AudioEngine {
  public:
    static AudioEngine open_device(SoundBank sounds, EngineSettings settings = {});
    static Result<AudioEngine> open_loopback(SoundBank sounds, int sample_rate = 48000,
                                             EngineSettings settings = {});
    // The engine open_device() falls back to: accepts every call, plays nothing, handles are invalid.
    static AudioEngine silent(SoundBank sounds, EngineSettings settings = {});

    AudioEngine(AudioEngine&&) noexcept;
    AudioEngine& operator=(AudioEngine&&) noexcept;
    ~AudioEngine();

    // Starts `params.sound` (at the next update). Returns an invalid handle when the sound does not exist
    // (a warning, once per name), the voice limit dropped it, or there is no output.
    VoiceHandle play(const PlayParams& params);
    // Calls through a handle whose sound ended or was stolen do nothing. A new volume is applied by the next
    // update, with the distance gain.
    void set_position(VoiceHandle voice, Vec3 position);
    void set_volume(VoiceHandle voice, float volume);
    void stop(VoiceHandle voice);
    // True from play() until the sound ends (noticed at the next update), is stopped or stolen.
    bool is_playing(VoiceHandle voice) const;
    void stop_all();

    void set_listener(Vec3 position, Vec3 forward, Vec3 up);
    void set_volumes(const Volumes& volumes);
    // Pauses the voices played with game = true and resumes them; menu voices keep playing.
    void set_game_paused(bool paused);

    // Once per frame: retires ended voices, casts occlusion rays (blocked(listener, source): is the straight
    // line between them blocked?), applies gains and filters, starts new voices. Allocates nothing.
    void update(float dt, BlockedQuery blocked);
    void update(float dt); // no occlusion

    // Loopback engines: mixes `frames` frames of interleaved 16-bit stereo. Other engines write silence.
    void render(std::int16_t* interleaved_stereo, int frames);

    AudioStats stats() const;
    int sample_rate() const;
    const SoundBank& sounds() const;

    struct Impl; // audio_engine_impl.h

  private:
    explicit AudioEngine(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

} // namespace ks::audio
