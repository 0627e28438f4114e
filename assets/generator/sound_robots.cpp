// The robot's voice and body: the alert chirp, a hit on its armour, its death, and the servo loop it plays
// while it moves.
#include "sounds.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
// One chirp of the alert: a square and a sine an octave apart gliding up, ring-modulated for a machine voice.
Signal chirp(double from, double to, double seconds) {
    Signal tone = oscillator(seconds + 0.15, Wave::Square, glide(from, to, seconds * 0.8));
    filter(tone, Pass::Low, 4200.0, 0.9);
    mix(tone, oscillator(seconds + 0.15, Wave::Sine, glide(from * 2.0, to * 2.0, seconds * 0.8)), 0.35);
    const Signal ring = oscillator(seconds + 0.15, Wave::Sine, constant(38.0), 0.25);
    for (std::size_t i = 0; i < tone.size(); ++i) tone[i] *= 0.75 + 0.25 * ring[i];
    shape(tone, [seconds](double t) { return attack_hold_release(t, 0.004, seconds, 0.02); });
    return tone;
}
} // namespace

Signal robot_alert() {
    Rng rng(0xA1E27ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::Band, 2600.0, 1.2, 0.004), 0.25);
    mix(out, chirp(700.0, 1050.0, 0.11), 0.8);
    mix(out, chirp(1050.0, 1580.0, 0.15), 0.9, 0.16);
    return reverb(out, Room{0.4, 0.4, 0.18, 1.0, 0.008, 0.6}, 0.3);
}

Signal robot_hit() {
    Rng rng(0x2081717ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::High, 1500.0, 0.7, 0.004), 0.9);
    // The armour plate ringing: inharmonic modes of a struck bar.
    mix(out,
        modes(0.6, {{523.0, 1.0, 0.18},
                    {1182.0, 0.7, 0.12},
                    {1917.0, 0.5, 0.09},
                    {2766.0, 0.4, 0.06},
                    {3790.0, 0.3, 0.05},
                    {5070.0, 0.2, 0.03}}),
        0.55);
    mix(out, thump(180.0, 80.0, 0.06, 0.03), 0.6);
    // Shorted wiring spitting.
    Signal zap = crackle(0.2, rng, knots({{0.0, 4000.0}, {0.12, 0.0}}));
    filter(zap, Pass::Band, 3500.0, 0.8);
    mix(out, zap, 0.6, 0.01);
    return reverb(out, Room{0.35, 0.5, 0.12, 1.0, 0.004, 0.7}, 0.25);
}

Signal robot_death() {
    Rng rng(0xDEAD2087ull);
    constexpr double kLength = 1.7;
    Signal out;
    // Shorting out: a harsh FM buzz first.
    Signal short_out = fm(0.3, constant(120.0), 3.0, constant(8.0));
    shape(short_out, [](double t) { return attack_decay(t, 0.001, 0.06); });
    mix(out, short_out, 0.6);
    mix(out, noise_burst(rng, Pass::High, 1200.0, 0.7, 0.006), 0.7);
    // Powering down: a saw and a square an octave below falling away, the filter closing, sputtering.
    Signal whine = oscillator(kLength, Wave::Saw, glide(900.0, 35.0, 1.3));
    mix(whine, oscillator(kLength, Wave::Square, glide(450.0, 17.5, 1.3)), 0.5);
    filter(whine, Pass::Low, glide(6000.0, 200.0, 1.3), 3.0);
    const Signal sputter = wander(kLength, rng, 22.0);
    for (std::size_t i = 0; i < whine.size(); ++i)
        whine[i] *= std::clamp((sputter[i] - 0.3) * 5.0, 0.12, 1.0);
    shape(whine, [](double t) { return attack_hold_release(t, 0.01, 0.9, 0.25); });
    fade_out(whine, 0.3);
    mix(out, whine, 0.55, 0.02);
    Signal sparks = crackle(kLength, rng, knots({{0.0, 2500.0}, {0.6, 800.0}, {1.4, 0.0}}));
    filter(sparks, Pass::Band, 4000.0, 0.7);
    mix(out, sparks, 0.4);
    // Slumping onto its chassis.
    Signal slump = modes(0.5, {{210.0, 1.0, 0.12}, {470.0, 0.6, 0.08}, {1130.0, 0.3, 0.05}});
    mix(slump, noise_burst(rng, Pass::Low, 600.0, 0.7, 0.03), 0.7);
    mix(out, slump, 0.7, 1.15);
    return reverb(out, Room{0.55, 0.5, 0.2, 1.0, 0.01, 0.9}, 0.5);
}

Signal robot_motor() {
    // Two seconds: every tone has a whole number of cycles, every modulator a whole number of periods.
    constexpr double kLoop = 2.0;
    Rng rng(0x2070202ull);
    // The servo: a nasal saw at 165 Hz, its pitch swinging four times a loop as the drive load changes.
    Signal servo = oscillator(kLoop, Wave::Saw, wobble(165.0, 0.04, 2.0));
    Signal gear = oscillator(kLoop, Wave::Sine, wobble(660.0, 0.04, 2.0));
    mix(gear, oscillator(kLoop, Wave::Sine, wobble(2140.0, 0.04, 2.0)), 0.4);
    shape(gear, wobble(1.0, 0.35, 8.0));
    // The gearbox: teeth ticking 24 times a second, with a grind of low noise.
    Signal teeth = silence(kLoop);
    for (int i = 0; i < 48; ++i) {
        const double size = 0.6 + 0.4 * rng.uniform_double();
        mix_wrapped(teeth, modes(0.03, {{2350.0, size, 0.004}, {3900.0, size * 0.5, 0.003}}), 1.0,
                    i * kLoop / 48.0);
    }
    Signal grind = white_noise(kLoop, rng);
    const Signal grind_level = wander(kLoop, rng, 12.0);
    for (std::size_t i = 0; i < grind.size(); ++i) grind[i] *= 0.5 + 0.5 * grind_level[i];

    process_looped(servo, [](Signal& s) { filter(s, Pass::Band, 900.0, 1.5); });
    process_looped(grind, [](Signal& s) { filter(s, Pass::Low, 380.0, 0.8); });
    process_looped(teeth, [](Signal& s) { filter(s, Pass::Low, 6000.0, 0.7); });
    Signal out = silence(kLoop);
    mix(out, servo, 0.7);
    mix(out, gear, 0.18);
    mix(out, teeth, 0.12);
    mix(out, grind, 0.45);
    saturate(out, 1.3);
    return out;
}

} // namespace ks::assetgen::sounds
