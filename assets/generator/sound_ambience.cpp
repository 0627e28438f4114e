// Loops: the two level ambiences and the machine beds a sound entity can place. Each is built exactly
// periodic (see synth.h): steady tones with whole cycles per loop, events mixed with wrap-around, filters and
// reverb run as if the loop had always been playing, and evolving noise crossfaded into its own start.
#include "sounds.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen::sounds {
using namespace synth;

namespace {
// Noise that drifts: white noise through `process`, its level wandering `per_second` times a second between
// `floor` and 1, rendered past the loop and crossfaded back into its start.
Signal noise_bed(Rng& rng, double loop, double per_second, double floor,
                 const std::function<void(Signal&)>& process) {
    constexpr double kCrossfade = 0.5;
    Signal s = white_noise(loop + kCrossfade, rng);
    process(s);
    const Signal level = wander(loop + kCrossfade, rng, per_second);
    for (std::size_t i = 0; i < s.size(); ++i) s[i] *= floor + (1.0 - floor) * level[i];
    return crossfade_loop(s, kCrossfade);
}

// Steady sine partials (Hz, gain), each snapped to a whole number of cycles over the loop.
Signal drone(double loop, const std::vector<std::pair<double, double>>& partials) {
    Signal out = silence(loop);
    for (const auto& [pitch, gain] : partials)
        mix(out, oscillator(loop, Wave::Sine, constant(loop_frequency(pitch, loop))), gain);
    return out;
}

// A short beep for the consoles: a square or sine at `pitch`, `seconds` long, with soft edges.
Signal beep(Wave wave, double pitch, double seconds) {
    Signal s = oscillator(seconds + 0.02, wave, constant(pitch));
    if (wave == Wave::Square) filter(s, Pass::Low, 4000.0, 0.7);
    shape(s, [seconds](double t) { return attack_hold_release(t, 0.003, seconds, 0.008); });
    return s;
}
} // namespace

Signal ambient_facility() {
    constexpr double kLoop = 10.0;
    Rng rng(0xFAC111ull);
    // The building's drone: mains hum and its harmonics, close pairs beating slowly.
    Signal out =
        drone(kLoop, {{55.0, 0.5}, {55.3, 0.4}, {110.0, 0.3}, {110.4, 0.25}, {165.0, 0.1}, {220.2, 0.08}});
    mix(out, noise_bed(rng, kLoop, 0.4, 0.4, [](Signal& s) { filter(s, Pass::Low, 120.0, 0.7); }), 2.0);
    // Air handling breathing through the ducts.
    mix(out,
        noise_bed(rng, kLoop, 0.3, 0.3,
                  [](Signal& s) {
                      filter(s, Pass::Band, 450.0, 0.5);
                      filter(s, Pass::Low, 1500.0, 0.7);
                  }),
        0.5);
    // Distant machinery, heard through walls: a press thumping every 2.5 s, clanks, a hydraulic sigh.
    Signal far = silence(kLoop);
    for (int i = 0; i < 4; ++i) {
        Signal press = thump(62.0, 50.0, 0.05, 0.12);
        mix(press, noise_burst(rng, Pass::Low, 300.0, 0.7, 0.06), 0.6);
        mix_wrapped(far, press, 0.8, 0.4 + 2.5 * i);
    }
    const double clanks[][2] = {{1.3, 1.0}, {4.1, 0.7}, {4.35, 0.5}, {7.6, 0.9}, {9.2, 0.4}};
    for (const auto& [at, size] : clanks) {
        const double pitch = 180.0 + 500.0 * rng.uniform_double();
        mix_wrapped(far, modes(1.0, {{pitch, 1.0, 0.3}, {pitch * 2.37, 0.6, 0.2}, {pitch * 4.1, 0.3, 0.1}}),
                    0.35 * size, at);
    }
    Signal sigh = white_noise(1.5, rng);
    filter(sigh, Pass::Band, 2000.0, 0.8);
    shape(sigh, [](double t) { return attack_hold_release(t, 0.15, 0.3, 0.35); });
    mix_wrapped(far, sigh, 0.15, 6.0);
    process_looped(far, [](Signal& s) {
        filter(s, Pass::Low, 1200.0, 0.7);
        s = reverb(s, Room{0.85, 0.6, 0.6, 0.3, 0.03, 1.2}, 0.0);
    });
    mix(out, far, 1.0);
    return out;
}

Signal ambient_dojo() {
    constexpr double kLoop = 8.0;
    Rng rng(0xD0D0ull);
    // Still air in a quiet wooden room: soft broadband air, a little low room tone, faint high hiss.
    Signal out = noise_bed(rng, kLoop, 0.5, 0.7, [](Signal& s) {
        filter(s, Pass::Low, 2500.0, 0.7);
        filter(s, Pass::High, 150.0, 0.7);
    });
    mix(out, noise_bed(rng, kLoop, 0.3, 0.5, [](Signal& s) { filter(s, Pass::Low, 80.0, 0.7); }), 1.5);
    mix(out, noise_bed(rng, kLoop, 0.7, 0.3, [](Signal& s) { filter(s, Pass::Band, 6000.0, 0.5); }), 0.08);
    // The building settling: two faint wooden creaks in a soft room.
    Signal creaks = silence(kLoop);
    for (double at : {2.7, 6.1}) {
        Signal creak = crackle(0.35, rng, knots({{0.0, 60.0}, {0.2, 260.0}, {0.35, 0.0}}));
        Signal body = modes(0.02, {{340.0, 1.0, 0.012}, {610.0, 0.6, 0.008}, {920.0, 0.3, 0.005}});
        Signal wood = silence(0.4);
        for (std::size_t i = 0; i < creak.size(); ++i)
            if (creak[i] != 0.0) mix(wood, body, creak[i], static_cast<double>(i) / kSampleRate);
        mix_wrapped(creaks, wood, 0.12, at);
    }
    process_looped(creaks, [](Signal& s) { s = reverb(s, Room{0.5, 0.7, 0.3, 0.8, 0.01, 0.8}, 0.0); });
    mix(out, creaks, 1.0);
    return out;
}

Signal machine_hum() {
    constexpr double kLoop = 3.0;
    Rng rng(0x4A11ull);
    // A transformer's 100 Hz hum with its harmonics, a motor turning at 24.7 Hz, a bearing singing.
    Signal out = drone(kLoop, {{100.0, 1.0}, {200.0, 0.5}, {300.0, 0.35}, {400.0, 0.15}, {600.0, 0.08}});
    saturate(out, 1.2);
    Signal motor = oscillator(kLoop, Wave::Saw, constant(loop_frequency(24.7, kLoop)));
    Signal bearing = oscillator(kLoop, Wave::Sine, constant(loop_frequency(1230.0, kLoop)));
    shape(bearing, wobble(1.0, 0.6, 3.0));
    Signal hiss = white_noise(kLoop, rng);
    process_looped(motor, [](Signal& s) { filter(s, Pass::Low, 250.0, 1.2); });
    process_looped(hiss, [](Signal& s) { filter(s, Pass::Low, 600.0, 0.7); });
    mix(out, motor, 0.5);
    mix(out, bearing, 0.04);
    mix(out, hiss, 0.25);
    return out;
}

Signal vent_loop() {
    constexpr double kLoop = 4.0;
    Rng rng(0x7E47ull);
    // Air rushing through a duct, pulsed by the fan's blades eighteen times a second.
    Signal air = noise_bed(rng, kLoop, 0.8, 0.7, [](Signal& s) {
        filter(s, Pass::Band, 700.0, 0.4);
        filter(s, Pass::Low, 3000.0, 0.7);
    });
    shape(air, wobble(1.0, 0.25, 18.0));
    Signal out = drone(kLoop, {{72.0, 0.15}, {144.0, 0.05}});
    mix(out, air, 1.0);
    // A loose panel ticking once a turn.
    Signal ticks = silence(kLoop);
    for (int i = 0; i < 18; ++i) {
        const double size = 0.7 + 0.3 * rng.uniform_double();
        mix_wrapped(ticks, modes(0.05, {{2500.0, size, 0.006}, {4100.0, 0.5 * size, 0.004}}), 1.0,
                    i * kLoop / 18.0);
    }
    mix(out, ticks, 0.05);
    return out;
}

Signal alarm_loop() {
    constexpr double kLoop = 2.0;
    // Hi-lo, half a second each, each change smoothed over 20 ms centred on the beat. The changes are
    // symmetric, so the pitch averages (880 + 660) / 2 Hz and the loop holds a whole number of cycles.
    const auto pitch = [](double t) {
        const auto smooth = [](double x) { return 0.5 - 0.5 * std::cos(kPi * std::clamp(x, 0.0, 1.0)); };
        const double p = std::fmod(t, 1.0);
        const double low = p < 0.25   ? 1.0 - smooth((p + 0.01) / 0.02)
                           : p < 0.75 ? smooth((p - 0.49) / 0.02)
                                      : 1.0 - smooth((p - 0.99) / 0.02);
        return 880.0 + (660.0 - 880.0) * low;
    };
    Signal out = oscillator(kLoop, Wave::Square, pitch);
    mix(out, oscillator(kLoop, Wave::Saw, [&](double t) { return pitch(t) * 0.5; }), 0.4);
    process_looped(out, [](Signal& s) {
        filter(s, Pass::Low, 3200.0, 0.9);
        s = reverb(s, Room{0.6, 0.5, 0.3, 1.0, 0.02, 1.2}, 0.0);
    });
    return out;
}

Signal computer_beeps() {
    constexpr double kLoop = 4.0;
    Rng rng(0xC0B1ull);
    Signal out = silence(kLoop);
    // Chirps at random moments from a small set of pitches (a console's vocabulary).
    const double pitches[] = {1174.7, 1568.0, 1760.0, 2093.0, 2349.3, 2637.0};
    double at = 0.05;
    while (at < kLoop - 0.05) {
        const double seconds = 0.03 + 0.06 * rng.uniform_double();
        const double pitch = pitches[rng.below(6)];
        mix_wrapped(out, beep(rng.chance(0.5f) ? Wave::Square : Wave::Sine, pitch, seconds), 0.3, at);
        at += seconds + 0.04 + 0.3 * rng.uniform_double();
    }
    // A burst of data warble and a soft fan under it all.
    Signal warble = fm(0.6, wobble(1800.0, 0.3, 13.0), 2.0, constant(3.0));
    shape(warble, [](double t) { return attack_hold_release(t, 0.01, 0.5, 0.02); });
    mix_wrapped(out, warble, 0.06, 2.3);
    Signal fan = white_noise(kLoop, rng);
    process_looped(fan, [](Signal& s) { filter(s, Pass::Low, 900.0, 0.7); });
    mix(out, fan, 0.07);
    process_looped(out, [](Signal& s) { s = reverb(s, Room{0.3, 0.5, 0.12, 1.0, 0.005, 0.6}, 0.0); });
    return out;
}

} // namespace ks::assetgen::sounds
