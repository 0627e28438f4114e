#pragma once
// Looking at sounds without ears: per-sound numbers (duration, peak, RMS, spectral centroid, how fast it
// starts, how it ends or loops) and a picture (waveform over a log-frequency spectrogram). Used by
// `ks_assetgen --sound-report` and `--sound-views`.
#include "output.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::assetgen {

struct SoundStats {
    double seconds = 0.0;
    double peak_db = -200.0; // dBFS (full scale 32767)
    double rms_db = -200.0;
    // Magnitude-weighted mean frequency over 2048-sample Hann frames: where the sound's energy sits.
    double centroid_hz = 0.0;
    double onset_ms = 0.0;   // first sample at or above 1% of the peak
    double end_db = -200.0;  // the loudest of the last 48 samples, dBFS (a one-shot ends near silence)
    double seam_ratio = 0.0; // |last - first| over the mean |step| between neighbours (a loop stays small)
};

SoundStats analyse_sound(const std::vector<std::int16_t>& samples);
// The report table: a header line, then one line per sound.
std::string sound_report(const Output& out);
// DIR/<name>.png for every sound of the run: the waveform (min/max per column) above a spectrogram from
// 30 Hz to 20 kHz on a log axis, 0 to -90 dB, labelled with the numbers above.
Result<void> write_sound_views(const Output& out, const std::filesystem::path& folder);

} // namespace ks::assetgen
