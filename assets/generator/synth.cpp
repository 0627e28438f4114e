#include "synth.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ks::assetgen::synth {
namespace {
constexpr double kDt = 1.0 / kSampleRate;

double raised_cosine(double x) {
    return 0.5 - 0.5 * std::cos(kPi * std::clamp(x, 0.0, 1.0));
}

// The PolyBLEP correction that rounds off a waveform's jump at phase 0 (`t` the phase, `dt` its step).
double poly_blep(double t, double dt) {
    if (t < dt) {
        t /= dt;
        return t + t - t * t - 1.0;
    }
    if (t > 1.0 - dt) {
        t = (t - 1.0) / dt;
        return t * t + t + t + 1.0;
    }
    return 0.0;
}

// One damped feedback comb of the reverb (Freeverb's lowpass-in-the-loop comb).
struct Comb {
    std::vector<double> buffer;
    std::size_t index = 0;
    double store = 0.0;
    double process(double in, double feedback, double damping) {
        const double out = buffer[index];
        store = out * (1.0 - damping) + store * damping;
        buffer[index] = in + store * feedback;
        index = (index + 1) % buffer.size();
        return out;
    }
};

struct Allpass {
    std::vector<double> buffer;
    std::size_t index = 0;
    double process(double in) {
        const double held = buffer[index];
        buffer[index] = in + held * 0.5;
        index = (index + 1) % buffer.size();
        return held - in;
    }
};

std::size_t scaled_length(int samples_at_44k, double spread) {
    return std::max<std::size_t>(
        1, static_cast<std::size_t>(std::lround(samples_at_44k * spread * kSampleRate / 44100.0)));
}
} // namespace

std::size_t frames(double seconds) {
    return static_cast<std::size_t>(std::lround(std::max(0.0, seconds) * kSampleRate));
}

double db_to_gain(double db) {
    return std::pow(10.0, db / 20.0);
}

double gain_to_db(double gain) {
    return gain > 0.0 ? 20.0 * std::log10(gain) : -200.0;
}

Signal silence(double seconds) {
    return Signal(frames(seconds), 0.0);
}

Curve constant(double value) {
    return [value](double) { return value; };
}

Curve glide(double from, double to, double seconds) {
    return [=](double t) { return from * std::pow(to / from, std::clamp(t / seconds, 0.0, 1.0)); };
}

Curve knots(std::vector<std::pair<double, double>> points) {
    return [points = std::move(points)](double t) {
        if (points.empty()) return 0.0;
        if (t <= points.front().first) return points.front().second;
        for (std::size_t i = 1; i < points.size(); ++i)
            if (t < points[i].first) {
                const auto& [t0, v0] = points[i - 1];
                const auto& [t1, v1] = points[i];
                return v0 + (v1 - v0) * (t - t0) / (t1 - t0);
            }
        return points.back().second;
    };
}

Curve wobble(double centre, double depth, double rate, double phase) {
    return [=](double t) { return centre * (1.0 + depth * std::sin(2.0 * kPi * rate * t + phase)); };
}

double attack_decay(double t, double attack, double decay) {
    if (t < 0.0) return 0.0;
    if (t < attack) return raised_cosine(t / attack);
    return std::exp(-(t - attack) / decay);
}

double attack_hold_release(double t, double attack, double release_at, double release) {
    if (t < 0.0) return 0.0;
    if (t < release_at) return attack > 0.0 ? raised_cosine(t / attack) : 1.0;
    return std::exp(-(t - release_at) / release) * (attack > 0.0 ? raised_cosine(release_at / attack) : 1.0);
}

Signal oscillator(double seconds, Wave wave, const Curve& frequency, double phase) {
    Signal s(frames(seconds));
    phase -= std::floor(phase);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double dt = std::clamp(frequency(static_cast<double>(i) * kDt) * kDt, 0.0, 0.5);
        double v = 0.0;
        switch (wave) {
        case Wave::Sine:
            v = std::sin(2.0 * kPi * phase);
            break;
        case Wave::Triangle:
            v = 1.0 - 4.0 * std::abs(phase - 0.5);
            break;
        case Wave::Saw:
            v = 2.0 * phase - 1.0 - poly_blep(phase, dt);
            break;
        case Wave::Square: {
            const double half = phase + 0.5 - std::floor(phase + 0.5);
            v = (phase < 0.5 ? 1.0 : -1.0) + poly_blep(phase, dt) - poly_blep(half, dt);
            break;
        }
        }
        s[i] = v;
        phase += dt;
        phase -= std::floor(phase);
    }
    return s;
}

Signal fm(double seconds, const Curve& carrier, double ratio, const Curve& index) {
    Signal s(frames(seconds));
    double carrier_phase = 0.0, modulator_phase = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double t = static_cast<double>(i) * kDt;
        const double f = carrier(t);
        s[i] = std::sin(2.0 * kPi * carrier_phase + index(t) * std::sin(2.0 * kPi * modulator_phase));
        carrier_phase += f * kDt;
        modulator_phase += f * ratio * kDt;
        carrier_phase -= std::floor(carrier_phase);
        modulator_phase -= std::floor(modulator_phase);
    }
    return s;
}

Signal white_noise(double seconds, Rng& rng) {
    Signal s(frames(seconds));
    for (double& v : s) v = rng.uniform_double() * 2.0 - 1.0;
    return s;
}

Signal crackle(double seconds, Rng& rng, const Curve& density) {
    Signal s(frames(seconds), 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double chance = density(static_cast<double>(i) * kDt) * kDt;
        const double roll = rng.uniform_double();
        const double size = rng.uniform_double();
        const bool negative = rng.chance(0.5f);
        if (roll < chance) s[i] = (0.2 + 0.8 * size) * (negative ? -1.0 : 1.0);
    }
    return s;
}

Signal wander(double seconds, Rng& rng, double per_second) {
    const std::size_t n = frames(seconds);
    const int count = std::max(2, static_cast<int>(std::lround(seconds * per_second)));
    std::vector<double> knot(static_cast<std::size_t>(count));
    for (double& k : knot) k = rng.uniform_double();
    Signal s(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(i) / static_cast<double>(n) * count;
        const auto k = static_cast<std::size_t>(x);
        const double a = knot[k % knot.size()], b = knot[(k + 1) % knot.size()];
        s[i] = a + (b - a) * raised_cosine(x - static_cast<double>(k));
    }
    return s;
}

Signal modes(double seconds, const std::vector<Mode>& body) {
    Signal s(frames(seconds), 0.0);
    for (const Mode& m : body) {
        // A rotating phasor with a shrinking radius: one complex multiply per sample instead of sin and exp.
        const double w = 2.0 * kPi * m.frequency * kDt;
        const double fall = std::exp(-kDt / m.decay);
        const double c = std::cos(w) * fall, d = std::sin(w) * fall;
        double re = m.amplitude, im = 0.0;
        for (double& v : s) {
            v += im;
            const double next_re = re * c - im * d;
            im = re * d + im * c;
            re = next_re;
        }
    }
    // Modes still ringing when the signal ends must not stop dead (a click): ease out the last fifth.
    fade_out(s, 0.2 * seconds);
    return s;
}

Signal noise_burst(Rng& rng, Pass pass, double cutoff, double q, double decay) {
    Signal s = white_noise(8.0 * decay, rng);
    filter(s, pass, cutoff, q);
    shape(s, [decay](double t) { return attack_decay(t, 0.0002, decay); });
    return s;
}

Signal thump(double from, double to, double sweep, double decay) {
    Signal s = oscillator(8.0 * decay, Wave::Sine, glide(from, to, sweep));
    shape(s, [decay](double t) { return attack_decay(t, 0.001, decay); });
    return s;
}

void filter(Signal& s, Pass pass, const Curve& cutoff, double q) {
    const double k = 1.0 / std::max(q, 0.05);
    double ic1 = 0.0, ic2 = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double fc = std::clamp(cutoff(static_cast<double>(i) * kDt), 5.0, 0.49 * kSampleRate);
        const double g = std::tan(kPi * fc * kDt);
        const double a1 = 1.0 / (1.0 + g * (g + k)), a2 = g * a1, a3 = g * a2;
        const double v0 = s[i];
        const double v3 = v0 - ic2;
        const double v1 = a1 * ic1 + a2 * v3;
        const double v2 = ic2 + a2 * ic1 + a3 * v3;
        ic1 = 2.0 * v1 - ic1;
        ic2 = 2.0 * v2 - ic2;
        switch (pass) {
        case Pass::Low:
            s[i] = v2;
            break;
        case Pass::High:
            s[i] = v0 - k * v1 - v2;
            break;
        case Pass::Band:
            s[i] = k * v1;
            break;
        }
    }
}

void filter(Signal& s, Pass pass, double cutoff, double q) {
    filter(s, pass, constant(cutoff), q);
}

void shape(Signal& s, const Curve& gain) {
    for (std::size_t i = 0; i < s.size(); ++i) s[i] *= gain(static_cast<double>(i) * kDt);
}

void scale(Signal& s, double gain) {
    for (double& v : s) v *= gain;
}

void saturate(Signal& s, double drive) {
    const double norm = 1.0 / std::tanh(drive);
    for (double& v : s) v = std::tanh(drive * v) * norm;
}

void dc_block(Signal& s) {
    filter(s, Pass::High, 10.0, 0.5);
}

void mix(Signal& into, const Signal& source, double gain, double at) {
    const std::size_t start = frames(at);
    if (into.size() < start + source.size()) into.resize(start + source.size(), 0.0);
    for (std::size_t i = 0; i < source.size(); ++i) into[start + i] += source[i] * gain;
}

void fade_in(Signal& s, double seconds) {
    const std::size_t n = std::min(frames(seconds), s.size());
    for (std::size_t i = 0; i < n; ++i)
        s[i] *= raised_cosine(static_cast<double>(i) / static_cast<double>(n));
}

void fade_out(Signal& s, double seconds) {
    const std::size_t n = std::min(frames(seconds), s.size());
    for (std::size_t i = 0; i < n; ++i)
        s[s.size() - 1 - i] *= raised_cosine(static_cast<double>(i) / static_cast<double>(n));
}

double peak(const Signal& s) {
    double p = 0.0;
    for (double v : s) p = std::max(p, std::abs(v));
    return p;
}

double rms(const Signal& s) {
    if (s.empty()) return 0.0;
    double sum = 0.0;
    for (double v : s) sum += v * v;
    return std::sqrt(sum / static_cast<double>(s.size()));
}

Signal reverb(const Signal& dry, const Room& room, double tail) {
    // Freeverb's tunings (samples at 44.1 kHz), spread to our rate and the room's size.
    static constexpr std::array<int, 8> kCombs = {1116, 1188, 1277, 1356, 1422, 1491, 1557, 1617};
    static constexpr std::array<int, 4> kAllpasses = {556, 441, 341, 225};
    std::array<Comb, 8> combs;
    for (std::size_t c = 0; c < combs.size(); ++c)
        combs[c].buffer.assign(scaled_length(kCombs[c], room.spread), 0.0);
    std::array<Allpass, 4> allpasses;
    for (std::size_t a = 0; a < allpasses.size(); ++a)
        allpasses[a].buffer.assign(scaled_length(kAllpasses[a], room.spread), 0.0);
    const double feedback = 0.7 + 0.28 * std::clamp(room.size, 0.0, 1.0);
    const double damping = 0.4 * std::clamp(room.damping, 0.0, 1.0);
    const std::size_t predelay = frames(room.predelay);

    Signal out(dry.size() + frames(tail), 0.0);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double in = i >= predelay && i - predelay < dry.size() ? dry[i - predelay] * 0.015 : 0.0;
        double wet = 0.0;
        for (Comb& c : combs) wet += c.process(in, feedback, damping);
        for (Allpass& a : allpasses) wet = a.process(wet);
        out[i] = wet * room.wet * 3.0 + (i < dry.size() ? dry[i] * room.dry : 0.0);
    }
    return out;
}

void mix_wrapped(Signal& loop, const Signal& source, double gain, double at) {
    if (loop.empty()) return;
    std::size_t index = frames(at) % loop.size();
    for (double v : source) {
        loop[index] += v * gain;
        index = (index + 1) % loop.size();
    }
}

void process_looped(Signal& loop, const std::function<void(Signal&)>& process) {
    const std::size_t n = loop.size();
    Signal run;
    run.reserve(3 * n);
    for (int copy = 0; copy < 3; ++copy) run.insert(run.end(), loop.begin(), loop.end());
    process(run);
    // The third copy has heard the two before it, so it holds the tails of the laps that preceded it; what
    // ran past its end would only go to a fourth lap.
    run.resize(std::max(run.size(), 3 * n), 0.0);
    loop.assign(run.begin() + static_cast<std::ptrdiff_t>(2 * n),
                run.begin() + static_cast<std::ptrdiff_t>(3 * n));
}

Signal crossfade_loop(const Signal& rendered, double crossfade) {
    const std::size_t x = frames(crossfade);
    if (rendered.size() <= 2 * x) return rendered;
    const std::size_t n = rendered.size() - x;
    Signal out(rendered.begin(), rendered.begin() + static_cast<std::ptrdiff_t>(n));
    for (std::size_t i = 0; i < x; ++i) {
        const double a = 0.5 * kPi * (static_cast<double>(i) + 0.5) / static_cast<double>(x);
        out[i] = rendered[i] * std::sin(a) + rendered[n + i] * std::cos(a);
    }
    return out;
}

double loop_frequency(double frequency, double loop_seconds) {
    return std::max(1.0, std::round(frequency * loop_seconds)) / loop_seconds;
}

std::vector<std::int16_t> to_pcm16(const Signal& s) {
    std::vector<std::int16_t> out(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
        out[i] = static_cast<std::int16_t>(std::lround(std::clamp(s[i], -1.0, 1.0) * 32767.0));
    return out;
}

} // namespace ks::assetgen::synth
