// The game window's sound, without a sound card: --audio-out records the mix of a screenshot run through the
// loopback device (the same run, the same bytes), M mutes and the choice is saved, and the game runs silently
// with one notice where there is no output device.
#include "audio/wav.h"
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

using namespace ks;

namespace {

std::string game_command(const test::ScratchDir& dir) {
    static const test::PrivateDisplay display;
    return "env DISPLAY=" + display.name() + " XDG_CONFIG_HOME=" + (dir / "config").string() + " " +
           (test::bin_dir() / "killswitch").string() + " --width 480 --height 270 --status-file " +
           (dir / "status.txt").string();
}

double rms(const audio::SoundData& sound, std::size_t from_frame, std::size_t to_frame) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = from_frame * 2; i < std::min(to_frame * 2, sound.samples.size()); ++i, ++n)
        sum += static_cast<double>(sound.samples[i]) * sound.samples[i];
    return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

} // namespace

TEST_CASE(
    "--audio-out records a screenshot run's mix: a shot is heard, and the same run writes the same file") {
    REQUIRE_MESSAGE(test::have_display(), "needs a display: ./run.sh test runs this under xvfb-run");
    test::ScratchDir dir;
    const std::string run = game_command(dir) + " --screen play --fire --frames 60 --screenshot " +
                            (dir / "shot.png").string() + " --audio-out ";
    auto first = test::run_command(run + (dir / "a.wav").string());
    INFO(first.output);
    REQUIRE(first.exit_code == 0);
    auto second = test::run_command(run + (dir / "b.wav").string());
    REQUIRE(second.exit_code == 0);
    CHECK(test::read_file(dir / "a.wav") == test::read_file(dir / "b.wav"));
    auto wav = audio::read_wav(dir / "a.wav");
    REQUIRE_MESSAGE(wav.ok(), wav.error().str());
    CHECK(wav->channels == 2);
    CHECK(wav->sample_rate == 48000);
    // 60 frames of 1/60 s: one second of sound.
    CHECK(wav->frames() == 48000);
    const double shot = rms(*wav, 0, 9600), later = rms(*wav, 38400, 48000);
    MESSAGE("first 0.2 s (the shot): ", 20.0 * std::log10(shot / 32768.0),
            " dBFS; last 0.2 s: ", 20.0 * std::log10(later / 32768.0), " dBFS");
    CHECK(shot > 300.0);
    CHECK(shot > later * 2.0);
    const auto status = test::read_file(dir / "status.txt");
    CHECK(status.find("audio output 1") != std::string::npos); // the loopback device is an output
}

TEST_CASE("M mutes the game, the file remembers it, and a muted recording is silent") {
    REQUIRE_MESSAGE(test::have_display(), "needs a display: ./run.sh test runs this under xvfb-run");
    test::ScratchDir dir;
    std::ofstream(dir / "mute.txt") << "5 key m tap\n";
    auto run = test::run_command(game_command(dir) + " --screen play --input-script " +
                                 (dir / "mute.txt").string() + " --frames 40 --screenshot " +
                                 (dir / "m.png").string() + " --audio-out " + (dir / "m.wav").string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const auto status = test::read_file(dir / "status.txt");
    CHECK(status.find("sound master 0.80 effects 1.00 ambience 0.70 muted 1") != std::string::npos);
    const auto saved = test::read_file(dir / "config" / "killswitch" / "options.json");
    CHECK(saved.find("\"muted\": true") != std::string::npos);
    auto wav = audio::read_wav(dir / "m.wav");
    REQUIRE(wav.ok());
    // Frames 0-4 may carry sound; after the key every sample is silent (dither is off at zero gain).
    CHECK(rms(*wav, 48000 / 60 * 8, static_cast<std::size_t>(wav->frames())) < 2.0);
}

TEST_CASE("without a sound card the game plays silently with one notice line") {
    REQUIRE_MESSAGE(test::have_display(), "needs a display: ./run.sh test runs this under xvfb-run");
    test::ScratchDir dir;
    // An ALSA configuration that names no card, whatever this machine has: OpenAL Soft finds no device.
    std::ofstream(dir / "asoundrc") << "pcm.!default { type null }\n";
    auto run =
        test::run_command("env ALSOFT_DRIVERS=none " + game_command(dir) +
                          " --screen play --fire --frames 20 --screenshot " + (dir / "s.png").string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    std::size_t notices = 0;
    for (std::size_t at = run.output.find("audio: no output device"); at != std::string::npos;
         at = run.output.find("audio: no output device", at + 1))
        ++notices;
    CHECK(notices == 1);
    CHECK(test::read_file(dir / "status.txt").find("audio output 0") != std::string::npos);
}
