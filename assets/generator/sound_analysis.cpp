#include "sound_analysis.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

namespace ks::assetgen {
namespace {
constexpr double kRate = 48000.0;
constexpr int kFrame = 2048;
constexpr double kAnalysisPi = 3.14159265358979323846;

double to_db(double v) {
    return v > 0.0 ? 20.0 * std::log10(v) : -200.0;
}

// In-place iterative radix-2 FFT (the size a power of two).
void fft(std::vector<std::complex<double>>& a) {
    const std::size_t n = a.size();
    for (std::size_t i = 1, j = 0; i < n; ++i) {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(a[i], a[j]);
    }
    for (std::size_t len = 2; len <= n; len <<= 1) {
        const std::complex<double> step = std::polar(1.0, -2.0 * kAnalysisPi / static_cast<double>(len));
        for (std::size_t i = 0; i < n; i += len) {
            std::complex<double> w(1.0, 0.0);
            for (std::size_t k = 0; k < len / 2; ++k) {
                const std::complex<double> u = a[i + k], v = a[i + k + len / 2] * w;
                a[i + k] = u + v;
                a[i + k + len / 2] = u - v;
                w *= step;
            }
        }
    }
}

// Magnitudes (bins 0..kFrame/2) of the Hann-windowed frame starting at `start` (zeros past the end).
std::vector<double> spectrum(const std::vector<std::int16_t>& samples, std::ptrdiff_t start) {
    std::vector<std::complex<double>> a(kFrame);
    for (int i = 0; i < kFrame; ++i) {
        const std::ptrdiff_t at = start + i;
        const double v = at >= 0 && at < static_cast<std::ptrdiff_t>(samples.size())
                             ? samples[static_cast<std::size_t>(at)] / 32767.0
                             : 0.0;
        a[static_cast<std::size_t>(i)] = v * (0.5 - 0.5 * std::cos(2.0 * kAnalysisPi * i / kFrame));
    }
    fft(a);
    std::vector<double> mag(kFrame / 2 + 1);
    for (std::size_t k = 0; k < mag.size(); ++k) mag[k] = std::abs(a[k]) * (4.0 / kFrame);
    return mag;
}

// Black through purple, red and orange to pale yellow.
Color heat(double x) {
    static const Color stops[] = {{0.0f, 0.0f, 0.02f, 1.0f},
                                  {0.3f, 0.05f, 0.45f, 1.0f},
                                  {0.8f, 0.2f, 0.25f, 1.0f},
                                  {0.98f, 0.6f, 0.1f, 1.0f},
                                  {1.0f, 0.98f, 0.7f, 1.0f}};
    const double t = std::clamp(x, 0.0, 1.0) * 4.0;
    const int i = std::min(3, static_cast<int>(t));
    return mix(stops[i], stops[i + 1], static_cast<float>(t - i));
}

void draw_waveform(Image& image, const std::vector<std::int16_t>& samples, int top, int height) {
    const int mid = top + height / 2;
    for (int x = 0; x < image.width; ++x) image.at(x, mid) = Color(0.3f, 0.3f, 0.35f, 1.0f);
    for (int x = 0; x < image.width; ++x) {
        const std::size_t from =
            samples.size() * static_cast<std::size_t>(x) / static_cast<std::size_t>(image.width);
        const std::size_t to = std::max(from + 1, samples.size() * static_cast<std::size_t>(x + 1) /
                                                      static_cast<std::size_t>(image.width));
        double lo = 0.0, hi = 0.0;
        for (std::size_t i = from; i < std::min(to, samples.size()); ++i) {
            lo = std::min(lo, samples[i] / 32767.0);
            hi = std::max(hi, samples[i] / 32767.0);
        }
        const int y0 = mid - static_cast<int>(std::lround(hi * (height / 2 - 1)));
        const int y1 = mid - static_cast<int>(std::lround(lo * (height / 2 - 1)));
        for (int y = y0; y <= y1; ++y) image.at(x, y) = Color(0.35f, 0.85f, 0.6f, 1.0f);
    }
}

// Ticks under the waveform every 0.1 s, longer every second.
void draw_time_ticks(Image& image, std::size_t sample_count, int bottom) {
    const double seconds = static_cast<double>(sample_count) / kRate;
    for (int tick = 0; tick <= static_cast<int>(seconds * 10.0); ++tick) {
        const int x = static_cast<int>(tick * 0.1 / seconds * image.width);
        const int length = tick % 10 == 0 ? 10 : 4;
        for (int y = bottom - length; y < bottom; ++y) image.at(x, y) = Color(0.7f, 0.7f, 0.75f, 1.0f);
    }
}

void draw_spectrogram(Image& image, const std::vector<std::int16_t>& samples, int top, int height) {
    constexpr double kLow = 30.0, kHigh = 20000.0, kRangeDb = 90.0;
    for (int x = 0; x < image.width; ++x) {
        const auto centre = static_cast<std::ptrdiff_t>(samples.size() * static_cast<std::size_t>(x) /
                                                        static_cast<std::size_t>(image.width));
        const std::vector<double> mag = spectrum(samples, centre - kFrame / 2);
        for (int y = 0; y < height; ++y) {
            const double f = kLow * std::pow(kHigh / kLow, 1.0 - (y + 0.5) / height);
            const double bin = f * kFrame / kRate;
            const auto k = std::min(static_cast<std::size_t>(bin), mag.size() - 2);
            const double m = mag[k] + (mag[k + 1] - mag[k]) * (bin - static_cast<double>(k));
            image.at(x, top + y) = heat(1.0 + to_db(m) / kRangeDb);
        }
    }
}
} // namespace

double seam_ratio(const std::vector<std::int16_t>& samples) {
    constexpr std::size_t kAround = 480; // 10 ms: a whole cycle of anything above 100 Hz
    const std::size_t n = samples.size();
    if (n < 2 * kAround + 2) return 0.0;
    const auto step = [&](std::size_t i) { // from sample i to the one after it, wrapping at the end
        return std::abs(static_cast<int>(samples[(i + 1) % n]) - static_cast<int>(samples[i]));
    };
    int largest = 0;
    for (std::size_t k = 1; k <= kAround; ++k) largest = std::max({largest, step(n - 1 - k), step(k - 1)});
    return largest > 0 ? static_cast<double>(step(n - 1)) / largest : (step(n - 1) > 0 ? 1e9 : 0.0);
}

SoundStats analyse_sound(const std::vector<std::int16_t>& samples) {
    SoundStats s;
    if (samples.empty()) return s;
    s.seconds = static_cast<double>(samples.size()) / kRate;
    double peak = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double v = samples[i] / 32767.0;
        peak = std::max(peak, std::abs(v));
        sum += v * v;
    }
    s.peak_db = to_db(peak);
    s.rms_db = to_db(std::sqrt(sum / static_cast<double>(samples.size())));
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (std::abs(samples[i] / 32767.0) >= 0.01 * peak) {
            s.onset_ms = 1000.0 * static_cast<double>(i) / kRate;
            break;
        }
    double end = 0.0;
    for (std::size_t i = samples.size() - std::min<std::size_t>(48, samples.size()); i < samples.size(); ++i)
        end = std::max(end, std::abs(samples[i] / 32767.0));
    s.end_db = to_db(end);
    s.seam_ratio = seam_ratio(samples);
    double weighted = 0.0, total = 0.0;
    for (std::ptrdiff_t start = 0; start < static_cast<std::ptrdiff_t>(samples.size()); start += kFrame / 2) {
        const std::vector<double> mag = spectrum(samples, start);
        for (std::size_t k = 1; k < mag.size(); ++k) {
            weighted += mag[k] * static_cast<double>(k) * kRate / kFrame;
            total += mag[k];
        }
    }
    s.centroid_hz = total > 0.0 ? weighted / total : 0.0;
    return s;
}

std::string sound_report(const Output& out) {
    std::string text =
        "sound                 seconds  peak dB   rms dB  centroid Hz  onset ms   end dB  seam\n";
    double bytes = 0.0;
    for (const auto& [name, samples] : out.sounds()) {
        const SoundStats s = analyse_sound(samples);
        char line[200];
        std::snprintf(line, sizeof line, "%-20s %8.3f %8.1f %8.1f %12.0f %9.2f %8.1f %5.2f\n", name.c_str(),
                      s.seconds, s.peak_db, s.rms_db, s.centroid_hz, s.onset_ms, s.end_db, s.seam_ratio);
        text += line;
        bytes += 44.0 + 2.0 * static_cast<double>(samples.size());
    }
    char total[80];
    std::snprintf(total, sizeof total, "%zu sounds, %.2f MB\n", out.sounds().size(), bytes / 1e6);
    return text + total;
}

Result<void> write_sound_views(const Output& out, const std::filesystem::path& folder) {
    constexpr int kWidth = 900, kLabel = 26, kWave = 120, kSpectrum = 300;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec)
        return Error("cannot create the sound view folder: " + ec.message(), Location{folder.string()},
                     "pass --sound-views a folder you can write to");
    for (const auto& [name, samples] : out.sounds()) {
        Image image(kWidth, kLabel + kWave + kSpectrum, Color(0.08f, 0.08f, 0.1f, 1.0f));
        draw_waveform(image, samples, kLabel, kWave);
        draw_time_ticks(image, samples.size(), kLabel + kWave);
        draw_spectrogram(image, samples, kLabel + kWave, kSpectrum);
        const SoundStats s = analyse_sound(samples);
        char label[200];
        std::snprintf(label, sizeof label, "%s   %.2f s   peak %.1f dB   rms %.1f dB   centroid %.0f Hz",
                      name.c_str(), s.seconds, s.peak_db, s.rms_db, s.centroid_hz);
        Field text(image.width, image.height);
        out.font().draw(text, label, Vec2f(6.0f, 18.0f), 14.0f);
        blend(image, text, Color(0.95f, 0.95f, 0.95f, 1.0f));
        KS_ASSETGEN_TRY(write_png(folder / (name + ".png"), image, PngChannels::Rgb));
    }
    return ok();
}

} // namespace ks::assetgen
