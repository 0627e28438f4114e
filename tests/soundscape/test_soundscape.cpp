// The game heard through the loopback device: where a robot is by ear, walls muffling, pause, motors that
// follow robots, and a headless run's mix, byte for byte the same twice.
#include "audio/audio_test_signals.h"
#include "core/paths.h"
#include "game/game_test_levels.h"
#include "game/headless.h"
#include "soundscape/mix_recorder.h"
#include "soundscape/soundscape.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>
#include <iterator>

using namespace ks;
using namespace ks::game_test;

namespace {

constexpr int kRate = 48000;

// A bank where every sound the game asks for is white noise (level measurements need a broadband signal).
audio::SoundBank noise_bank() {
    audio::SoundBank bank;
    for (const char* name : {"robot_motor", "noise", "robot_alert", "robot_shot"})
        bank.add(name, test::white_noise());
    return bank;
}

audio::AudioEngine loopback(audio::SoundBank bank = noise_bank()) {
    auto engine = audio::AudioEngine::open_loopback(std::move(bank), kRate);
    REQUIRE_MESSAGE(engine.ok(), engine.error().str());
    return std::move(*engine);
}

// Steps the game `seconds`, running the soundscape per step, and returns the mix of the last `listen`
// seconds.
std::vector<std::int16_t> play_and_listen(game::Game& g, soundscape::Soundscape& s,
                                          audio::AudioEngine& engine, double seconds, double listen,
                                          const game::Input& in = {}) {
    std::vector<std::int16_t> heard;
    const int steps = static_cast<int>(seconds * 120.0 + 0.5),
              listen_from = steps - static_cast<int>(listen * 120.0);
    for (int i = 0; i < steps; ++i) {
        g.step(in);
        s.after_step(g);
        s.update(g, soundscape::player_listener(g), 1.0f / 120.0f);
        auto block = test::render(engine, kRate / 120);
        if (i >= listen_from) heard.insert(heard.end(), block.begin(), block.end());
    }
    return heard;
}

level::Level emitter_level(bool wall_between) {
    auto lv = flat_level();
    auto& e = lv.add(level::EntityType::Sound, Vec3(0.0f, 1.5f, -24.0f), "hum");
    auto& props = e.as<level::SoundProps>();
    props.sound.value = "noise";
    props.radius = 100.0f;
    props.volume = 1.0f;
    props.loop = true;
    lv.settings.ambient_sound.value.clear();
    if (wall_between) add_wall(lv, Vec3(0.0f, 0.0f, -12.0f), Vec3(40.0f, 16.0f, 1.0f));
    return lv;
}

} // namespace

TEST_CASE("a robot to the player's left is louder in the left channel; turning round swaps the sides") {
    auto lv = flat_level();
    lv.settings.ambient_sound.value.clear();
    auto& robot = add_robot(lv, Vec3(-14.0f, 0.0f, 0.0f));
    robot.as<level::RobotProps>().eye_radius_min = 0.0f; // it must not notice the player (and move or shoot)
    robot.as<level::RobotProps>().eye_radius_max = 0.0f;
    auto g = make_game(lv);
    audio::AudioEngine engine = loopback();
    soundscape::Soundscape s(engine, lv);
    const auto facing_ahead = play_and_listen(*g, s, engine, 0.6, 0.3);
    const double left = test::rms(facing_ahead, 0), right = test::rms(facing_ahead, 1);
    MESSAGE("robot 14 units to the left: left ", test::db(left / 32768.0), " dBFS, right ",
            test::db(right / 32768.0), " dBFS");
    REQUIRE(left > 50.0); // clearly audible
    CHECK(test::db(left / right) > 6.0);

    g->teleport_player(g->player().feet, kPi, 0.0f); // face +z: the robot is now on the right
    const auto turned = play_and_listen(*g, s, engine, 0.6, 0.3);
    CHECK(test::db(test::rms(turned, 1) / test::rms(turned, 0)) > 6.0);
    CHECK(s.motors_running() == 1);
}

TEST_CASE("a robot behind the player sounds duller than one in front: front and back are told apart") {
    auto listen_to_robot_at = [](Vec3 feet) {
        auto lv = flat_level();
        lv.settings.ambient_sound.value.clear();
        auto& robot = add_robot(lv, feet);
        robot.as<level::RobotProps>().eye_radius_min = 0.0f;
        robot.as<level::RobotProps>().eye_radius_max = 0.0f;
        auto g = make_game(lv);
        audio::AudioEngine engine = loopback();
        soundscape::Soundscape s(engine, lv);
        return play_and_listen(*g, s, engine, 0.6, 0.3);
    };
    const auto ahead = listen_to_robot_at(Vec3(0.0f, 0.0f, -12.0f)),
               behind = listen_to_robot_at(Vec3(0.0f, 0.0f, 12.0f));
    const double lows = test::db(test::low_band_rms(behind, 1000.0) / test::low_band_rms(ahead, 1000.0));
    const double highs = test::db(test::high_band_rms(behind, 5000.0) / test::high_band_rms(ahead, 5000.0));
    MESSAGE("robot behind vs ahead: below 1 kHz ", lows, " dB, above 5 kHz ", highs, " dB");
    CHECK(std::abs(test::db(test::rms(behind, 0) / test::rms(behind, 1))) < 1.0); // centred, like ahead
    CHECK(lows > -6.0);
    CHECK(highs < lows - 5.0);
}

TEST_CASE("a wall between the player and a sound muffles it: quieter, and the highs more than the rest") {
    auto measure = [](bool wall) {
        const auto lv = emitter_level(wall);
        auto g = make_game(lv);
        audio::AudioEngine engine = loopback();
        soundscape::Soundscape s(engine, lv);
        const auto heard = play_and_listen(*g, s, engine, 1.0, 0.5);
        return std::pair{test::rms_both(heard), test::high_band_rms(heard, 6000.0)};
    };
    const auto [open_rms, open_high] = measure(false);
    const auto [walled_rms, walled_high] = measure(true);
    const double level_drop = test::db(open_rms / walled_rms), high_drop = test::db(open_high / walled_high);
    MESSAGE("wall between: level -", level_drop, " dB, above 6 kHz -", high_drop, " dB");
    REQUIRE(open_rms > 100.0);
    // docs/audio.md: fully blocked = gain 0.5 (-6 dB) and, with EFX, the highs at 0.15 of that.
    CHECK(level_drop > 6.0);
    CHECK(level_drop < 20.0); // muffled, not gone
    const bool efx = audio::AudioEngine::open_loopback(noise_bank(), kRate)->stats().efx;
    if (efx) CHECK(high_drop > level_drop + 6.0);
}

TEST_CASE("pausing the game silences its sounds; resuming brings them back") {
    const auto lv = emitter_level(false);
    auto g = make_game(lv);
    audio::AudioEngine engine = loopback();
    soundscape::Soundscape s(engine, lv);
    const double playing = test::rms_both(play_and_listen(*g, s, engine, 0.5, 0.2));
    game::Input pause;
    pause.pause = true;
    play_and_listen(*g, s, engine, 1.0 / 120.0, 0.0, pause);
    const double paused = test::rms_both(play_and_listen(*g, s, engine, 0.3, 0.2));
    play_and_listen(*g, s, engine, 1.0 / 120.0, 0.0, pause);
    const double resumed = test::rms_both(play_and_listen(*g, s, engine, 0.3, 0.2));
    CHECK(playing > 100.0);
    CHECK(paused < playing * 0.01);
    CHECK(resumed > playing * 0.5);
}

TEST_CASE("a robot's motor stops when it dies; a shot robot is heard") {
    auto lv = flat_level();
    lv.settings.ambient_sound.value.clear();
    add_robot(lv, Vec3(0.0f, 0.0f, -10.0f));
    auto g = make_game(lv);
    audio::AudioEngine engine = loopback();
    soundscape::Soundscape s(engine, lv);
    play_and_listen(*g, s, engine, 0.2, 0.1);
    CHECK(s.motors_running() == 1);
    game::Input fire;
    fire.fire = true;
    for (int shot = 0; shot < 12 && !g->robots().empty() && g->robots()[0].alive(); ++shot) {
        play_and_listen(*g, s, engine, 1.0 / 120.0, 0.0, fire);
        play_and_listen(*g, s, engine, 0.1, 0.0);
    }
    REQUIRE_FALSE(g->robots()[0].alive());
    play_and_listen(*g, s, engine, 0.1, 0.0);
    CHECK(s.motors_running() == 0);
    CHECK(s.cues_played() > 5); // rifle shots, robot hits, its death
}

TEST_CASE("the headless mix of a bot run is non-silent and byte-identical across two runs") {
    const ks::test::ScratchDir scratch;
    const auto& dir = scratch.path();
    auto run = [&](const char* name) {
        game::HeadlessOptions o;
        o.level = paths::level("main.json");
        o.seconds = 6.0;
        o.seed = 3;
        o.autoplay = true;
        std::unique_ptr<soundscape::MixRecorder> recorder;
        const auto wav = dir / name;
        o.on_start = [&](const level::Level& level, const game::Game&) -> Result<void> {
            auto opened = soundscape::MixRecorder::open(wav, level);
            if (!opened) return opened.error();
            recorder = std::move(*opened);
            return {};
        };
        o.after_step = [&](const game::Game& g) { return recorder->after_step(g); };
        o.on_finish = [&](const game::Game&) { return recorder->finish(); };
        auto stats = game::run_headless(o);
        REQUIRE_MESSAGE(stats.ok(), stats.error().str());
        std::ifstream in(wav, std::ios::binary);
        return std::vector<char>(std::istreambuf_iterator<char>(in), {});
    };
    const auto a = run("a.wav"), b = run("b.wav");
    REQUIRE(a.size() > 44);
    // 6 s of 48 kHz 16-bit stereo after the 44-byte header.
    CHECK(a.size() == 44 + 6 * 48000 * 4);
    CHECK(a == b);
    auto read = audio::read_wav(dir / "a.wav");
    REQUIRE(read.ok());
    CHECK(read->channels == 2);
    CHECK(read->sample_rate == 48000);
    std::vector<std::int16_t> samples(read->samples.begin(), read->samples.end());
    const double level = test::rms_both(samples);
    MESSAGE("bot run mix: ", test::db(level / 32768.0), " dBFS RMS");
    CHECK(level > 100.0); // ambience, footsteps, shots
}
