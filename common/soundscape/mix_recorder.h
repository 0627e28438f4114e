#pragma once
// Renders what a run sounds like into a WAV file (`killswitch --headless --audio-out FILE.wav`, and the
// windowed game's `--audio-out` with --screenshot --frames): a Soundscape on a loopback engine (no sound card
// needed), mixed to 48 kHz 16-bit stereo. Deterministic: the same run (seed, level, inputs) writes the same
// bytes, because the mix depends only on the calls made, never on a clock.
#include "audio/audio_engine.h"
#include "audio/loopback_recording.h"
#include "core/result.h"
#include "soundscape/soundscape.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace ks::soundscape {

class MixRecorder {
  public:
    // Opens the loopback engine on assets/sounds/ (a broken sound file is a warning; that sound is left out)
    // and the output file. The level gives the ambience and emitters.
    static Result<std::unique_ptr<MixRecorder>> open(const std::filesystem::path& wav_path,
                                                     const level::Level& level, int sample_rate = 48000);
    ~MixRecorder();

    // After each game step: the step's sounds, the listener at the player's eye, one step of samples.
    Result<void> after_step(const game::Game& game);
    // `seconds` more of the mix heard from `listener` with no new step (the tail after a run ends).
    Result<void> render(const game::Game& game, const Listener& listener, double seconds);
    // Writes the header's sizes and moves the file into place.
    Result<void> finish();

    double seconds_written() const;
    const audio::AudioEngine& engine() const { return *engine_; }

  private:
    MixRecorder() = default;
    std::unique_ptr<audio::AudioEngine> engine_;
    std::unique_ptr<Soundscape> soundscape_;
    std::unique_ptr<audio::LoopbackRecording> recording_;
};

} // namespace ks::soundscape
