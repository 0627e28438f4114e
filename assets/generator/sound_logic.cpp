// Sounds of the level's logic: a locked door refusing the player, an objective done, a message arriving.
// Each has to read at once over combat without being mistaken for a weapon or a pickup: the lock is low and
// buzzing (a refusal), the objective a rising bell pair (good news, smaller than the win sting), the message
// a light two-blip chirp (attention, not an event in the world).
#include "sounds.h"

#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
// The handle tried against a locked latch: a short metallic knock of small steel parts.
Signal latch_knock(Rng& rng) {
    Signal s = modes(0.2, {{640.0, 1.0, 0.03}, {1510.0, 0.55, 0.02}, {2870.0, 0.25, 0.012}});
    mix(s, noise_burst(rng, Pass::Band, 2400.0, 1.2, 0.004), 0.45);
    return s;
}

// A lock's "denied" buzz: two detuned square waves, low passed so it buzzes rather than screams.
Signal denied_buzz(double seconds) {
    Signal s = oscillator(seconds, Wave::Square, constant(185.0));
    mix(s, oscillator(seconds, Wave::Square, constant(196.0)), 0.7);
    filter(s, Pass::Low, 1600.0, 0.9);
    shape(s, [seconds](double t) { return attack_hold_release(t, 0.004, seconds - 0.03, 0.01); });
    return s;
}

// A bell-like FM note that opens bright and mellows, with a soft sine under it for body.
Signal bell_note(double pitch, double decay) {
    const double length = decay * 4.5;
    Signal s = fm(length, constant(pitch), 2.0, glide(2.5, 0.6, decay));
    shape(s, [decay](double t) { return attack_decay(t, 0.002, decay); });
    Signal body = oscillator(length, Wave::Sine, constant(pitch));
    shape(body, [decay](double t) { return attack_decay(t, 0.01, decay * 1.4); });
    mix(s, body, 0.5);
    return s;
}

// A short sine blip with a quick downward flick, like a radio's squelch tone.
Signal chirp(double pitch, double seconds) {
    Signal s = oscillator(seconds, Wave::Sine, glide(pitch * 1.06, pitch, 0.015));
    mix(s, oscillator(seconds, Wave::Sine, constant(pitch * 2.0)), 0.15);
    shape(s, [seconds](double t) { return attack_hold_release(t, 0.002, seconds * 0.6, seconds * 0.12); });
    return s;
}
} // namespace

Signal door_locked() {
    Rng rng(0x10CCEDull);
    Signal out;
    // Rattled twice, the second softer, then the lock's buzzer answers twice.
    mix(out, latch_knock(rng), 0.7);
    mix(out, latch_knock(rng), 0.45, 0.075);
    mix(out, denied_buzz(0.1), 0.5, 0.17);
    mix(out, denied_buzz(0.1), 0.5, 0.31);
    return reverb(out, Room{0.35, 0.6, 0.12, 1.0, 0.005, 0.8}, 0.25);
}

Signal objective_complete() {
    Signal out;
    // A perfect fifth up (E5 then B5), the second note held longer, with a faint octave sparkle on it.
    mix(out, bell_note(659.26, 0.14), 0.55);
    mix(out, bell_note(987.77, 0.24), 0.6, 0.12);
    mix(out, bell_note(1975.5, 0.1), 0.12, 0.13);
    filter(out, Pass::Low, 9000.0, 0.7);
    return reverb(out, Room{0.5, 0.55, 0.2, 1.0, 0.015, 1.0}, 0.4);
}

Signal message_shown() {
    Rng rng(0x3E55A6Eull);
    Signal out;
    // A breath of static opening the channel, then two quick chirps up a fourth.
    Signal hiss = noise_burst(rng, Pass::Band, 3500.0, 0.8, 0.012);
    mix(out, hiss, 0.12);
    mix(out, chirp(1318.5, 0.055), 0.6, 0.01);
    mix(out, chirp(1760.0, 0.07), 0.6, 0.085);
    return reverb(out, Room{0.25, 0.7, 0.1, 1.0, 0.004, 0.7}, 0.15);
}

} // namespace ks::assetgen::sounds
