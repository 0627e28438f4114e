// The engine's per-voice work: starting, stopping, pausing voices and the per-frame update.
#include "audio/audio_engine_impl.h"
#include "core/log.h"

#include <algorithm>
#include <cmath>

namespace ks::audio {
namespace {

float lerp(float a, float b, float t) {
    return a + (b - a) * t;
}
float finite_or(float v, float fallback) {
    return std::isfinite(v) ? v : fallback;
}

} // namespace

AudioEngine::Impl::Impl(SoundBank sounds, const EngineSettings& settings)
    : bank(std::move(sounds)), buffers(static_cast<std::size_t>(bank.size()), 0), pool(settings.voices),
      occlusion(pool.capacity(), settings.occlusion), voices(static_cast<std::size_t>(pool.capacity())),
      positions(static_cast<std::size_t>(pool.capacity()), Vec3(0.0f)) {
    batch.reserve(static_cast<std::size_t>(pool.capacity()));
}

AudioEngine::Impl::~Impl() {
    if (!al.ok()) return;
    al.make_current();
    if (!sources.empty()) {
        alSourceStopv(static_cast<ALsizei>(sources.size()), sources.data());
        alDeleteSources(static_cast<ALsizei>(sources.size()), sources.data());
    }
    if (!filters.empty()) al.delete_filters(static_cast<int>(filters.size()), filters.data());
    for (ALuint buffer : buffers)
        if (buffer) alDeleteBuffers(1, &buffer);
}

bool AudioEngine::Impl::open_sources() {
    al.make_current();
    sources.assign(static_cast<std::size_t>(pool.capacity()), 0);
    alGetError();
    alGenSources(static_cast<ALsizei>(sources.size()), sources.data());
    if (alGetError() != AL_NO_ERROR) {
        sources.clear();
        return false;
    }
    for (ALuint source : sources) alSourcef(source, AL_ROLLOFF_FACTOR, 0.0f);
    if (al.has_efx()) {
        filters.assign(sources.size(), 0);
        al.gen_filters(static_cast<int>(filters.size()), filters.data());
        if (alGetError() != AL_NO_ERROR) {
            filters.clear();
        } else {
            for (ALuint filter : filters) al.filter_i(filter, AL_FILTER_TYPE, AL_FILTER_LOWPASS);
        }
    }
    return true;
}

float AudioEngine::Impl::bus_volume(Bus bus) const {
    switch (bus) {
    case Bus::Effects:
        return volumes.effects;
    case Bus::Ambience:
        return volumes.ambience;
    case Bus::Ui:
        return 1.0f;
    }
    return 1.0f;
}

float AudioEngine::Impl::base_gain(int slot) const {
    const Voice& v = voices[static_cast<std::size_t>(slot)];
    float gain = v.volume * bus_volume(v.bus);
    if (v.positional)
        gain *= distance_gain(glm::length(positions[static_cast<std::size_t>(slot)] - listener),
                              v.ref_distance, v.max_distance);
    return gain;
}

float AudioEngine::Impl::occlusion_gain(float amount) const {
    return lerp(1.0f, filters.empty() ? kBlockedGainWithoutEfx : kBlockedGain, amount);
}

ALuint AudioEngine::Impl::buffer_for(int sound) {
    ALuint& buffer = buffers[static_cast<std::size_t>(sound)];
    if (buffer) return buffer;
    const SoundData& data = bank.at(sound);
    alGetError();
    alGenBuffers(1, &buffer);
    alBufferData(buffer, data.channels == 2 ? AL_FORMAT_STEREO16 : AL_FORMAT_MONO16, data.samples.data(),
                 static_cast<ALsizei>(data.samples.size() * sizeof(std::int16_t)), data.sample_rate);
    if (const ALenum error = alGetError(); error != AL_NO_ERROR) {
        log::warn("audio: cannot upload sound \"", bank.name_at(sound), "\" (", alGetString(error), ")");
        if (buffer) alDeleteBuffers(1, &buffer);
        buffer = 0;
    }
    return buffer;
}

void AudioEngine::Impl::apply_filter(int slot, float amount, float rear_hf) {
    Voice& v = voices[static_cast<std::size_t>(slot)];
    if (filters.empty()) return;
    const float gain = lerp(1.0f, kBlockedGain, amount),
                gain_hf = lerp(1.0f, kBlockedGainHf, amount) * rear_hf;
    if (std::abs(gain - v.applied_filter_gain) < 1e-3f && std::abs(gain_hf - v.applied_filter_hf) < 1e-3f)
        return;
    const ALuint filter = filters[static_cast<std::size_t>(slot)];
    al.filter_f(filter, AL_LOWPASS_GAIN, gain);
    al.filter_f(filter, AL_LOWPASS_GAINHF, gain_hf);
    // A source copies the filter's parameters when it is attached, so attach it again after each change.
    alSourcei(sources[static_cast<std::size_t>(slot)], AL_DIRECT_FILTER, static_cast<ALint>(filter));
    v.applied_filter_gain = gain;
    v.applied_filter_hf = gain_hf;
}

VoiceHandle AudioEngine::Impl::play(const PlayParams& params) {
    const int sound = bank.index_of(params.sound);
    if (sound < 0) {
        if (warned_missing.insert(params.sound).second)
            log::warn("audio: no sound called \"", params.sound, "\" (expected assets/sounds/", params.sound,
                      ".wav); it is not played");
        return {};
    }
    if (params.positional && !is_finite(params.position)) {
        if (!warned_bad_position)
            log::warn("audio: \"", params.sound, "\" played at a non-finite position; not played");
        warned_bad_position = true;
        return {};
    }
    Voice voice;
    voice.sound = sound;
    voice.bus = params.bus;
    voice.positional = params.positional;
    voice.game = params.game;
    voice.pending = true;
    voice.volume = std::clamp(finite_or(params.volume, 0.0f), 0.0f, 1.0f);
    voice.ref_distance = std::max(finite_or(params.ref_distance, kDefaultRefDistance), 0.01f);
    voice.max_distance = std::max(finite_or(params.max_distance, kDefaultMaxDistance), voice.ref_distance);

    // Judge the newcomer by how loud it would be; the slot is not known yet, so compute it directly.
    float gain = voice.volume * bus_volume(voice.bus);
    if (voice.positional)
        gain *=
            distance_gain(glm::length(params.position - listener), voice.ref_distance, voice.max_distance);
    const VoiceClaim claim = pool.claim(params.priority, gain);
    if (claim.slot < 0) return {};
    const ALuint buffer = buffer_for(sound);
    const ALuint source = sources[static_cast<std::size_t>(claim.slot)];
    alSourceStop(source); // a stolen voice, or a finished one the last update has not retired yet
    occlusion.stop(claim.slot);
    if (!buffer) {
        pool.release(claim.slot);
        voices[static_cast<std::size_t>(claim.slot)] = Voice{};
        return {};
    }
    voices[static_cast<std::size_t>(claim.slot)] = voice;
    positions[static_cast<std::size_t>(claim.slot)] = voice.positional ? params.position : Vec3(0.0f);
    alSourcei(source, AL_BUFFER, static_cast<ALint>(buffer));
    alSourcei(source, AL_LOOPING, params.loop ? AL_TRUE : AL_FALSE);
    alSourcef(source, AL_PITCH, std::clamp(finite_or(params.pitch, 1.0f), 0.25f, 4.0f));
    alSourcei(source, AL_SOURCE_RELATIVE, voice.positional ? AL_FALSE : AL_TRUE);
    const Vec3& p = positions[static_cast<std::size_t>(claim.slot)];
    alSource3f(source, AL_POSITION, p.x, p.y, p.z);
    if (voice.positional) occlusion.start(claim.slot);
    apply_filter(claim.slot, 0.0f, 1.0f);
    return pool.handle(claim.slot);
}

void AudioEngine::Impl::stop_slot(int slot) {
    alSourceStop(sources[static_cast<std::size_t>(slot)]);
    pool.release(slot);
    occlusion.stop(slot);
    voices[static_cast<std::size_t>(slot)] = Voice{};
}

void AudioEngine::Impl::set_game_paused(bool paused) {
    if (paused == game_paused) return;
    game_paused = paused;
    batch.clear();
    for (int slot = 0; slot < pool.capacity(); ++slot) {
        Voice& v = voices[static_cast<std::size_t>(slot)];
        if (!pool.active(slot) || !v.game || v.pending) continue; // pending game voices wait for the resume
        if (paused) {
            ALint state = AL_STOPPED;
            alGetSourcei(sources[static_cast<std::size_t>(slot)], AL_SOURCE_STATE, &state);
            if (state != AL_PLAYING) continue;
        } else if (!v.game_paused) {
            continue;
        }
        v.game_paused = paused;
        batch.push_back(sources[static_cast<std::size_t>(slot)]);
    }
    if (batch.empty()) return;
    if (paused)
        alSourcePausev(static_cast<ALsizei>(batch.size()), batch.data());
    else
        alSourcePlayv(static_cast<ALsizei>(batch.size()), batch.data());
}

void AudioEngine::Impl::retire_ended_voices() {
    for (int slot = 0; slot < pool.capacity(); ++slot) {
        if (!pool.active(slot) || voices[static_cast<std::size_t>(slot)].pending) continue;
        ALint state = AL_STOPPED;
        alGetSourcei(sources[static_cast<std::size_t>(slot)], AL_SOURCE_STATE, &state);
        if (state == AL_STOPPED) stop_slot(slot);
    }
}

void AudioEngine::Impl::start_pending_voices() {
    batch.clear();
    for (int slot = 0; slot < pool.capacity(); ++slot) {
        Voice& v = voices[static_cast<std::size_t>(slot)];
        if (!pool.active(slot) || !v.pending || (v.game && game_paused)) continue;
        v.pending = false;
        batch.push_back(sources[static_cast<std::size_t>(slot)]);
    }
    // Sounds asked for in the same frame start on the same sample.
    if (!batch.empty()) alSourcePlayv(static_cast<ALsizei>(batch.size()), batch.data());
}

void AudioEngine::Impl::update(float dt, BlockedQuery blocked) {
    retire_ended_voices();
    rays_last_update = occlusion.update(dt, listener, positions, blocked);
    for (int slot = 0; slot < pool.capacity(); ++slot) {
        if (!pool.active(slot)) continue;
        Voice& v = voices[static_cast<std::size_t>(slot)];
        const float amount = v.positional ? occlusion.amount(slot) : 0.0f;
        const float base = base_gain(slot);
        pool.set_audible_gain(slot, base * occlusion_gain(amount));
        // With EFX the filter carries the occlusion (its own broadband gain included); else the gain does.
        const float gain = filters.empty() ? base * occlusion_gain(amount) : base;
        if (std::abs(gain - v.applied_gain) > 1e-4f) {
            alSourcef(sources[static_cast<std::size_t>(slot)], AL_GAIN, gain);
            v.applied_gain = gain;
        }
        float rear_hf = 1.0f;
        if (v.positional) {
            const Vec3 to = positions[static_cast<std::size_t>(slot)] - listener;
            rear_hf = rear_highs(listener_forward, to);
        }
        apply_filter(slot, amount, rear_hf);
    }
    start_pending_voices();
}

void AudioEngine::Impl::set_listener(Vec3 position, Vec3 forward, Vec3 up) {
    if (!is_finite(position) || !is_finite(forward) || !is_finite(up)) return;
    const float fl = glm::length(forward), ul = glm::length(up);
    if (fl < 1e-6f || ul < 1e-6f || glm::length(glm::cross(forward, up)) < 1e-6f * fl * ul) return;
    listener = position;
    const Vec3 f = forward / fl, u = up / ul;
    listener_forward = f;
    const ALfloat orientation[6] = {f.x, f.y, f.z, u.x, u.y, u.z};
    alListener3f(AL_POSITION, position.x, position.y, position.z);
    alListenerfv(AL_ORIENTATION, orientation);
}

void AudioEngine::Impl::set_volumes(const Volumes& v) {
    volumes.master = std::clamp(finite_or(v.master, 1.0f), 0.0f, 1.0f);
    volumes.effects = std::clamp(finite_or(v.effects, 1.0f), 0.0f, 1.0f);
    volumes.ambience = std::clamp(finite_or(v.ambience, 1.0f), 0.0f, 1.0f);
    volumes.muted = v.muted;
    alListenerf(AL_GAIN, volumes.muted ? 0.0f : volumes.master);
}

} // namespace ks::audio
