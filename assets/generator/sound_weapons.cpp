// Weapon sounds: the player's energy rifle, the robot's blaster, the empty click and a shot hitting a wall.
#include "sounds.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

Signal rifle_shot() {
    Rng rng(0x51F1E5407ull);
    Signal out;
    // The crack: a bright snap of noise, gone in a few milliseconds.
    mix(out, noise_burst(rng, Pass::High, 1800.0, 0.7, 0.005), 0.9);
    // The zap: an FM voice diving from 2.4 kHz, its sidebands thinning as it falls...
    Signal zap = fm(0.3, glide(2400.0, 210.0, 0.12), 0.5, glide(6.0, 0.8, 0.15));
    shape(zap, [](double t) { return attack_decay(t, 0.0005, 0.045); });
    mix(out, zap, 0.55);
    // ...doubled by a saw whose filter closes behind it.
    Signal edge = oscillator(0.3, Wave::Saw, glide(1250.0, 90.0, 0.14));
    filter(edge, Pass::Low, glide(9000.0, 700.0, 0.15), 1.4);
    shape(edge, [](double t) { return attack_decay(t, 0.0005, 0.06); });
    mix(out, edge, 0.45);
    // The punch: a short low kick under it.
    mix(out, thump(170.0, 48.0, 0.09, 0.045), 0.85);
    // The sizzle of the discharge.
    Signal sizzle = white_noise(0.4, rng);
    filter(sizzle, Pass::Band, glide(5200.0, 1800.0, 0.25), 0.9);
    shape(sizzle, [](double t) { return attack_decay(t, 0.002, 0.08); });
    mix(out, sizzle, 0.22);
    saturate(out, 1.6);
    return reverb(out, Room{0.45, 0.6, 0.16, 1.0, 0.004, 0.8}, 0.35);
}

Signal robot_shot() {
    Rng rng(0x20B07540ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::Band, 1100.0, 0.8, 0.009), 0.8);
    // The buzz: a square wave ring-modulated at 57 Hz, falling from 440 Hz, with a resonant filter sweep.
    Signal buzz = oscillator(0.8, Wave::Square, glide(440.0, 92.0, 0.26));
    const Signal ring = oscillator(0.8, Wave::Sine, constant(57.0));
    for (std::size_t i = 0; i < buzz.size(); ++i) buzz[i] *= 0.55 + 0.45 * ring[i];
    Signal under = oscillator(0.8, Wave::Saw, glide(221.0, 47.0, 0.26));
    mix(buzz, under, 0.6);
    filter(buzz, Pass::Low, glide(5200.0, 500.0, 0.3), 2.6);
    shape(buzz, [](double t) { return attack_decay(t, 0.0015, 0.11); });
    mix(out, buzz, 0.75);
    mix(out, thump(125.0, 40.0, 0.12, 0.07), 0.8);
    saturate(out, 2.6);
    return reverb(out, Room{0.5, 0.5, 0.2, 1.0, 0.006, 0.9}, 0.4);
}

Signal dry_fire() {
    Rng rng(0xD2F12Eull);
    Signal out;
    // The trigger breaking: a bright, tiny metal click.
    mix(out, noise_burst(rng, Pass::High, 3000.0, 0.7, 0.0012), 0.5);
    mix(out,
        modes(0.05, {{3150.0, 1.0, 0.006}, {4870.0, 0.6, 0.004}, {7420.0, 0.4, 0.003}, {1860.0, 0.3, 0.01}}),
        0.7);
    // The hammer falling on nothing, a little lower and softer.
    Signal fall = modes(0.06, {{2240.0, 0.7, 0.008}, {3580.0, 0.5, 0.006}, {5210.0, 0.3, 0.004}});
    mix(fall, thump(420.0, 300.0, 0.01, 0.012), 0.35);
    mix(out, fall, 0.55, 0.038);
    return out;
}

Signal impact() {
    Rng rng(0x1A9AC7ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::High, 2500.0, 0.7, 0.003), 1.0);
    // The wall: a hard body and a puff of dust.
    mix(out, modes(0.1, {{1650.0, 0.5, 0.02}, {2930.0, 0.4, 0.015}, {4410.0, 0.3, 0.01}}), 0.6);
    mix(out, thump(300.0, 120.0, 0.05, 0.015), 0.5);
    mix(out, noise_burst(rng, Pass::Low, 800.0, 0.7, 0.012), 0.45);
    // Sparks spraying off, and the faint whine of the deflected bolt.
    Signal sparks = crackle(0.2, rng, knots({{0.0, 3000.0}, {0.15, 0.0}}));
    filter(sparks, Pass::High, 3000.0, 0.7);
    mix(out, sparks, 0.45, 0.004);
    Signal whine = oscillator(0.3, Wave::Sine, [](double t) {
        return 4200.0 * std::pow(2400.0 / 4200.0, std::min(t / 0.25, 1.0)) *
               (1.0 + 0.01 * std::sin(60.0 * t));
    });
    shape(whine, [](double t) { return attack_decay(t, 0.004, 0.07); });
    mix(out, whine, 0.14, 0.006);
    return reverb(out, Room{0.3, 0.5, 0.12, 1.0, 0.003, 0.6}, 0.2);
}

} // namespace ks::assetgen::sounds
