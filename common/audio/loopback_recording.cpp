#include "audio/loopback_recording.h"

#include <algorithm>
#include <cmath>

namespace ks::audio {

Result<LoopbackRecording> LoopbackRecording::open(const std::filesystem::path& path, int sample_rate) {
    auto writer = WavWriter::open(path, sample_rate, 2);
    if (!writer) return writer.error();
    LoopbackRecording r;
    r.writer_ = std::make_unique<WavWriter>(std::move(*writer));
    r.sample_rate_ = sample_rate;
    r.buffer_.resize(static_cast<std::size_t>(sample_rate) / 10 * 2);
    return r;
}

Result<void> LoopbackRecording::record(AudioEngine& engine, double seconds) {
    if (!writer_ || !(seconds > 0.0) || !std::isfinite(seconds)) return {};
    owed_frames_ += seconds * sample_rate_;
    auto frames = static_cast<int>(std::floor(owed_frames_ + 1e-6));
    owed_frames_ -= frames;
    const int chunk = static_cast<int>(buffer_.size() / 2);
    while (frames > 0) {
        const int n = std::min(frames, chunk);
        engine.render(buffer_.data(), n);
        if (auto w = writer_->write(buffer_.data(), n); !w) return w;
        frames -= n;
    }
    return {};
}

Result<void> LoopbackRecording::close() {
    if (!writer_) return {};
    auto closed = writer_->close();
    writer_.reset();
    return closed;
}

double LoopbackRecording::seconds_written() const {
    return writer_ ? static_cast<double>(writer_->frames_written()) / sample_rate_ : 0.0;
}

} // namespace ks::audio
