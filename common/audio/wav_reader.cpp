// Reading RIFF/WAVE: walk the chunks, check the fmt chunk against what we can decode, convert the data chunk
// to 16-bit. The whole file is read at once; sounds are small.
#include "audio/wav.h"
#include "core/files.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

namespace ks::audio {
namespace {

constexpr std::uint16_t kFormatPcm = 1;
constexpr std::uint16_t kFormatFloat = 3;
constexpr std::uint16_t kFormatExtensible = 0xFFFE;
constexpr const char* kExportHint = "export it as 16-bit PCM WAV (mono or stereo)";

std::uint16_t u16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
std::uint32_t u32(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
           (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

// The usual name of a WAVE format tag, so "unsupported format 85" also says "MP3".
std::string_view format_name(std::uint16_t tag) {
    switch (tag) {
    case 2:
        return "Microsoft ADPCM";
    case 6:
        return "A-law";
    case 7:
        return "mu-law";
    case 0x11:
        return "IMA ADPCM";
    case 0x31:
        return "GSM 6.10";
    case 0x50:
        return "MPEG";
    case 0x55:
        return "MP3";
    case 0xFF:
        return "AAC";
    case 0x161:
        return "WMA";
    default:
        return "";
    }
}

struct Format {
    std::uint16_t tag = 0; // kFormatPcm or kFormatFloat after unwrapping WAVE_FORMAT_EXTENSIBLE
    int channels = 0;
    int sample_rate = 0;
    int block_align = 0;
    int bits = 0;
};

class Reader {
  public:
    explicit Reader(const std::filesystem::path& path) : path_(path) {}

    Error error(const std::string& what, std::string hint = kExportHint) const {
        return Error(what, Location{path_.string()}, std::move(hint));
    }

    std::optional<Error> parse_format(const std::uint8_t* p, std::uint32_t size, Format& out) const {
        if (size < 16) return error("fmt chunk is " + std::to_string(size) + " bytes, needs at least 16");
        out.tag = u16(p);
        out.channels = u16(p + 2);
        out.sample_rate = static_cast<int>(std::min<std::uint32_t>(u32(p + 4), 0x7fffffff));
        out.block_align = u16(p + 12);
        out.bits = u16(p + 14);
        if (out.tag == kFormatExtensible) {
            if (size < 26)
                return error("extensible fmt chunk is " + std::to_string(size) + " bytes, needs 26");
            out.tag = u16(p + 24); // the first two bytes of the sub-format GUID are the plain format tag
        }
        if (out.tag != kFormatPcm && out.tag != kFormatFloat) {
            std::string name(format_name(out.tag));
            return error("unsupported format " + std::to_string(out.tag) +
                         (name.empty() ? "" : " (" + name + " in WAV)"));
        }
        if (out.channels == 0)
            return error("0 channels in the fmt chunk", "the header is broken; " + std::string(kExportHint));
        if (out.channels > 2)
            return error(std::to_string(out.channels) + " channels; only mono and stereo are played",
                         "mix it down to mono (positional sounds) or stereo");
        if (out.sample_rate < kMinSampleRate || out.sample_rate > kMaxSampleRate)
            return error("sample rate " + std::to_string(out.sample_rate) + " Hz is outside " +
                             std::to_string(kMinSampleRate) + ".." + std::to_string(kMaxSampleRate),
                         "the header is broken; export it at 48000 Hz");
        const bool pcm_ok =
            out.tag == kFormatPcm && (out.bits == 8 || out.bits == 16 || out.bits == 24 || out.bits == 32);
        const bool float_ok = out.tag == kFormatFloat && out.bits == 32;
        if (!pcm_ok && !float_ok)
            return error(std::to_string(out.bits) + "-bit " + (out.tag == kFormatFloat ? "float" : "PCM") +
                         " samples are not supported (8, 16, 24, 32-bit PCM and 32-bit float are)");
        if (out.block_align != out.channels * out.bits / 8)
            return error("block align " + std::to_string(out.block_align) + " does not match " +
                             std::to_string(out.channels) + " channels of " + std::to_string(out.bits) +
                             " bits",
                         "the header is broken; " + std::string(kExportHint));
        return std::nullopt;
    }

  private:
    std::filesystem::path path_;
};

std::int16_t to_16(const std::uint8_t* p, const Format& f) {
    if (f.tag == kFormatFloat) {
        float v;
        std::memcpy(&v, p, 4);
        if (!std::isfinite(v)) return 0;
        return static_cast<std::int16_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f));
    }
    switch (f.bits) {
    case 8:
        return static_cast<std::int16_t>((static_cast<int>(p[0]) - 128) * 256);
    case 16:
        return static_cast<std::int16_t>(u16(p));
    case 24:
        return static_cast<std::int16_t>(u16(p + 1)); // the top 16 of 24 bits
    default:
        return static_cast<std::int16_t>(u16(p + 2)); // the top 16 of 32 bits
    }
}

} // namespace

Result<SoundData> read_wav(const std::filesystem::path& path) {
    auto text = files::read_text(path);
    if (!text) return text.error();
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(text->data());
    const std::size_t size = text->size();
    Reader reader(path);

    if (size < 12 || std::memcmp(bytes, "RIFF", 4) != 0 || std::memcmp(bytes + 8, "WAVE", 4) != 0)
        return reader.error("not a RIFF/WAVE file (the first 12 bytes are not \"RIFF....WAVE\")");

    std::optional<Format> format;
    std::size_t at = 12;
    while (at + 8 <= size) {
        const std::string id(reinterpret_cast<const char*>(bytes + at), 4);
        const std::uint32_t chunk_size = u32(bytes + at + 4);
        const std::uint8_t* body = bytes + at + 8;
        const std::size_t available = size - at - 8;
        if (id == "fmt ") {
            if (chunk_size > available) return reader.error("the file is truncated inside the fmt chunk");
            Format f;
            if (auto problem = reader.parse_format(body, chunk_size, f)) return *problem;
            format = f;
        } else if (id == "data") {
            if (!format) return reader.error("the data chunk comes before any fmt chunk");
            if (chunk_size > available)
                return reader.error("the file is truncated: the data chunk says " +
                                        std::to_string(chunk_size) + " bytes but only " +
                                        std::to_string(available) + " follow",
                                    "the file was cut off while copying or saving; export it again");
            const std::size_t frame_bytes = static_cast<std::size_t>(format->block_align);
            const std::size_t frames = chunk_size / frame_bytes; // a trailing partial frame is dropped
            if (frames == 0)
                return reader.error("the data chunk holds no samples", "export a sound that is not empty");
            SoundData sound;
            sound.sample_rate = format->sample_rate;
            sound.channels = format->channels;
            sound.samples.resize(frames * static_cast<std::size_t>(format->channels));
            const std::size_t sample_bytes = static_cast<std::size_t>(format->bits / 8);
            for (std::size_t i = 0; i < sound.samples.size(); ++i)
                sound.samples[i] = to_16(body + i * sample_bytes, *format);
            return sound;
        }
        // Chunks are padded to an even size; skip unknown ones (LIST, cue, bext, ...).
        at += 8 + static_cast<std::size_t>(chunk_size) + (chunk_size & 1u);
    }
    if (!format) return reader.error("no fmt chunk (the header describing the samples is missing)");
    return reader.error("no data chunk (the file has a header but no samples)",
                        "the file may be truncated; export it again");
}

} // namespace ks::audio
