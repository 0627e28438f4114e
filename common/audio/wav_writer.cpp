// Writing 16-bit PCM WAVs: whole sounds atomically through core/files, recordings streamed through a
// temporary file whose header sizes are filled in on close.
#include "audio/wav.h"
#include "core/files.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace ks::audio {
namespace {

constexpr std::size_t kHeaderBytes = 44;
// A RIFF file's sizes are 32-bit; stop well before they wrap.
constexpr std::int64_t kMaxDataBytes = 0xFFFFFFFFll - kHeaderBytes;

void put_u16(std::uint8_t* p, std::uint32_t v) {
    p[0] = static_cast<std::uint8_t>(v);
    p[1] = static_cast<std::uint8_t>(v >> 8);
}
void put_u32(std::uint8_t* p, std::uint32_t v) {
    put_u16(p, v);
    put_u16(p + 2, v >> 16);
}

// The canonical 44-byte header of a 16-bit PCM file holding `data_bytes` bytes of samples.
void fill_header(std::uint8_t* h, int sample_rate, int channels, std::uint32_t data_bytes) {
    std::memcpy(h, "RIFF", 4);
    put_u32(h + 4, 36 + data_bytes);
    std::memcpy(h + 8, "WAVEfmt ", 8);
    put_u32(h + 16, 16);
    put_u16(h + 20, 1); // PCM
    put_u16(h + 22, static_cast<std::uint32_t>(channels));
    put_u32(h + 24, static_cast<std::uint32_t>(sample_rate));
    put_u32(h + 28, static_cast<std::uint32_t>(sample_rate * channels * 2));
    put_u16(h + 32, static_cast<std::uint32_t>(channels * 2));
    put_u16(h + 34, 16);
    std::memcpy(h + 36, "data", 4);
    put_u32(h + 40, data_bytes);
}

std::optional<Error> check_shape(const std::filesystem::path& path, int sample_rate, int channels) {
    if (channels != 1 && channels != 2)
        return Error(std::to_string(channels) + " channels cannot be written", Location{path.string()},
                     "a WAV written here is mono (1) or stereo (2)");
    if (sample_rate < kMinSampleRate || sample_rate > kMaxSampleRate)
        return Error(
            "sample rate " + std::to_string(sample_rate) + " Hz cannot be written", Location{path.string()},
            "use a rate in " + std::to_string(kMinSampleRate) + ".." + std::to_string(kMaxSampleRate));
    return std::nullopt;
}

Error io_error(const std::filesystem::path& path, const std::string& what) {
    return Error(what + ": " + std::strerror(errno), Location{path.string()},
                 "check that the folder exists, is writable and the disk is not full");
}

} // namespace

std::vector<std::uint8_t> encode_wav(const SoundData& sound) {
    const std::size_t data_bytes = sound.samples.size() * 2;
    std::vector<std::uint8_t> out(kHeaderBytes + data_bytes);
    fill_header(out.data(), sound.sample_rate, sound.channels, static_cast<std::uint32_t>(data_bytes));
    std::uint8_t* p = out.data() + kHeaderBytes;
    for (std::int16_t s : sound.samples) {
        put_u16(p, static_cast<std::uint16_t>(s));
        p += 2;
    }
    return out;
}

Result<void> write_wav(const std::filesystem::path& path, const SoundData& sound) {
    if (auto problem = check_shape(path, sound.sample_rate, sound.channels)) return *problem;
    if (sound.samples.size() % static_cast<std::size_t>(sound.channels) != 0)
        return Error(std::to_string(sound.samples.size()) + " samples are not a whole number of " +
                         std::to_string(sound.channels) + "-channel frames",
                     Location{path.string()}, "give every channel a sample in each frame");
    if (static_cast<std::int64_t>(sound.samples.size()) * 2 > kMaxDataBytes)
        return Error("the sound is too long for a WAV file (over 4 GiB)", Location{path.string()});
    const std::vector<std::uint8_t> bytes = encode_wav(sound);
    return files::write_atomic(path,
                               std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

Result<WavWriter> WavWriter::open(const std::filesystem::path& path, int sample_rate, int channels) {
    if (auto problem = check_shape(path, sample_rate, channels)) return *problem;
    auto created = files::create_temp_beside(path);
    if (!created) return created.error();
    const int fd = created->fd;
    const std::string temp = created->path.string();
    WavWriter writer;
    writer.file_ = ::fdopen(fd, "wb");
    if (!writer.file_) {
        ::close(fd);
        ::unlink(temp.c_str());
        return io_error(path, "cannot open the temporary file");
    }
    writer.path_ = path;
    writer.temp_path_ = temp;
    writer.sample_rate_ = sample_rate;
    writer.channels_ = channels;
    std::uint8_t header[kHeaderBytes];
    fill_header(header, sample_rate, channels, 0); // sizes are fixed up on close
    if (std::fwrite(header, 1, kHeaderBytes, writer.file_) != kHeaderBytes)
        return io_error(path, "write failed");
    return writer;
}

WavWriter::WavWriter(WavWriter&& other) noexcept {
    *this = std::move(other);
}

WavWriter& WavWriter::operator=(WavWriter&& other) noexcept {
    if (this != &other) {
        discard();
        path_ = std::move(other.path_);
        temp_path_ = std::move(other.temp_path_);
        file_ = std::exchange(other.file_, nullptr);
        sample_rate_ = other.sample_rate_;
        channels_ = other.channels_;
        frames_written_ = other.frames_written_;
    }
    return *this;
}

WavWriter::~WavWriter() {
    discard();
}

void WavWriter::discard() {
    if (!file_) return;
    std::fclose(file_);
    file_ = nullptr;
    ::unlink(temp_path_.c_str());
}

Result<void> WavWriter::write(const std::int16_t* interleaved, int frames) {
    if (!file_)
        return Error("the recording is already closed", Location{path_.string()}, "open a new WavWriter");
    if (frames <= 0) return ok();
    if ((frames_written_ + frames) * channels_ * 2 > kMaxDataBytes)
        return Error("the recording is too long for a WAV file (over 4 GiB)", Location{path_.string()},
                     "close it and start a new file");
    const std::size_t count = static_cast<std::size_t>(frames) * static_cast<std::size_t>(channels_);
    // Little-endian on disk; convert in small blocks so a long write allocates nothing.
    std::uint8_t block[4096];
    std::size_t done = 0;
    while (done < count) {
        const std::size_t n = std::min(count - done, sizeof(block) / 2);
        for (std::size_t i = 0; i < n; ++i)
            put_u16(block + 2 * i, static_cast<std::uint16_t>(interleaved[done + i]));
        if (std::fwrite(block, 2, n, file_) != n) return io_error(path_, "write failed");
        done += n;
    }
    frames_written_ += frames;
    return ok();
}

Result<void> WavWriter::close() {
    if (!file_)
        return Error("the recording is already closed", Location{path_.string()}, "open a new WavWriter");
    std::uint8_t header[kHeaderBytes];
    fill_header(header, sample_rate_, channels_, static_cast<std::uint32_t>(frames_written_ * channels_ * 2));
    const bool written = std::fseek(file_, 0, SEEK_SET) == 0 &&
                         std::fwrite(header, 1, kHeaderBytes, file_) == kHeaderBytes &&
                         std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
    if (!written) {
        Error problem = io_error(path_, "finishing the recording failed");
        discard();
        return problem;
    }
    ::fchmod(::fileno(file_), 0644);
    std::fclose(file_);
    file_ = nullptr;
    if (::rename(temp_path_.c_str(), path_.c_str()) != 0) {
        Error problem = io_error(path_, "rename over the target failed");
        ::unlink(temp_path_.c_str());
        return problem;
    }
    return ok();
}

} // namespace ks::audio
