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
    auto recording = audio::LoopbackRecording::open(record_to, engine->sample_rate());
    if (!recording) return recording.error();
    a->engine_ = std::make_unique<audio::AudioEngine>(std::move(*engine));
    a->recording_ = std::make_unique<audio::LoopbackRecording>(std::move(*recording));
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
    if (!recording_) return;
    if (auto recorded = recording_->record(*engine_, seconds); !recorded) {
        log::error(recorded.error().str(), " (recording stopped)");
        recording_.reset();
    }
}

Result<void> AppAudio::finish() {
    if (!recording_) return {};
    auto closed = recording_->close();
    recording_.reset();
    return closed;
}

} // namespace ks::runtime
