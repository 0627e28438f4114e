// The engine's bookkeeping through the loopback device: determinism, handles, the voice limit, sounds that
// do not exist, and the silent engine a machine without a sound card gets.
#include "audio/audio_engine.h"
#include "audio_test_signals.h"
#include "core/log.h"

#include <cstring>
#include <doctest/doctest.h>

using namespace ks;
using namespace ks::audio;

namespace {

constexpr float kVoiceFrame = 1.0f / 60.0f;

SoundBank test_bank() {
    SoundBank bank;
    bank.add("noise", test::white_noise());
    SoundData blip; // 0.1 s of a 1 kHz square wave
    for (int i = 0; i < 4800; ++i) blip.samples.push_back((i / 24) % 2 ? 8000 : -8000);
    bank.add("blip", std::move(blip));
    return bank;
}

AudioEngine voice_engine(EngineSettings settings = {}) {
    auto engine = AudioEngine::open_loopback(test_bank(), 48000, settings);
    REQUIRE_MESSAGE(engine.ok(), engine.error().str());
    return std::move(*engine);
}

PlayParams params(const char* sound, Vec3 position, int priority = 0) {
    PlayParams p;
    p.sound = sound;
    p.position = position;
    p.priority = priority;
    return p;
}

// A scripted minute of game: sounds start, move, stop, go behind walls, the listener turns.
std::vector<std::int16_t> scripted_render() {
    AudioEngine engine = voice_engine();
    std::vector<std::int16_t> out;
    VoiceHandle motor;
    for (int frame = 0; frame < 90; ++frame) {
        const float t = static_cast<float>(frame) * kVoiceFrame;
        engine.set_listener(Vec3(t, 1.5f, 0.0f), Vec3(std::sin(t), 0.0f, -std::cos(t)),
                            Vec3(0.0f, 1.0f, 0.0f));
        if (frame == 0) {
            PlayParams loop = params("noise", Vec3(-5.0f, 1.0f, -5.0f));
            loop.loop = true;
            loop.volume = 0.4f;
            motor = engine.play(loop);
        }
        if (frame % 7 == 0)
            engine.play(params("blip", Vec3(static_cast<float>(frame % 11) - 5.0f, 0.0f, -3.0f)));
        engine.set_position(motor, Vec3(-5.0f + t * 4.0f, 1.0f, -5.0f));
        if (frame == 60) engine.stop(motor);
        engine.update(kVoiceFrame, [&](Vec3, Vec3 source) { return source.x > 0.0f && frame > 30; });
        const auto block = test::render(engine, 800);
        out.insert(out.end(), block.begin(), block.end());
    }
    return out;
}

} // namespace

TEST_CASE("loopback: the same calls in the same order render byte-identical samples") {
    const auto first = scripted_render();
    const auto second = scripted_render();
    REQUIRE(first.size() == second.size());
    CHECK(test::rms_both(first) > 500.0); // something was really played
    CHECK(std::memcmp(first.data(), second.data(), first.size() * sizeof(std::int16_t)) == 0);
}

TEST_CASE("loopback: a sound that does not exist plays nothing, returns an invalid handle, warns once") {
    AudioEngine engine = voice_engine();
    log::Capture capture;
    const VoiceHandle voice = engine.play(params("no_such_sound", Vec3(0.0f)));
    CHECK_FALSE(voice.valid());
    CHECK_FALSE(engine.is_playing(voice));
    engine.set_position(voice, Vec3(1.0f));
    engine.set_volume(voice, 0.5f);
    engine.stop(voice);
    engine.play(params("no_such_sound", Vec3(0.0f)));
    engine.update(kVoiceFrame);
    CHECK(test::rms_both(test::render(engine, 4800)) < 2.0);
    CHECK(engine.stats().active_voices == 0);
    CHECK(capture.count(log::Level::Warn) == 1);
    CHECK(capture.text().find("no_such_sound") != std::string::npos);

    PlayParams nan_position = params("blip", Vec3(std::nanf(""), 0.0f, 0.0f));
    CHECK_FALSE(engine.play(nan_position).valid());
}

TEST_CASE("loopback: a one-shot ends by itself and its handle goes stale") {
    AudioEngine engine = voice_engine();
    const VoiceHandle blip = engine.play(params("blip", Vec3(0.0f, 0.0f, -2.0f)));
    CHECK(engine.is_playing(blip));
    engine.update(kVoiceFrame);
    CHECK(test::rms_both(test::render(engine, 2400)) > 1000.0);
    test::render(engine, 4800); // past its 0.1 s
    engine.update(kVoiceFrame);
    CHECK_FALSE(engine.is_playing(blip));
    CHECK(engine.stats().active_voices == 0);

    // The slot is reused by the next sound; the old handle must not reach it.
    const VoiceHandle next = engine.play(params("blip", Vec3(0.0f, 0.0f, -2.0f)));
    CHECK(next.slot == blip.slot);
    engine.stop(blip);
    CHECK(engine.is_playing(next));
    engine.stop(next);
    CHECK_FALSE(engine.is_playing(next));
}

TEST_CASE("loopback: the voice limit steals the least important voice and drops the less important sound") {
    EngineSettings settings;
    settings.voices = 4;
    AudioEngine engine = voice_engine(settings);
    engine.set_listener(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 1.0f, 0.0f));
    std::vector<VoiceHandle> voices;
    for (int i = 0; i < 4; ++i) {
        PlayParams p = params("noise", Vec3(0.0f, 0.0f, -4.0f - 8.0f * static_cast<float>(i)), 1);
        p.loop = true;
        voices.push_back(engine.play(p));
    }
    engine.update(kVoiceFrame);
    CHECK(engine.stats().active_voices == 4);
    // Same priority, louder than the farthest (quietest) voice: it takes that one's slot.
    const VoiceHandle near = engine.play(params("blip", Vec3(0.0f, 0.0f, -2.0f), 1));
    CHECK(near.valid());
    CHECK_FALSE(engine.is_playing(voices[3]));
    CHECK(engine.is_playing(voices[0]));
    // A lower priority sound loses to every voice.
    CHECK_FALSE(engine.play(params("blip", Vec3(0.0f, 0.0f, -1.0f), 0)).valid());
    const AudioStats stats = engine.stats();
    CHECK(stats.voice_limit == 4);
    CHECK(stats.active_voices == 4);
    CHECK(stats.stolen == 1);
    CHECK(stats.dropped == 1);
    engine.stop_all();
    CHECK(engine.stats().active_voices == 0);
}

TEST_CASE("audio: without an output device the engine runs silently after one notice") {
    AudioEngine silent = AudioEngine::silent(test_bank());
    CHECK_FALSE(silent.stats().output);
    CHECK_FALSE(silent.play(params("noise", Vec3(0.0f))).valid());
    silent.set_listener(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 1.0f, 0.0f));
    silent.set_volumes({});
    silent.set_game_paused(true);
    silent.update(kVoiceFrame, [](Vec3, Vec3) { return true; });
    std::vector<std::int16_t> out(200, 123);
    silent.render(out.data(), 100);
    CHECK(std::all_of(out.begin(), out.end(), [](std::int16_t s) { return s == 0; }));
    CHECK(silent.sounds().size() == 2);

    // The real default device: CI machines have none and must get the notice, exactly once.
    log::Capture capture;
    AudioEngine device = AudioEngine::open_device(test_bank());
    if (device.stats().output) {
        CHECK(capture.text().find("running silently") == std::string::npos);
    } else {
        CHECK(capture.count(log::Level::Info) == 1);
        CHECK(capture.text().find("audio: no output device (") != std::string::npos);
        CHECK(capture.text().find("); running silently") != std::string::npos);
    }
    device.update(kVoiceFrame);
}
