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
    auto writer = audio::WavWriter::open(wav_path, sample_rate, 2);
    if (!writer) return writer.error();
    std::unique_ptr<MixRecorder> r(new MixRecorder());
    r->sample_rate_ = sample_rate;
    r->engine_ = std::make_unique<audio::AudioEngine>(std::move(*engine));
    // The options menu's defaults (runtime/app/options.h), so a recording sounds like a fresh install.
    audio::Volumes volumes;
    volumes.master = 0.8f;
    volumes.effects = 1.0f;
    volumes.ambience = 0.7f;
    r->engine_->set_volumes(volumes);
    r->writer_ = std::make_unique<audio::WavWriter>(std::move(*writer));
    r->soundscape_ = std::make_unique<Soundscape>(*r->engine_, level);
    r->buffer_.resize(static_cast<std::size_t>(sample_rate) * 2 / 10); // a tenth of a second, reused
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
    owed_frames_ += seconds * sample_rate_;
    auto frames = static_cast<int>(std::floor(owed_frames_ + 1e-6));
    owed_frames_ -= frames;
    const int chunk = static_cast<int>(buffer_.size() / 2);
    while (frames > 0) {
        const int n = std::min(frames, chunk);
        engine_->render(buffer_.data(), n);
        if (auto w = writer_->write(buffer_.data(), n); !w) return w;
        frames -= n;
    }
    return {};
}

Result<void> MixRecorder::finish() {
    return writer_->close();
}

double MixRecorder::seconds_written() const {
    return static_cast<double>(writer_->frames_written()) / sample_rate_;
}

} // namespace ks::soundscape
