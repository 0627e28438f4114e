// The engine rendered through OpenAL Soft's loopback device: no sound card needed, so these run on CI.
#include "audio/audio_engine.h"
#include "audio_test_signals.h"
#include "core/log.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::audio;

namespace {

constexpr float kLoopbackFrame = 1.0f / 60.0f;
constexpr int kHalfSecond = 24000;

SoundBank noise_bank() {
    SoundBank bank;
    bank.add("noise", test::white_noise());
    return bank;
}

AudioEngine loopback(SoundBank bank = noise_bank(), EngineSettings settings = {}) {
    auto engine = AudioEngine::open_loopback(std::move(bank), 48000, settings);
    REQUIRE_MESSAGE(engine.ok(), engine.error().str());
    engine->set_listener(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 1.0f, 0.0f));
    return std::move(*engine);
}

PlayParams noise_at(Vec3 position) {
    PlayParams p;
    p.sound = "noise";
    p.position = position;
    p.loop = true;
    return p;
}

// Level difference left over right, in dB, of a looping noise source at `position`.
double left_over_right_db(Vec3 position, Vec3 forward = Vec3(0.0f, 0.0f, -1.0f)) {
    AudioEngine engine = loopback();
    engine.set_listener(Vec3(0.0f), forward, Vec3(0.0f, 1.0f, 0.0f));
    engine.play(noise_at(position));
    engine.update(kLoopbackFrame);
    const auto out = test::render(engine, kHalfSecond);
    return test::db(test::rms(out, 0) / std::max(test::rms(out, 1), 1.0));
}

} // namespace

TEST_CASE("loopback: a source to the listener's left is louder in the left channel") {
    // 45 degrees to the front left: 22.5 dB louder on the left (OpenAL Soft 1.19 stereo panning).
    const double front_left = left_over_right_db(Vec3(-3.0f, 0.0f, -3.0f));
    MESSAGE("45 degrees left: left channel " << front_left << " dB over the right");
    CHECK(front_left > 10.0);
    CHECK(left_over_right_db(Vec3(3.0f, 0.0f, -3.0f)) < -10.0);
    CHECK(left_over_right_db(Vec3(-3.0f, 0.0f, 0.0f)) > 40.0); // hard left: the right channel is silent
    CHECK(std::abs(left_over_right_db(Vec3(0.0f, 0.0f, -3.0f))) < 0.5); // straight ahead: centred
    // Turn the listener around: the same source is now behind to the right.
    CHECK(left_over_right_db(Vec3(-3.0f, 0.0f, -3.0f), Vec3(0.0f, 0.0f, 1.0f)) < -10.0);
}

TEST_CASE("loopback: a source behind the listener is duller than the same source in front") {
    // Stereo panning puts front and back in the same place; the rear shading (attenuation.h, rear_highs:
    // highs x0.6 at the filter's 5 kHz reference straight behind) tells them apart. OpenAL Soft's stereo
    // decode itself makes a source straight behind 3.4 dB quieter than in front, at all frequencies.
    auto render_at = [](Vec3 position) {
        AudioEngine engine = loopback();
        engine.play(noise_at(position));
        engine.update(kLoopbackFrame);
        return test::render(engine, kHalfSecond);
    };
    const auto front = render_at(Vec3(0.0f, 0.0f, -6.0f)), behind = render_at(Vec3(0.0f, 0.0f, 6.0f));
    const auto side = render_at(Vec3(-6.0f, 0.0f, 0.0f));
    const double lows = test::db(test::low_band_rms(behind, 1000.0) / test::low_band_rms(front, 1000.0));
    const double highs = test::db(test::high_band_rms(behind, 5000.0) / test::high_band_rms(front, 5000.0));
    MESSAGE("behind vs in front: below 1 kHz " << lows << " dB, above 5 kHz " << highs << " dB");
    CHECK(lows > -5.0);        // the body of the sound is still clearly heard
    CHECK(highs < lows - 5.0); // duller, not just quieter
    // Beside the listener nothing is shaded.
    CHECK(test::high_band_rms(side, 5000.0) / test::rms(side, 0) ==
          doctest::Approx(test::high_band_rms(front, 5000.0) / test::rms(front, 0)).epsilon(0.15));
    CHECK(rear_highs(Vec3(0, 0, -1), Vec3(0, 0, -5)) == 1.0f);
    CHECK(rear_highs(Vec3(0, 0, -1), Vec3(0, 0, 5)) == doctest::Approx(kRearGainHf));
    CHECK(rear_highs(Vec3(0, 0, -1), Vec3(0.0f)) == 1.0f);
}

TEST_CASE("loopback: distance attenuation follows attenuation.h, silent past the max distance") {
    auto level_at = [](float distance) {
        AudioEngine engine = loopback();
        PlayParams p = noise_at(Vec3(0.0f, 0.0f, -distance));
        p.ref_distance = 4.0f;
        p.max_distance = 64.0f;
        engine.play(p);
        engine.update(kLoopbackFrame);
        return test::rms_both(test::render(engine, kHalfSecond));
    };
    const double at_4 = level_at(4.0f), at_8 = level_at(8.0f), at_16 = level_at(16.0f),
                 at_70 = level_at(70.0f);
    CHECK(test::db(at_8 / at_4) == doctest::Approx(-6.02).epsilon(0.05));
    CHECK(test::db(at_16 / at_4) == doctest::Approx(-12.04).epsilon(0.05));
    CHECK(at_70 < 2.0); // past max_distance: nothing but OpenAL's dither
    CHECK(distance_gain(8.0f, 8.0f, 150.0f) == 1.0f);
    CHECK(distance_gain(16.0f, 8.0f, 150.0f) == doctest::Approx(0.5f));
    CHECK(distance_gain(150.0f, 8.0f, 150.0f) == 0.0f);
    CHECK(distance_gain(131.25f, 8.0f, 150.0f) ==
          doctest::Approx(8.0f / 131.25f * 0.5f)); // half way into the fade
    CHECK(distance_gain(std::nanf(""), 8.0f, 150.0f) == 0.0f);
}

TEST_CASE("loopback: a blocked source is quieter and loses its highs") {
    // White noise 3 units in front. Fully blocked through the EFX low-pass (gain 0.5, gain HF 0.15):
    // measured broadband -16.5 dB, above 5 kHz -29.6 dB.
    auto render_with = [](bool wall) {
        AudioEngine engine = loopback();
        engine.play(noise_at(Vec3(0.0f, 0.0f, -3.0f)));
        engine.update(kLoopbackFrame, [&](Vec3, Vec3) { return wall; });
        CHECK(engine.stats().rays_this_update == 1);
        return test::render(engine, kHalfSecond);
    };
    const auto clear = render_with(false), blocked = render_with(true);
    const double broadband = test::db(test::rms_both(blocked) / test::rms_both(clear));
    const double highs = test::db(test::high_band_rms(blocked, 5000.0) / test::high_band_rms(clear, 5000.0));
    MESSAGE("blocked: broadband " << broadband << " dB, above 5 kHz " << highs << " dB");
    AudioEngine probe = loopback();
    REQUIRE(probe.stats().efx); // OpenAL Soft always has ALC_EXT_EFX
    CHECK(broadband < -12.0);
    CHECK(broadband > -20.0);
    CHECK(highs < -22.0);
    CHECK(highs < broadband - 6.0); // the highs go more than the rest: muffled, not just quieter
}

TEST_CASE("loopback: occlusion fades in and out without a jump") {
    AudioEngine engine = loopback();
    engine.play(noise_at(Vec3(0.0f, 0.0f, -3.0f)));
    bool wall = false;
    auto blocked = [&](Vec3, Vec3) { return wall; };
    engine.update(kLoopbackFrame, blocked);
    const double clear = test::rms_both(test::render(engine, 800));
    wall = true;
    std::vector<double> levels;
    for (int frame = 0; frame < 30; ++frame) {
        engine.update(kLoopbackFrame, blocked);
        levels.push_back(test::rms_both(test::render(engine, 800)));
    }
    // Each 60 Hz frame moves at most 19% of the way: no frame drops by more than 3 dB.
    double previous = clear;
    for (double level : levels) {
        CHECK(test::db(level / previous) > -3.0);
        previous = level;
    }
    CHECK(test::db(levels.back() / clear) < -12.0);
}

TEST_CASE("loopback: pausing the game pauses game voices, not menu voices") {
    auto level = [](bool game_voice, bool paused) {
        AudioEngine engine = loopback();
        PlayParams p = noise_at(Vec3(0.0f));
        p.positional = false;
        p.game = game_voice;
        p.bus = game_voice ? Bus::Effects : Bus::Ui;
        const VoiceHandle voice = engine.play(p);
        engine.update(kLoopbackFrame);
        test::render(engine, 4800);
        engine.set_game_paused(paused);
        engine.update(kLoopbackFrame);
        test::render(engine, 1024); // OpenAL Soft fades a pausing voice out over its next mix
        const double during = test::rms_both(test::render(engine, 4800));
        CHECK(engine.is_playing(voice)); // paused, not ended
        engine.set_game_paused(false);
        engine.update(kLoopbackFrame);
        const double after = test::rms_both(test::render(engine, 4800));
        CHECK(after > 1000.0);
        return during;
    };
    CHECK(level(true, true) < 2.0);
    CHECK(level(true, false) > 1000.0);
    CHECK(level(false, true) > 1000.0);

    // A game sound asked for while paused waits for the resume.
    AudioEngine engine = loopback();
    engine.set_game_paused(true);
    PlayParams p = noise_at(Vec3(0.0f));
    p.positional = false;
    engine.play(p);
    engine.update(kLoopbackFrame);
    CHECK(test::rms_both(test::render(engine, 4800)) < 2.0);
    engine.set_game_paused(false);
    engine.update(kLoopbackFrame);
    CHECK(test::rms_both(test::render(engine, 4800)) > 1000.0);
}

TEST_CASE("loopback: master, bus volumes and mute scale the output") {
    auto level = [](Volumes volumes, Bus bus) {
        AudioEngine engine = loopback();
        engine.set_volumes(volumes);
        PlayParams p = noise_at(Vec3(0.0f));
        p.positional = false;
        p.bus = bus;
        engine.play(p);
        engine.update(kLoopbackFrame);
        return test::rms_both(test::render(engine, 9600));
    };
    const double full = level({}, Bus::Effects);
    CHECK(full > 1000.0);
    CHECK(level({0.5f, 1.0f, 1.0f, false}, Bus::Effects) / full == doctest::Approx(0.5).epsilon(0.02));
    CHECK(level({1.0f, 0.25f, 1.0f, false}, Bus::Effects) / full == doctest::Approx(0.25).epsilon(0.02));
    CHECK(level({1.0f, 0.25f, 1.0f, false}, Bus::Ambience) / full == doctest::Approx(1.0).epsilon(0.02));
    CHECK(level({1.0f, 1.0f, 0.5f, false}, Bus::Ambience) / full == doctest::Approx(0.5).epsilon(0.02));
    CHECK(level({1.0f, 0.0f, 0.0f, false}, Bus::Ui) / full == doctest::Approx(1.0).epsilon(0.02));
    CHECK(level({1.0f, 1.0f, 1.0f, true}, Bus::Ui) < 2.0);
    CHECK(level({0.0f, 1.0f, 1.0f, false}, Bus::Effects) < 2.0);
}
