// Sounds of the level's things: the sliding door, the light switch and the three pickups (each its own
// character: health warm, ammo metallic, shield shimmering).
#include "sounds.h"

#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
// The leaves travelling: a motor (a filtered saw) and the rumble of the rollers, under `level(t)`.
Signal door_slide(Rng& rng, double seconds, double motor_from, double motor_to, const Curve& level) {
    Signal motor = oscillator(seconds, Wave::Saw, glide(motor_from, motor_to, seconds));
    filter(motor, Pass::Band, 700.0, 2.0);
    mix(motor, oscillator(seconds, Wave::Sine, glide(motor_from * 4.0, motor_to * 4.0, seconds)), 0.15);
    Signal rollers = white_noise(seconds, rng);
    filter(rollers, Pass::Low, 350.0, 0.8);
    const Signal bumps = wander(seconds, rng, 30.0);
    for (std::size_t i = 0; i < rollers.size(); ++i) rollers[i] *= 0.4 + bumps[i];
    Signal out = silence(seconds);
    mix(out, motor, 0.35);
    mix(out, rollers, 0.9);
    shape(out, level);
    return out;
}

// A pneumatic valve venting: hiss through a high band.
Signal hiss(Rng& rng, double decay) {
    Signal s = white_noise(decay * 8.0, rng);
    filter(s, Pass::Band, 4500.0, 0.7);
    filter(s, Pass::High, 2000.0, 0.7);
    shape(s, [decay](double t) { return attack_decay(t, 0.008, decay); });
    return s;
}

// A door leaf or latch hitting its stop: low modes of the heavy leaf, a thud and a burst of noise.
Signal clunk(Rng& rng, double weight) {
    Signal s = modes(0.5, {{160.0 / weight, 1.0, 0.08 * weight},
                           {390.0 / weight, 0.5, 0.05 * weight},
                           {910.0, 0.25, 0.03},
                           {1650.0, 0.15, 0.02}});
    mix(s, thump(110.0 / weight, 60.0 / weight, 0.05, 0.04 * weight), 0.8);
    mix(s, noise_burst(rng, Pass::Low, 1800.0, 0.7, 0.006), 0.5);
    return s;
}

// A bell-like note: a sine with a little of its second and third harmonics, falling with `decay`.
Signal chime_note(double pitch, double decay) {
    Signal s = oscillator(decay * 6.0, Wave::Sine, constant(pitch));
    mix(s, oscillator(decay * 6.0, Wave::Sine, constant(pitch * 2.0)), 0.3);
    mix(s, oscillator(decay * 6.0, Wave::Sine, constant(pitch * 3.0)), 0.1);
    // A quieter copy a few cents sharp for a gentle chorus.
    mix(s, oscillator(decay * 6.0, Wave::Sine, constant(pitch * 1.002)), 0.25);
    shape(s, [decay](double t) { return attack_decay(t, 0.003, decay); });
    return s;
}
} // namespace

Signal door_open() {
    Rng rng(0xD0027ull);
    Signal out;
    mix(out, modes(0.1, {{1400.0, 0.5, 0.02}, {2650.0, 0.3, 0.015}}), 0.6); // the latch
    mix(out, hiss(rng, 0.18), 0.6);
    mix(out, door_slide(rng, 1.0, 110.0, 150.0, knots({{0.0, 0.0}, {0.1, 1.0}, {0.75, 1.0}, {0.95, 0.0}})),
        0.8, 0.08);
    mix(out, clunk(rng, 1.0), 0.55, 0.98);
    return reverb(out, Room{0.4, 0.6, 0.14, 1.0, 0.006, 0.9}, 0.35);
}

Signal door_close() {
    Rng rng(0xD0C105Eull);
    Signal out;
    mix(out, noise_burst(rng, Pass::Band, 3000.0, 0.8, 0.01), 0.3); // the valve switching
    mix(out, door_slide(rng, 0.85, 150.0, 110.0, knots({{0.0, 0.0}, {0.06, 1.0}, {0.7, 1.0}, {0.82, 0.3}})),
        1.5);
    mix(out, clunk(rng, 1.35), 0.8, 0.8);
    mix(out, hiss(rng, 0.09), 0.35, 0.88);
    return reverb(out, Room{0.4, 0.6, 0.14, 1.0, 0.006, 0.9}, 0.35);
}

Signal light_switch() {
    Rng rng(0x5A17C4ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::High, 2000.0, 0.7, 0.001), 0.6);
    mix(out,
        modes(0.08, {{2900.0, 1.0, 0.012}, {4700.0, 0.6, 0.008}, {6900.0, 0.4, 0.005}, {1200.0, 0.3, 0.02}}),
        0.7);
    mix(out, thump(180.0, 150.0, 0.01, 0.015), 0.4);
    // The contact bouncing once.
    mix(out, modes(0.04, {{3300.0, 1.0, 0.006}, {5200.0, 0.5, 0.004}}), 0.2, 0.018);
    return out;
}

Signal pickup_health() {
    Rng rng(0x4EA17ull);
    // C major rising, C5 E5 G5 C6: soft sines, filtered warm.
    Signal out;
    mix(out, noise_burst(rng, Pass::Band, 1500.0, 1.0, 0.004), 0.15);
    const double notes[] = {523.25, 659.26, 783.99, 1046.5};
    for (int i = 0; i < 4; ++i) mix(out, chime_note(notes[i], 0.12 + 0.03 * i), 0.5, 0.06 * i);
    filter(out, Pass::Low, 3200.0, 0.7);
    return reverb(out, Room{0.5, 0.6, 0.22, 1.0, 0.01, 1.0}, 0.4);
}

Signal pickup_ammo() {
    Rng rng(0xA770ull);
    Signal out;
    // The magazine seating: two metallic clacks.
    const std::vector<Mode> clack = {
        {1850.0, 1.0, 0.03}, {3120.0, 0.7, 0.02}, {4630.0, 0.5, 0.015}, {760.0, 0.4, 0.04}};
    mix(out, noise_burst(rng, Pass::High, 2500.0, 0.7, 0.002), 0.5);
    mix(out, modes(0.2, clack), 0.6);
    mix(out, noise_burst(rng, Pass::High, 2500.0, 0.7, 0.002), 0.35, 0.07);
    mix(out, modes(0.2, clack), 0.45, 0.07);
    // The confirming ping: an inharmonic FM bell.
    Signal ping = fm(0.5, constant(1760.0), 3.5, glide(4.0, 0.5, 0.2));
    shape(ping, [](double t) { return attack_decay(t, 0.002, 0.09); });
    mix(out, ping, 0.4, 0.11);
    return reverb(out, Room{0.35, 0.5, 0.12, 1.0, 0.005, 0.7}, 0.3);
}

Signal pickup_shield() {
    Rng rng(0x5E1Dull);
    Signal out = silence(1.2);
    // Four partials sweeping up two octaves together, trembling fast: the shimmer.
    const double partials[] = {1.0, 1.5, 2.0, 3.01};
    for (double ratio : partials) {
        Signal p = oscillator(1.2, Wave::Sine, glide(330.0 * ratio, 1320.0 * ratio, 0.5));
        mix(out, p, 0.35 / ratio);
    }
    shape(out, wobble(1.0, 0.45, 22.0));
    // FM sparkle riding on top, and air rushing up with it.
    Signal sparkle = fm(1.2, glide(1320.0, 2640.0, 0.5), 1.41, constant(2.0));
    mix(out, sparkle, 0.12);
    Signal air = white_noise(1.2, rng);
    filter(air, Pass::Band, glide(800.0, 6000.0, 0.5), 1.0);
    mix(out, air, 0.25);
    shape(out, [](double t) { return attack_hold_release(t, 0.02, 0.45, 0.12); });
    mix(out, modes(0.2, {{2640.0, 1.0, 0.03}, {3960.0, 0.5, 0.02}}), 0.2); // a glassy tink to start it
    return reverb(out, Room{0.6, 0.4, 0.3, 1.0, 0.012, 1.0}, 0.6);
}

} // namespace ks::assetgen::sounds
