// Opening the engine (device, loopback or silent) and the public calls, which forward to the Impl when there
// is an output and do nothing when there is none.
#include "audio/audio_engine.h"
#include "audio/audio_engine_impl.h"
#include "core/log.h"

#include <algorithm>

namespace ks::audio {

AudioEngine::AudioEngine(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
AudioEngine::AudioEngine(AudioEngine&&) noexcept = default;
AudioEngine& AudioEngine::operator=(AudioEngine&&) noexcept = default;
AudioEngine::~AudioEngine() = default;

AudioEngine AudioEngine::silent(SoundBank sounds, EngineSettings settings) {
    return AudioEngine(std::make_unique<Impl>(std::move(sounds), settings));
}

AudioEngine AudioEngine::open_device(SoundBank sounds, EngineSettings settings) {
    auto impl = std::make_unique<Impl>(std::move(sounds), settings);
    std::string reason;
    if (!impl->al.open_default(impl->pool.capacity(), reason)) {
        log::info("audio: no output device (", reason, "); running silently");
        return AudioEngine(std::move(impl));
    }
    if (!impl->open_sources()) {
        log::info("audio: no output device (cannot create ", impl->pool.capacity(),
                  " sources); running silently");
        return silent(std::move(impl->bank), settings);
    }
    impl->set_volumes(Volumes{});
    return AudioEngine(std::move(impl));
}

Result<AudioEngine> AudioEngine::open_loopback(SoundBank sounds, int sample_rate, EngineSettings settings) {
    auto impl = std::make_unique<Impl>(std::move(sounds), settings);
    std::string reason;
    if (!impl->al.open_loopback(sample_rate, impl->pool.capacity(), reason))
        return Error("audio: cannot open a loopback device: " + reason, Location{"OpenAL"},
                     "install OpenAL Soft (libopenal-dev), which has ALC_SOFT_loopback");
    if (!impl->open_sources())
        return Error("audio: cannot create " + std::to_string(impl->pool.capacity()) + " sources",
                     Location{"OpenAL"}, "ask for fewer voices (EngineSettings::voices)");
    impl->set_volumes(Volumes{});
    return AudioEngine(std::move(impl));
}

VoiceHandle AudioEngine::play(const PlayParams& params) {
    if (!impl_->al.ok()) return {};
    impl_->al.make_current();
    return impl_->play(params);
}

void AudioEngine::set_position(VoiceHandle voice, Vec3 position) {
    const int slot = impl_->pool.find(voice);
    if (slot < 0 || !impl_->voices[static_cast<std::size_t>(slot)].positional || !is_finite(position)) return;
    impl_->positions[static_cast<std::size_t>(slot)] = position;
    impl_->al.make_current();
    alSource3f(impl_->sources[static_cast<std::size_t>(slot)], AL_POSITION, position.x, position.y,
               position.z);
}

void AudioEngine::set_volume(VoiceHandle voice, float volume) {
    const int slot = impl_->pool.find(voice);
    if (slot < 0 || !std::isfinite(volume)) return;
    impl_->voices[static_cast<std::size_t>(slot)].volume =
        std::clamp(volume, 0.0f, 1.0f); // applied by update
}

void AudioEngine::stop(VoiceHandle voice) {
    const int slot = impl_->pool.find(voice);
    if (slot < 0) return;
    impl_->al.make_current();
    impl_->stop_slot(slot);
}

bool AudioEngine::is_playing(VoiceHandle voice) const {
    return impl_->pool.find(voice) >= 0;
}

void AudioEngine::stop_all() {
    if (!impl_->al.ok()) return;
    impl_->al.make_current();
    for (int slot = 0; slot < impl_->pool.capacity(); ++slot)
        if (impl_->pool.active(slot)) impl_->stop_slot(slot);
}

void AudioEngine::set_listener(Vec3 position, Vec3 forward, Vec3 up) {
    if (!impl_->al.ok()) return;
    impl_->al.make_current();
    impl_->set_listener(position, forward, up);
}

void AudioEngine::set_volumes(const Volumes& volumes) {
    if (!impl_->al.ok()) return;
    impl_->al.make_current();
    impl_->set_volumes(volumes);
}

void AudioEngine::set_game_paused(bool paused) {
    if (!impl_->al.ok()) return;
    impl_->al.make_current();
    impl_->set_game_paused(paused);
}

void AudioEngine::update(float dt, BlockedQuery blocked) {
    if (!impl_->al.ok()) return;
    impl_->al.make_current();
    impl_->update(dt, blocked);
}

void AudioEngine::update(float dt) {
    update(dt, [](Vec3, Vec3) { return false; });
}

void AudioEngine::render(std::int16_t* interleaved_stereo, int frames) {
    if (frames <= 0) return;
    if (!impl_->al.loopback()) {
        std::fill(interleaved_stereo, interleaved_stereo + 2 * static_cast<std::size_t>(frames),
                  std::int16_t{0});
        return;
    }
    impl_->al.render(interleaved_stereo, frames);
}

AudioStats AudioEngine::stats() const {
    AudioStats s;
    s.output = impl_->al.ok();
    s.efx = !impl_->filters.empty();
    s.active_voices = impl_->pool.active_count();
    s.voice_limit = impl_->pool.capacity();
    s.stolen = impl_->pool.stolen();
    s.dropped = impl_->pool.dropped();
    s.rays_this_update = impl_->rays_last_update;
    return s;
}

int AudioEngine::sample_rate() const {
    return impl_->al.ok() ? impl_->al.sample_rate() : 0;
}
const SoundBank& AudioEngine::sounds() const {
    return impl_->bank;
}

} // namespace ks::audio
