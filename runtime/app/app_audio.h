#pragma once
// The game window's sound: the audio engine (the sound card, or silence with one notice line when there is
// none), the player's volume options, the menu's hover and click sounds, and — with --audio-out FILE.wav —
// a loopback engine whose mix is written to that file frame by frame instead of played (deterministic with
// --screenshot --frames: fixed 1/60 s frames). Sessions' Soundscapes play through engine().
#include "audio/audio_engine.h"
#include "audio/loopback_recording.h"
#include "core/result.h"
#include "menu_style.h"
#include "runtime/model/options.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ks::runtime {

class AppAudio {
  public:
    // `record_to` empty: the sound card. Otherwise a loopback engine recording to that WAV file.
    static Result<std::unique_ptr<AppAudio>> open(const std::filesystem::path& record_to);
    ~AppAudio();

    audio::AudioEngine& engine() { return *engine_; }
    void apply_options(const Options& options);
    // The menu's sounds: a tick when the mouse moves onto a button, a click when one is pressed.
    void menu_sounds(const std::vector<ui::ButtonRect>& buttons);
    // End of a frame: `engine_updated` when a Soundscape already ran the engine's update this frame. When
    // recording, mixes `seconds` of sound into the file.
    void end_frame(double seconds, bool engine_updated);
    bool recording() const { return recording_ != nullptr; }
    // Closes the recording (the WAV's header sizes); nothing to do when playing to the sound card.
    Result<void> finish();

  private:
    AppAudio() = default;
    void play_ui(const char* sound);

    std::unique_ptr<audio::AudioEngine> engine_;
    std::unique_ptr<audio::LoopbackRecording> recording_;
    std::string hovered_;
};

} // namespace ks::runtime
