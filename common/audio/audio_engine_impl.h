#pragma once
// Internal to the audio module: the engine's state, one entry per voice slot, all sized at open so a frame
// allocates nothing.
#include "audio/al_device.h"
#include "audio/audio_engine.h"

#include <set>
#include <string>
#include <vector>

namespace ks::audio {

struct AudioEngine::Impl {
    struct Voice {
        int sound = -1; // index in the bank
        Bus bus = Bus::Effects;
        bool positional = false;
        bool game = true;
        bool pending = false;     // play() was called; the source starts at the next update
        bool game_paused = false; // paused by set_game_paused, resumed by it
        float volume = 1.0f;
        float ref_distance = kDefaultRefDistance;
        float max_distance = kDefaultMaxDistance;
        float applied_gain = -1.0f;        // the AL_GAIN last set (skip redundant calls)
        float applied_filter_gain = -1.0f; // the low-pass gains the filter last got
        float applied_filter_hf = -1.0f;
    };

    Impl(SoundBank sounds, const EngineSettings& settings);
    ~Impl();
    bool open_sources(); // after the device is open: one source (and filter) per voice slot

    VoiceHandle play(const PlayParams& params);
    void stop_slot(int slot);
    void set_game_paused(bool paused);
    void update(float dt, BlockedQuery blocked);
    void set_listener(Vec3 position, Vec3 forward, Vec3 up);
    void set_volumes(const Volumes& volumes);

    float bus_volume(Bus bus) const;
    float base_gain(int slot) const;          // volume, bus and distance
    float occlusion_gain(float amount) const; // the broadband part of occlusion
    ALuint buffer_for(int sound);             // uploads the sound on first use; 0 on failure
    // The direct path's low-pass: occlusion `amount` (0..1) and the rear shading `rear_hf` (rear_highs()).
    void apply_filter(int slot, float amount, float rear_hf);
    void retire_ended_voices();
    void start_pending_voices();

    detail::AlDevice al;
    SoundBank bank;
    std::vector<ALuint> buffers; // per bank index, 0 until uploaded
    VoicePool pool;
    OcclusionScheduler occlusion;
    std::vector<ALuint> sources;
    std::vector<ALuint> filters; // empty without EFX
    std::vector<Voice> voices;
    std::vector<Vec3> positions;
    std::vector<ALuint> batch; // sources to start or pause together
    Vec3 listener{0.0f};
    Vec3 listener_forward{0.0f, 0.0f, -1.0f};
    Volumes volumes;
    bool game_paused = false;
    int rays_last_update = 0;
    std::set<std::string, std::less<>> warned_missing; // unknown names already reported
    bool warned_bad_position = false;
};

} // namespace ks::audio
