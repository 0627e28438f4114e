#include "audio/sound_bank.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <fstream>

using namespace ks;
using namespace ks::audio;

TEST_CASE("sound bank: loads every wav by name, reports broken ones by file and goes on") {
    test::ScratchDir dir;
    SoundData tone;
    tone.samples = {1, 2, 3, 4};
    REQUIRE(write_wav(dir / "door_open.wav", tone).ok());
    REQUIRE(write_wav(dir / "alarm_loop.wav", tone).ok());
    std::ofstream(dir / "broken.wav") << "not a wave file";
    std::ofstream(dir / "notes.txt") << "ignored";

    std::vector<Error> problems;
    SoundBank bank = SoundBank::load_folder(dir.path(), problems);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].str().find("broken.wav") != std::string::npos);
    CHECK(problems[0].str().find("not a RIFF/WAVE file") != std::string::npos);
    CHECK(bank.names() == std::vector<std::string>{"alarm_loop", "door_open"});
    REQUIRE(bank.find("door_open") != nullptr);
    CHECK(bank.find("door_open")->samples == tone.samples);
    CHECK(bank.find("broken") == nullptr);
    CHECK(bank.index_of("alarm_loop") == 0);
    CHECK(bank.index_of("zzz") == -1);

    bank.add("ui_click", tone);
    bank.add("door_open", SoundData{});
    CHECK(bank.names() == std::vector<std::string>{"alarm_loop", "door_open", "ui_click"});
    CHECK(bank.find("door_open")->samples.empty());
}

TEST_CASE("sound bank: a missing folder is one error naming it") {
    test::ScratchDir dir;
    std::vector<Error> problems;
    SoundBank bank = SoundBank::load_folder(dir / "no_sounds_here", problems);
    CHECK(bank.size() == 0);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].str().find("no_sounds_here") != std::string::npos);
}
