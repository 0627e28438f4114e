#include "app_audio.h"

#include "core/log.h"

#include <cmath>

namespace ks::runtime {

Result<std::unique_ptr<AppAudio>> AppAudio::open(const std::filesystem::path& record_to) {
    std::vector<Error> problems;
    audio::SoundBank bank = audio::SoundBank::load_assets(problems);
    for (const Error& e : problems) log::warn(e.str(), " (the game goes on without that sound)");
    std::unique_ptr<AppAudio> a(new AppAudio());
    if (record_to.empty()) {
        a->engine_ = std::make_unique<audio::AudioEngine>(audio::AudioEngine::open_device(std::move(bank)));
        return a;
    }
    auto engine = audio::AudioEngine::open_loopback(std::move(bank));
    if (!engine) return engine.error();
    auto writer = audio::WavWriter::open(record_to, engine->sample_rate(), 2);
    if (!writer) return writer.error();
    a->engine_ = std::make_unique<audio::AudioEngine>(std::move(*engine));
    a->recording_ = std::make_unique<audio::WavWriter>(std::move(*writer));
    a->buffer_.resize(static_cast<std::size_t>(a->engine_->sample_rate()) / 5 * 2);
    return a;
}

AppAudio::~AppAudio() {
    if (recording_)
        if (auto closed = recording_->close(); !closed) log::warn(closed.error().str());
}

void AppAudio::apply_options(const Options& options) {
    audio::Volumes v;
    v.master = options.master_volume;
    v.effects = options.effects_volume;
    v.ambience = options.ambience_volume;
    v.muted = options.muted;
    engine_->set_volumes(v);
}

void AppAudio::play_ui(const char* sound) {
    audio::PlayParams p;
    p.sound = sound;
    p.positional = false;
    p.bus = audio::Bus::Ui;
    p.game = false;
    p.priority = 3;
    p.volume = 0.7f;
    engine_->play(p);
}

void AppAudio::menu_sounds(const std::vector<ui::ButtonRect>& buttons) {
    std::string hovered;
    bool clicked = false;
    for (const ui::ButtonRect& b : buttons) {
        if (b.hovered && hovered.empty()) hovered = b.label;
        clicked = clicked || b.clicked;
    }
    if (clicked)
        play_ui("ui_click");
    else if (!hovered.empty() && hovered != hovered_)
        play_ui("ui_hover");
    hovered_ = hovered;
}

void AppAudio::end_frame(double seconds, bool engine_updated) {
    if (!engine_updated) engine_->update(static_cast<float>(seconds));
    if (!recording_ || !(seconds > 0.0) || !std::isfinite(seconds)) return;
    owed_frames_ += seconds * engine_->sample_rate();
    auto frames = static_cast<int>(std::floor(owed_frames_ + 1e-6));
    owed_frames_ -= frames;
    const int chunk = static_cast<int>(buffer_.size() / 2);
    while (frames > 0) {
        const int n = std::min(frames, chunk);
        engine_->render(buffer_.data(), n);
        if (auto w = recording_->write(buffer_.data(), n); !w) {
            log::error(w.error().str(), " (recording stopped)");
            recording_.reset();
            return;
        }
        frames -= n;
    }
}

Result<void> AppAudio::finish() {
    if (!recording_) return {};
    auto closed = recording_->close();
    recording_.reset();
    return closed;
}

} // namespace ks::runtime
