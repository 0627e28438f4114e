#include "sound_audition.h"

#include "audio/audio_engine.h"
#include "core/log.h"

#include <memory>

namespace ks::editor::ui {
namespace {

class Auditioner {
  public:
    void play(const std::string& sound, float volume) {
        if (!engine_ || !engine_->sounds().find(sound)) open(); // first use, or a file added since
        audio::PlayParams p;
        p.sound = sound;
        p.positional = false;
        p.volume = volume;
        p.bus = audio::Bus::Ui;
        p.game = false;
        engine_->stop_all(); // one audition at a time: a loop must not run on behind the next
        engine_->play(p);
        engine_->update(0.0f); // the editor has no audio frame: start the voice now
    }

  private:
    void open() {
        std::vector<Error> problems;
        audio::SoundBank bank = audio::SoundBank::load_assets(problems);
        for (const Error& e : problems) log::warn(e.str(), " (that sound cannot be auditioned)");
        engine_ = std::make_unique<audio::AudioEngine>(audio::AudioEngine::open_device(std::move(bank)));
    }
    std::unique_ptr<audio::AudioEngine> engine_;
};

} // namespace

SoundAudition make_sound_audition() {
    auto player = std::make_shared<Auditioner>();
    return [player](const std::string& sound, float volume) { player->play(sound, volume); };
}

} // namespace ks::editor::ui
