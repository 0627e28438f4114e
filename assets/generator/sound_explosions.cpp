// Explosions: one recipe with two settings. The gas cylinder is the bigger blast: a deeper, longer boom, a
// metal rupture, burning gas roaring after it and a bigger room; the robot throws more metal debris.
#include "sounds.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
struct Blast {
    std::uint64_t seed = 0;
    double boom_from = 90.0, boom_to = 40.0; // Hz: the pressure wave's pitch drop
    double boom_decay = 0.15;                // seconds (time constants)
    double body_decay = 0.3;
    double body_from = 6000.0, body_to = 180.0; // Hz: the body's brightness, collapsing
    double rumble_decay = 0.5;
    double rumble = 2.0; // level of the sub-bass rumble
    double crackle_seconds = 1.0;
    double roar = 0.0;         // level of the burning gas after the blast
    int debris = 0;            // metal pieces clattering down
    std::vector<Mode> rupture; // the container tearing open (none for the robot)
    Room room;
    double tail = 1.5;
};

Signal blast(const Blast& b) {
    Rng rng(b.seed);
    const double length = std::max(b.crackle_seconds, b.rumble_decay * 7.0) + 0.3;
    Signal out;
    // The shock front: a broadband crack, then a short boom driven into saturation so small speakers hear
    // its harmonics.
    mix(out, noise_burst(rng, Pass::Low, 9000.0, 0.7, 0.008), 0.9);
    Signal boom = thump(b.boom_from, b.boom_to, 0.25, b.boom_decay);
    saturate(boom, 2.2);
    mix(out, boom, 1.0);
    // The body: noise whose brightness collapses as the fireball expands, over a sub-bass rumble that rolls
    // (its level wandering) and carries the long decay.
    Signal body = white_noise(length, rng);
    filter(body, Pass::Low, glide(b.body_from, b.body_to, b.body_decay * 2.5), 0.7);
    shape(body, [&](double t) { return attack_decay(t, 0.004, b.body_decay); });
    mix(out, body, 0.9);
    Signal rumble = white_noise(length, rng);
    filter(rumble, Pass::Low, 110.0, 0.8);
    const Signal roll = wander(length, rng, 7.0);
    for (std::size_t i = 0; i < rumble.size(); ++i) rumble[i] *= 0.55 + 0.9 * roll[i];
    shape(rumble, [&](double t) { return attack_decay(t, 0.03, b.rumble_decay); });
    mix(out, rumble, b.rumble);
    // Burning fragments popping.
    Signal pops = crackle(b.crackle_seconds, rng,
                          knots({{0.0, 1800.0}, {b.crackle_seconds * 0.3, 900.0}, {b.crackle_seconds, 0.0}}));
    filter(pops, Pass::Band, 2200.0, 0.5);
    mix(out, pops, 0.7, 0.02);
    if (!b.rupture.empty()) mix(out, modes(1.0, b.rupture), 0.5);
    if (b.roar > 0.0) {
        Signal roar = white_noise(length, rng);
        filter(roar, Pass::Band, 600.0, 0.6);
        const Signal flicker = wander(length, rng, 14.0);
        for (std::size_t i = 0; i < roar.size(); ++i) roar[i] *= 0.5 + flicker[i];
        shape(roar, [](double t) { return attack_hold_release(t, 0.12, 1.0, 0.5); });
        mix(out, roar, b.roar, 0.05);
    }
    for (int i = 0; i < b.debris; ++i) {
        const double at = 0.15 + 1.1 * rng.uniform_double();
        const double pitch = 1200.0 + 2800.0 * rng.uniform_double();
        Signal piece =
            modes(0.2, {{pitch, 1.0, 0.03}, {pitch * 1.73, 0.5, 0.02}, {pitch * 2.61, 0.3, 0.012}});
        filter(piece, Pass::Low, 5000.0, 0.7);
        mix(out, piece, 0.08 + 0.12 * rng.uniform_double() * (1.3 - at / 1.3), at);
    }
    // Nothing below hearing (it would only eat headroom). Then squashed like a blast overloading the ear:
    // the body stays loud against the first crack; levelled first, so both blasts are driven alike.
    filter(out, Pass::High, 28.0, 0.7);
    scale(out, 1.0 / peak(out));
    saturate(out, 2.0);
    return reverb(out, b.room, b.tail);
}
} // namespace

Signal robot_explosion() {
    Blast b;
    b.seed = 0xB0B0E7ull;
    b.boom_from = 95.0;
    b.boom_to = 42.0;
    b.boom_decay = 0.12;
    b.body_decay = 0.22;
    b.rumble_decay = 0.4;
    b.body_from = 7000.0;
    b.body_to = 300.0;
    b.crackle_seconds = 0.9;
    b.debris = 10;
    b.room = Room{0.7, 0.5, 0.25, 1.0, 0.012, 1.0};
    b.tail = 1.2;
    return blast(b);
}

Signal cylinder_explosion() {
    Blast b;
    b.seed = 0xC71ADE2ull;
    b.boom_from = 75.0;
    b.boom_to = 32.0;
    b.boom_decay = 0.2;
    b.body_decay = 0.38;
    b.rumble_decay = 0.75;
    b.rumble = 3.4;
    b.body_from = 4000.0;
    b.body_to = 110.0;
    b.crackle_seconds = 1.6;
    b.roar = 0.25;
    b.debris = 4;
    b.rupture = {{182.0, 1.0, 0.25}, {411.0, 0.6, 0.18}, {773.0, 0.4, 0.12}, {1290.0, 0.25, 0.08}};
    b.room = Room{0.85, 0.45, 0.3, 1.0, 0.015, 1.15};
    b.tail = 1.8;
    return blast(b);
}

} // namespace ks::assetgen::sounds
