#pragma once
// Test signals and measurements for the loopback tests: deterministic white noise and tones, RMS per
// channel, and the energy above a cutoff (a second-order high-pass).
#include "audio/audio_engine.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace ks::test {

// One second of mono white noise at 48 kHz, peak 0.5 of full scale (an LCG: the same on every machine).
inline audio::SoundData white_noise(int seconds = 1) {
    audio::SoundData sound;
    sound.sample_rate = 48000;
    sound.channels = 1;
    std::uint32_t state = 12345u;
    for (int i = 0; i < 48000 * seconds; ++i) {
        state = state * 1664525u + 1013904223u;
        sound.samples.push_back(static_cast<std::int16_t>((static_cast<int>(state >> 16) - 32768) / 2));
    }
    return sound;
}

// Renders `frames` stereo frames from the engine.
inline std::vector<std::int16_t> render(audio::AudioEngine& engine, int frames) {
    std::vector<std::int16_t> out(static_cast<std::size_t>(frames) * 2);
    engine.render(out.data(), frames);
    return out;
}

// RMS of one channel (0 left, 1 right) of interleaved stereo, in 16-bit units.
inline double rms(const std::vector<std::int16_t>& stereo, int channel) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = static_cast<std::size_t>(channel); i < stereo.size(); i += 2, ++n)
        sum += static_cast<double>(stereo[i]) * stereo[i];
    return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

inline double rms_both(const std::vector<std::int16_t>& stereo) {
    const double l = rms(stereo, 0), r = rms(stereo, 1);
    return std::sqrt(0.5 * (l * l + r * r));
}

// RMS of the left channel after a second-order Butterworth filter (RBJ biquad) at `cutoff` Hz: a high-pass
// (the energy above the cutoff) or a low-pass (below it).
inline double band_rms(const std::vector<std::int16_t>& stereo, double cutoff, bool high_pass,
                       double rate = 48000.0) {
    const double w = 2.0 * 3.14159265358979 * cutoff / rate, alpha = std::sin(w) / (2.0 * std::sqrt(0.5));
    const double c = std::cos(w), a0 = 1.0 + alpha;
    const double b0 = (high_pass ? (1.0 + c) : (1.0 - c)) / 2.0 / a0;
    const double b1 = (high_pass ? -(1.0 + c) : (1.0 - c)) / a0, b2 = b0;
    const double a1 = -2.0 * c / a0, a2 = (1.0 - alpha) / a0;
    double x1 = 0, x2 = 0, y1 = 0, y2 = 0, sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < stereo.size(); i += 2, ++n) {
        const double x = stereo[i];
        const double y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
        x2 = x1, x1 = x, y2 = y1, y1 = y;
        sum += y * y;
    }
    return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

inline double high_band_rms(const std::vector<std::int16_t>& stereo, double cutoff) {
    return band_rms(stereo, cutoff, true);
}
inline double low_band_rms(const std::vector<std::int16_t>& stereo, double cutoff) {
    return band_rms(stereo, cutoff, false);
}

inline double db(double ratio) {
    return 20.0 * std::log10(ratio);
}

} // namespace ks::test
