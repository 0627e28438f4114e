#pragma once
// RIFF/WAVE files: the one sound format the game reads (assets/sounds/*.wav) and writes (the sound
// generator, loopback recordings). Everything is converted to 16-bit signed samples on load, which is what
// the mixer is given; no OpenAL here, so tools can use it without an audio device.
#include "core/result.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace ks::audio {

// Interleaved 16-bit samples: frame i of a stereo sound is samples[2i] (left), samples[2i + 1] (right).
struct SoundData {
    int sample_rate = 48000;
    int channels = 1; // 1 or 2
    std::vector<std::int16_t> samples;

    int frames() const { return channels > 0 ? static_cast<int>(samples.size()) / channels : 0; }
    float seconds() const { return sample_rate > 0 ? static_cast<float>(frames()) / sample_rate : 0.0f; }
};

// Sample rates accepted on read and write; anything outside is a broken header, not a real recording.
inline constexpr int kMinSampleRate = 1000;
inline constexpr int kMaxSampleRate = 384000;

// Reads PCM 8-bit (unsigned), 16/24/32-bit (signed) and 32-bit float WAVs (also in WAVE_FORMAT_EXTENSIBLE
// wrappers), mono or stereo, any rate in [kMinSampleRate, kMaxSampleRate]; unknown chunks are skipped.
// Every error names the file, what is wrong, and how to fix it.
Result<SoundData> read_wav(const std::filesystem::path& path);

// The bytes of a 16-bit PCM WAV holding `sound` (header included).
std::vector<std::uint8_t> encode_wav(const SoundData& sound);

// Writes `sound` as 16-bit PCM, atomically (a crash mid-write leaves the old file or the new one).
Result<void> write_wav(const std::filesystem::path& path, const SoundData& sound);

// Streams 16-bit PCM frames to a file of unknown final length (a recording). The data goes to a temporary
// file next to the target; close() writes the final RIFF and data sizes into the header and renames it over
// the target, so an unfinished recording never replaces a good file. Destroying an unclosed writer discards
// it.
class WavWriter {
  public:
    static Result<WavWriter> open(const std::filesystem::path& path, int sample_rate = 48000,
                                  int channels = 2);

    WavWriter(WavWriter&& other) noexcept;
    WavWriter& operator=(WavWriter&& other) noexcept;
    WavWriter(const WavWriter&) = delete;
    WavWriter& operator=(const WavWriter&) = delete;
    ~WavWriter();

    // `frames` frames of interleaved samples (frames * channels values).
    Result<void> write(const std::int16_t* interleaved, int frames);
    Result<void> close();

    int frames_written() const { return static_cast<int>(frames_written_); }

  private:
    WavWriter() = default;
    void discard();

    std::filesystem::path path_;
    std::filesystem::path temp_path_;
    std::FILE* file_ = nullptr;
    int sample_rate_ = 0;
    int channels_ = 0;
    std::int64_t frames_written_ = 0;
};

} // namespace ks::audio
