#pragma once
// A loopback engine's mix written to a WAV file as time passes: record(engine, seconds) renders that much
// sound (fractions of a frame carried to the next call, so no time is lost or gained over a long run) and
// streams it to the file; close() finishes the header. Used by the game window's --audio-out and the
// headless recorder alike.
#include "audio/audio_engine.h"
#include "audio/wav.h"
#include "core/result.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace ks::audio {

class LoopbackRecording {
  public:
    static Result<LoopbackRecording> open(const std::filesystem::path& path, int sample_rate);

    // Renders `seconds` from `engine` (a loopback engine at the recording's rate) into the file.
    Result<void> record(AudioEngine& engine, double seconds);
    Result<void> close();
    double seconds_written() const;

  private:
    LoopbackRecording() = default;
    std::unique_ptr<WavWriter> writer_;
    std::vector<std::int16_t> buffer_; // a tenth of a second of stereo, reused
    double owed_frames_ = 0.0;
    int sample_rate_ = 48000;
};

} // namespace ks::audio
