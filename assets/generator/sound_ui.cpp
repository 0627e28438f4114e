// Menu sounds (subtle, they repeat a lot) and the win sting.
#include "sounds.h"

#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
// A sine blip: `pitch` falling with `decay`.
Signal blip(double pitch, double decay) {
    Signal s = oscillator(decay * 7.0, Wave::Sine, constant(pitch));
    shape(s, [decay](double t) { return attack_decay(t, 0.0005, decay); });
    return s;
}

// A brass-like FM note (carrier = modulator, the index opening with the attack), held until `release_at`.
Signal brass(double pitch, double release_at, double release, double vibrato_from) {
    const double length = release_at + release * 6.0;
    Signal s = fm(
        length,
        [=](double t) {
            const double depth = t > vibrato_from ? 0.006 * std::min(1.0, (t - vibrato_from) / 0.3) : 0.0;
            return pitch * (1.0 + depth * std::sin(2.0 * kPi * 5.2 * t));
        },
        1.0, [](double t) { return 1.5 + 2.0 * std::exp(-t / 0.08); });
    shape(s, [=](double t) { return attack_hold_release(t, 0.012, release_at, release); });
    return s;
}
} // namespace

Signal ui_hover() {
    Signal out = blip(2600.0, 0.008);
    mix(out, blip(5200.0, 0.004), 0.2);
    return out;
}

Signal ui_click() {
    Rng rng(0xC11Cull);
    Signal out;
    mix(out, noise_burst(rng, Pass::High, 3000.0, 0.7, 0.001), 0.4);
    mix(out, blip(1500.0, 0.018), 1.0);
    mix(out, blip(750.0, 0.025), 0.5);
    mix(out, blip(2250.0, 0.01), 0.4, 0.018);
    return out;
}

Signal win_sting() {
    Rng rng(0x717ull);
    Signal out;
    // G4 C5 E5 G5 staccato, then the C major chord held with a timpani hit and a bell on top.
    const double run[] = {392.0, 523.25, 659.26, 783.99};
    for (int i = 0; i < 4; ++i) mix(out, brass(run[i], 0.08, 0.05, 1.0), 0.35, 0.1 * i);
    const double chord[] = {523.25, 659.26, 783.99, 1046.5};
    for (double pitch : chord) mix(out, brass(pitch, 1.0, 0.25, 0.3), 0.22, 0.42);
    Signal timpani = thump(98.0, 92.0, 0.1, 0.35);
    mix(timpani, noise_burst(rng, Pass::Low, 400.0, 0.7, 0.05), 0.4);
    mix(out, timpani, 0.5, 0.42);
    Signal bell = fm(1.5, constant(2093.0), 3.5, glide(3.0, 0.3, 0.6));
    shape(bell, [](double t) { return attack_decay(t, 0.002, 0.3); });
    mix(out, bell, 0.12, 0.42);
    filter(out, Pass::Low, 7000.0, 0.7);
    return reverb(out, Room{0.7, 0.5, 0.3, 1.0, 0.02, 1.0}, 1.0);
}

} // namespace ks::assetgen::sounds
