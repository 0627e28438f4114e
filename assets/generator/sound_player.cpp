// The player's body: getting hurt, the shield taking a hit, dying, jumping, landing and footsteps.
#include "sounds.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
// A short grunt: a saw "voice" with a little breath and jitter through three vowel formants ("uh").
Signal grunt(Rng& rng, double seconds) {
    const Signal jitter = wander(seconds, rng, 40.0);
    const Curve contour = knots({{0.0, 150.0}, {0.05, 140.0}, {seconds, 100.0}});
    Signal voice = oscillator(seconds, Wave::Saw, [&](double t) {
        const auto i = std::min(jitter.size() - 1, frames(t));
        return contour(t) * (1.0 + 0.03 * (jitter[i] - 0.5));
    });
    mix(voice, white_noise(seconds, rng), 0.15);
    Signal out = silence(seconds);
    const double formants[3][3] = {{600.0, 5.0, 1.0}, {1040.0, 7.0, 0.5}, {2250.0, 9.0, 0.25}};
    for (const auto& [centre, q, gain] : formants) {
        Signal band = voice;
        filter(band, Pass::Band, centre, q);
        mix(out, band, gain);
    }
    filter(out, Pass::Low, 3500.0, 0.7);
    shape(out, [](double t) { return attack_hold_release(t, 0.02, 0.12, 0.07); });
    fade_out(out, 0.1);
    return out;
}

// One foot: the heel, then the toe a moment later, softer.
Signal step(Rng& rng, double heel_band, double heel_decay, double body_pitch, double body_decay) {
    Signal out;
    mix(out, noise_burst(rng, Pass::Band, heel_band, 0.9, heel_decay), 1.0);
    mix(out, thump(body_pitch, body_pitch * 0.67, 0.02, body_decay), 0.5);
    mix(out, noise_burst(rng, Pass::Band, heel_band * 1.35, 0.9, heel_decay * 0.6), 0.45, 0.035);
    return out;
}
} // namespace

Signal player_hurt() {
    Rng rng(0x4E27ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::Low, 2000.0, 0.7, 0.005), 0.5);
    mix(out, thump(110.0, 55.0, 0.08, 0.06), 1.0);
    mix(out, noise_burst(rng, Pass::Low, 500.0, 0.7, 0.025), 0.6);
    mix(out, grunt(rng, 0.45), 0.9, 0.015);
    return reverb(out, Room{0.3, 0.6, 0.1, 1.0, 0.004, 0.7}, 0.2);
}

Signal shield_hit() {
    Rng rng(0x5E1D417ull);
    Signal out;
    mix(out, noise_burst(rng, Pass::High, 1500.0, 0.7, 0.003), 0.8);
    Signal sparks = crackle(0.4, rng, knots({{0.0, 9000.0}, {0.08, 3000.0}, {0.35, 0.0}}));
    filter(sparks, Pass::Band, 3500.0, 0.6);
    mix(out, sparks, 1.0);
    // The field buzzing: heavily modulated FM at 110 Hz.
    Signal buzz = fm(0.4, constant(110.0), 1.0, constant(6.0));
    filter(buzz, Pass::High, 300.0, 0.7);
    shape(buzz, [](double t) { return attack_decay(t, 0.001, 0.06); });
    mix(out, buzz, 0.5);
    // And ringing down, trembling.
    Signal ring = oscillator(0.8, Wave::Sine, glide(2200.0, 1100.0, 0.3));
    mix(ring, oscillator(0.8, Wave::Sine, glide(2770.0, 1385.0, 0.3)), 0.7);
    shape(ring, wobble(1.0, 0.5, 40.0));
    shape(ring, [](double t) { return attack_decay(t, 0.001, 0.12); });
    mix(out, ring, 0.3);
    saturate(out, 2.5); // thickens the sparse crackle
    return reverb(out, Room{0.4, 0.4, 0.15, 1.0, 0.005, 0.8}, 0.3);
}

Signal player_death() {
    Rng rng(0xDEADull);
    constexpr double kLength = 2.0;
    Signal out;
    mix(out, thump(90.0, 40.0, 0.3, 0.2), 0.7);
    mix(out, noise_burst(rng, Pass::Low, 1200.0, 0.7, 0.01), 0.4);
    // Two soft voices a minor third apart (triangles, each over a sine an octave down) falling three octaves
    // together with a slowing vibrato: life fading, not a machine failing.
    const auto falling = [](double ratio) {
        return [ratio](double t) {
            const double base = 620.0 * ratio * std::pow(70.0 / 620.0, std::min(t / 1.6, 1.0));
            return base * (1.0 + 0.02 * std::sin(2.0 * kPi * 5.5 * t * (1.0 - 0.3 * t)));
        };
    };
    Signal voice = oscillator(kLength, Wave::Triangle, falling(1.0));
    mix(voice, oscillator(kLength, Wave::Sine, falling(0.5)), 0.7);
    mix(voice, oscillator(kLength, Wave::Triangle, falling(1.19)), 0.6);
    mix(voice, oscillator(kLength, Wave::Sine, falling(0.595)), 0.4);
    filter(voice, Pass::Low, glide(3000.0, 250.0, 1.8), 0.9);
    shape(voice, [](double t) { return attack_hold_release(t, 0.005, 1.0, 0.35); });
    fade_out(voice, 0.4);
    mix(out, voice, 0.5);
    Signal swell = white_noise(kLength, rng);
    filter(swell, Pass::Low, glide(2000.0, 200.0, 1.5), 0.7);
    shape(swell, [](double t) { return attack_hold_release(t, 0.3, 0.6, 0.4); });
    fade_out(swell, 0.4);
    mix(out, swell, 0.3);
    return reverb(out, Room{0.7, 0.5, 0.28, 1.0, 0.015, 1.0}, 0.8);
}

Signal jump() {
    Rng rng(0x7A4Bull);
    Signal out;
    mix(out, thump(150.0, 95.0, 0.05, 0.035), 0.8);
    mix(out, noise_burst(rng, Pass::Low, 700.0, 0.7, 0.025), 0.6);
    // Clothes and gear moving with the push.
    Signal rustle = white_noise(0.25, rng);
    filter(rustle, Pass::Band, 2500.0, 0.8);
    shape(rustle, [](double t) { return attack_decay(t, 0.01, 0.05); });
    mix(out, rustle, 0.15, 0.01);
    return out;
}

Signal land() {
    Rng rng(0x1A4Dull);
    Signal out;
    mix(out, noise_burst(rng, Pass::Low, 2500.0, 0.7, 0.004), 0.4);
    mix(out, thump(100.0, 45.0, 0.1, 0.07), 1.0);
    mix(out, noise_burst(rng, Pass::Low, 400.0, 0.7, 0.045), 0.8);
    // The kit on the player's back rattling.
    for (double at : {0.03, 0.07})
        mix(out, modes(0.1, {{2300.0, 1.0, 0.02}, {3400.0, 0.7, 0.015}}), 0.12, at);
    saturate(out, 1.4);
    return out;
}

Signal footstep_floor() {
    Rng rng(0xF007ull);
    Signal out = step(rng, 2200.0, 0.005, 210.0, 0.018);
    // A little scuff of the sole.
    mix(out, noise_burst(rng, Pass::High, 3000.0, 0.7, 0.02), 0.08, 0.03);
    filter(out, Pass::Low, 7000.0, 0.7);
    return reverb(out, Room{0.1, 0.7, 0.05, 1.0, 0.002, 0.3}, 0.05);
}

Signal footstep_stairs() {
    Rng rng(0x57A125ull);
    // A metal tread: hollow box resonances under the heel and the toe.
    const std::vector<Mode> tread = {{290.0, 0.6, 0.09},
                                     {687.0, 0.5, 0.07},
                                     {1184.0, 0.4, 0.05},
                                     {1770.0, 0.3, 0.04},
                                     {2652.0, 0.2, 0.03}};
    Signal out = step(rng, 1800.0, 0.003, 145.0, 0.06);
    mix(out, modes(0.4, tread), 0.9);
    mix(out, modes(0.4, tread), 0.3, 0.04);
    return reverb(out, Room{0.3, 0.5, 0.1, 1.0, 0.003, 0.6}, 0.15);
}

} // namespace ks::assetgen::sounds
