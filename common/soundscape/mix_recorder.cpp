#include "soundscape/mix_recorder.h"

#include "core/log.h"

#include <cmath>

namespace ks::soundscape {

Result<std::unique_ptr<MixRecorder>> MixRecorder::open(const std::filesystem::path& wav_path,
                                                       const level::Level& level, int sample_rate) {
    std::vector<Error> problems;
    audio::SoundBank bank = audio::SoundBank::load_assets(problems);
    for (const Error& e : problems) log::warn(e.str(), " (that sound is left out of the recording)");
    auto engine = audio::AudioEngine::open_loopback(std::move(bank), sample_rate);
    if (!engine) return engine.error();
    auto recording = audio::LoopbackRecording::open(wav_path, sample_rate);
    if (!recording) return recording.error();
    std::unique_ptr<MixRecorder> r(new MixRecorder());
    r->engine_ = std::make_unique<audio::AudioEngine>(std::move(*engine));
    // The options menu's defaults (runtime/model/options.h), so a recording sounds like a fresh install.
    audio::Volumes volumes;
    volumes.master = 0.8f;
    volumes.effects = 1.0f;
    volumes.ambience = 0.7f;
    r->engine_->set_volumes(volumes);
    r->recording_ = std::make_unique<audio::LoopbackRecording>(std::move(*recording));
    r->soundscape_ = std::make_unique<Soundscape>(*r->engine_, level);
    return r;
}

MixRecorder::~MixRecorder() {
    soundscape_.reset(); // stops its voices before the engine goes
}

Result<void> MixRecorder::after_step(const game::Game& game) {
    soundscape_->after_step(game);
    return render(game, player_listener(game), game.settings().step);
}

Result<void> MixRecorder::render(const game::Game& game, const Listener& listener, double seconds) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) return {};
    soundscape_->update(game, listener, static_cast<float>(seconds));
    return recording_->record(*engine_, seconds);
}

Result<void> MixRecorder::finish() {
    return recording_->close();
}

double MixRecorder::seconds_written() const {
    return recording_->seconds_written();
}

} // namespace ks::soundscape
