#pragma once
// The DSP toolkit of the sound recipes (sound_*.cpp): oscillators, seeded noise, envelopes, filters, struck
// resonators, a small reverb, loudness normalisation and the two ways of making a seamless loop. Signals are
// mono doubles at 48 kHz, nominally within -1..1; nothing rounds until to_pcm16, and every random source is a
// seeded ks::Rng, so the same source always gives the same samples.
#include "core/random.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace ks::assetgen::synth {

inline constexpr int kSampleRate = 48000;
inline constexpr double kPi = 3.14159265358979323846;

using Signal = std::vector<double>;
// A parameter over time in seconds from the start of the signal: a pitch, a cutoff, a gain.
using Curve = std::function<double(double t)>;

std::size_t frames(double seconds);
double db_to_gain(double db);
double gain_to_db(double gain);
Signal silence(double seconds);

// A filter's response: low pass, high pass or band pass (see filter).
enum class Pass { Low, High, Band };

// --- curves
Curve constant(double value);
// An exponential glide (pitches and cutoffs move in ratios) from `from` to `to` over `seconds`, then holds.
Curve glide(double from, double to, double seconds);
// Piecewise linear through (time, value) knots in time order; holds the end values outside them.
Curve knots(std::vector<std::pair<double, double>> points);
// `centre * (1 + depth * sin(2 pi rate t + phase))`: vibrato, tremolo, a swinging cutoff.
Curve wobble(double centre, double depth, double rate, double phase = 0.0);

// --- envelopes (gain 0..1 over time)
// A raised-cosine rise over `attack`, then an exponential fall with time constant `decay`.
double attack_decay(double t, double attack, double decay);
// A raised-cosine rise over `attack`, full level until `release_at`, then an exponential fall (constant
// `release`).
double attack_hold_release(double t, double attack, double release_at, double release);

// --- sources
enum class Wave { Sine, Triangle, Saw, Square };
// Phase-accumulating oscillator; the saw and square are band-limited (PolyBLEP) so sweeps do not alias.
// `phase` is the starting phase in cycles.
Signal oscillator(double seconds, Wave wave, const Curve& frequency, double phase = 0.0);
// Two-operator FM: a sine carrier whose phase is pushed by a sine modulator at `ratio` times its
// frequency, `index` radians deep.
Signal fm(double seconds, const Curve& carrier, double ratio, const Curve& index);
// Uniform white noise in -1..1.
Signal white_noise(double seconds, Rng& rng);
// Sparse single-sample clicks of random sign and size, `density` of them per second on average.
Signal crackle(double seconds, Rng& rng, const Curve& density);
// A smooth random wander in 0..1 through `per_second` random knots a second (cosine-interpolated). The last
// knot leads back into the first, so it is periodic over `seconds` (loops can use it unchanged).
Signal wander(double seconds, Rng& rng, double per_second);
// One resonance of a struck body: a sine at `frequency` falling with time constant `decay` seconds.
struct Mode {
    double frequency = 440.0;
    double amplitude = 1.0;
    double decay = 0.1;
};
// Modal synthesis: the sum of the modes, all struck at t = 0 (each starts at zero phase, so no click); the
// last fifth fades out, so a mode still ringing at the end does not click either.
Signal modes(double seconds, const std::vector<Mode>& body);

// --- building blocks
// Filtered white noise with a near-instant attack and an exponential fall (time constant `decay`), lasting
// eight decays: snaps, ticks, puffs, dust.
Signal noise_burst(Rng& rng, Pass pass, double cutoff, double q, double decay);
// A sine falling in pitch from `from` to `to` Hz over `sweep` seconds while it fades with time constant
// `decay`: kicks, thuds, booms.
Signal thump(double from, double to, double sweep, double decay);

// --- processing
// Topology-preserving state-variable filter (stays stable while the cutoff moves every sample). `q` 0.5
// (soft) to 30 (ringing); the band pass is scaled to unit gain at its centre.
void filter(Signal& s, Pass pass, const Curve& cutoff, double q = 0.7071);
void filter(Signal& s, Pass pass, double cutoff, double q = 0.7071);
// Multiplies every sample by `gain(t)`.
void shape(Signal& s, const Curve& gain);
void scale(Signal& s, double gain);
// Soft clipping: tanh(drive x) / tanh(drive), which keeps full scale at full scale.
void saturate(Signal& s, double drive);
// Removes any DC offset (a 10 Hz one-pole high pass).
void dc_block(Signal& s);
// Adds `source * gain` into `into` from `at` seconds on, lengthening `into` where needed.
void mix(Signal& into, const Signal& source, double gain = 1.0, double at = 0.0);
// Raised-cosine fades over the first / last `seconds` of the signal.
void fade_in(Signal& s, double seconds);
void fade_out(Signal& s, double seconds);
double peak(const Signal& s);
double rms(const Signal& s);

// A small room: Freeverb's eight damped feedback combs and four allpasses, mono.
struct Room {
    double size = 0.5;     // 0..1: the comb feedback, so the length of the tail
    double damping = 0.5;  // 0..1: how fast the highs die in the tail
    double wet = 0.25;     // level of the reverberated signal
    double dry = 1.0;      // level of the original
    double predelay = 0.0; // seconds before the tail starts
    double spread = 1.0;   // scales the comb and allpass lengths: below 1 a smaller, brighter room
};
// The signal through the room, `tail` seconds longer than `dry` so the reverberation can ring out.
Signal reverb(const Signal& dry, const Room& room, double tail);

// --- loops
// Two ways to make a loop seamless (the last sample flows into the first):
// * build it periodic: tones with a whole number of cycles over the loop, events mixed with wrap-around,
//   and filters and reverb run as if the loop had always been playing (process_looped);
// * render it longer and crossfade the tail into the head (crossfade_loop), for material that just evolves.
//
// Adds `source * gain` into `loop` at `at` seconds; what runs past the end continues at the start.
void mix_wrapped(Signal& loop, const Signal& source, double gain, double at);
// Runs a time-invariant `process` (filters, reverb; it may lengthen the signal) over three back-to-back
// copies of the loop and keeps the last copy, so tails ring from the end of the loop into its start. Curves
// inside `process` see t over three loop lengths: they must repeat with the loop.
void process_looped(Signal& loop, const std::function<void(Signal&)>& process);
// `rendered` holds a loop's length plus `crossfade` seconds; the result is the loop's length, its first
// `crossfade` seconds blended (equal power) with the rendered tail that followed the loop's end.
Signal crossfade_loop(const Signal& rendered, double crossfade);
// The nearest frequency with a whole number of cycles over `loop_seconds`, so a steady tone loops exactly.
double loop_frequency(double frequency, double loop_seconds);

// --- finishing
// Rounds to 16-bit PCM (full scale 32767), clamping anything beyond.
std::vector<std::int16_t> to_pcm16(const Signal& s);

} // namespace ks::assetgen::synth
