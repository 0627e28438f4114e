#include "audio/wav.h"
#include "test_support.h"

#include <cmath>
#include <cstring>
#include <doctest/doctest.h>
#include <fstream>
#include <string>

using namespace ks;
using audio::SoundData;

namespace {

void put_u16(std::string& s, unsigned v) {
    s += static_cast<char>(v & 0xff);
    s += static_cast<char>((v >> 8) & 0xff);
}
void put_u32(std::string& s, std::uint32_t v) {
    put_u16(s, v & 0xffff);
    put_u16(s, v >> 16);
}

// A WAV with a hand-written fmt chunk, so malformed headers can be built field by field.
struct WavSpec {
    unsigned tag = 1;
    unsigned channels = 1;
    std::uint32_t rate = 48000;
    unsigned bits = 16;
    unsigned block_align = 0; // 0: channels * bits / 8
    std::string data;         // raw sample bytes
    std::string extra_chunks; // placed between fmt and data
    std::uint32_t data_size_override = 0;
};

std::string build_wav(const WavSpec& w) {
    std::string fmt;
    put_u16(fmt, w.tag);
    put_u16(fmt, w.channels);
    put_u32(fmt, w.rate);
    const unsigned align = w.block_align ? w.block_align : w.channels * w.bits / 8;
    put_u32(fmt, w.rate * align);
    put_u16(fmt, align);
    put_u16(fmt, w.bits);
    std::string body = "WAVEfmt ";
    put_u32(body, static_cast<std::uint32_t>(fmt.size()));
    body += fmt + w.extra_chunks + "data";
    put_u32(body, w.data_size_override ? w.data_size_override : static_cast<std::uint32_t>(w.data.size()));
    body += w.data;
    std::string out = "RIFF";
    put_u32(out, static_cast<std::uint32_t>(body.size()));
    return out + body;
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// Reads `bytes` from a file called `name` and expects an error naming the file and containing `expected`.
void expect_error(const test::ScratchDir& dir, const std::string& name, const std::string& bytes,
                  const std::string& expected) {
    CAPTURE(name);
    const auto path = dir / name;
    write_bytes(path, bytes);
    auto result = audio::read_wav(path);
    REQUIRE_FALSE(result.ok());
    const std::string text = result.error().str();
    CAPTURE(text);
    CHECK(text.find(path.string()) != std::string::npos);
    CHECK(text.find(expected) != std::string::npos);
    CHECK_FALSE(result.error().hint.empty());
}

} // namespace

TEST_CASE("wav: a 16-bit sound survives write and read unchanged, mono and stereo") {
    test::ScratchDir dir;
    for (int channels : {1, 2}) {
        SoundData sound;
        sound.sample_rate = 22050;
        sound.channels = channels;
        for (int i = 0; i < 1000 * channels; ++i)
            sound.samples.push_back(static_cast<std::int16_t>(i * 67 - 32768));
        const auto path = dir / ("round_" + std::to_string(channels) + ".wav");
        REQUIRE(audio::write_wav(path, sound).ok());
        auto back = audio::read_wav(path);
        REQUIRE(back.ok());
        CHECK(back->sample_rate == 22050);
        CHECK(back->channels == channels);
        CHECK(back->frames() == 1000);
        CHECK(back->samples == sound.samples);
    }
}

TEST_CASE("wav: 8, 24, 32-bit PCM and 32-bit float convert to 16-bit; unknown chunks are skipped") {
    test::ScratchDir dir;
    SUBCASE("8-bit unsigned") {
        WavSpec w;
        w.bits = 8;
        w.data = std::string("\x00\x80\xff", 3);
        write_bytes(dir / "a.wav", build_wav(w));
        auto s = audio::read_wav(dir / "a.wav");
        REQUIRE(s.ok());
        CHECK(s->samples == std::vector<std::int16_t>{-32768, 0, 32512});
    }
    SUBCASE("24-bit keeps the top 16 bits") {
        WavSpec w;
        w.bits = 24;
        w.data = std::string("\x00\x34\x12\xff\xff\x80", 6); // 0x123400, 0x80ffff
        write_bytes(dir / "b.wav", build_wav(w));
        auto s = audio::read_wav(dir / "b.wav");
        REQUIRE(s.ok());
        CHECK(s->samples == std::vector<std::int16_t>{0x1234, static_cast<std::int16_t>(0x80ff)});
    }
    SUBCASE("32-bit int") {
        WavSpec w;
        w.bits = 32;
        w.data = std::string("\xff\xff\x00\x40", 4); // 0x4000ffff
        write_bytes(dir / "c.wav", build_wav(w));
        auto s = audio::read_wav(dir / "c.wav");
        REQUIRE(s.ok());
        CHECK(s->samples == std::vector<std::int16_t>{0x4000});
    }
    SUBCASE("float, clamped, NaN silent, stereo, with a LIST chunk of odd size before the data") {
        WavSpec w;
        w.tag = 3;
        w.bits = 32;
        w.channels = 2;
        for (float v : {0.5f, -1.0f, 2.0f, std::nanf("")}) {
            char b[4];
            std::memcpy(b, &v, 4);
            w.data.append(b, 4);
        }
        w.extra_chunks = std::string("LIST\x03\x00\x00\x00"
                                     "abc\x00",
                                     12); // odd size, padded
        write_bytes(dir / "d.wav", build_wav(w));
        auto s = audio::read_wav(dir / "d.wav");
        REQUIRE(s.ok());
        CHECK(s->channels == 2);
        CHECK(s->samples == std::vector<std::int16_t>{16384, -32767, 32767, 0});
    }
}

TEST_CASE("wav: every malformed file is an error naming the file, what is wrong and a fix") {
    test::ScratchDir dir;
    WavSpec good;
    good.data = std::string(200, '\x01');

    expect_error(dir, "magic.wav", "RIFX" + build_wav(good).substr(4), "not a RIFF/WAVE file");
    expect_error(dir, "tiny.wav", "RIFF", "not a RIFF/WAVE file");
    expect_error(dir, "text.wav", "this is a text file, not a sound at all", "not a RIFF/WAVE file");

    std::string truncated = build_wav(good);
    truncated.resize(truncated.size() - 50);
    expect_error(dir, "truncated.wav", truncated, "truncated");

    WavSpec mp3 = good;
    mp3.tag = 85;
    expect_error(dir, "mp3.wav", build_wav(mp3), "unsupported format 85 (MP3 in WAV)");
    WavSpec adpcm = good;
    adpcm.tag = 2;
    expect_error(dir, "adpcm.wav", build_wav(adpcm), "unsupported format 2 (Microsoft ADPCM in WAV)");

    WavSpec zero_channels = good;
    zero_channels.channels = 0;
    zero_channels.block_align = 2;
    expect_error(dir, "zero_channels.wav", build_wav(zero_channels), "0 channels");
    WavSpec six = good;
    six.channels = 6;
    expect_error(dir, "surround.wav", build_wav(six), "6 channels");

    WavSpec absurd_rate = good;
    absurd_rate.rate = 4000000000u;
    expect_error(dir, "rate.wav", build_wav(absurd_rate), "sample rate 2147483647 Hz is outside");
    WavSpec slow = good;
    slow.rate = 10;
    expect_error(dir, "slow.wav", build_wav(slow), "sample rate 10 Hz");

    WavSpec twelve_bit = good;
    twelve_bit.bits = 12;
    twelve_bit.block_align = 2;
    expect_error(dir, "bits.wav", build_wav(twelve_bit), "12-bit PCM samples are not supported");
    WavSpec bad_align = good;
    bad_align.block_align = 3;
    expect_error(dir, "align.wav", build_wav(bad_align), "block align 3");

    WavSpec empty = good;
    empty.data.clear();
    expect_error(dir, "empty.wav", build_wav(empty), "no samples");

    std::string no_data = "RIFF";
    put_u32(no_data, 4);
    no_data += "WAVE";
    expect_error(dir, "no_fmt.wav", no_data, "no fmt chunk");
    std::string header_only = build_wav(good);
    header_only.resize(36); // RIFF header + fmt chunk, nothing after
    expect_error(dir, "no_data.wav", header_only, "no data chunk");

    auto missing = audio::read_wav(dir / "nowhere.wav");
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error().str().find("nowhere.wav") != std::string::npos);
}

TEST_CASE("wav: the streaming writer fixes the header sizes on close and discards unfinished recordings") {
    test::ScratchDir dir;
    const auto path = dir / "recording.wav";
    std::vector<std::int16_t> expected;
    {
        auto writer = audio::WavWriter::open(path, 48000, 2);
        REQUIRE(writer.ok());
        for (int block = 0; block < 5; ++block) {
            std::vector<std::int16_t> frames(2 * 3000);
            for (std::size_t i = 0; i < frames.size(); ++i)
                frames[i] = static_cast<std::int16_t>(block * 1000 + i);
            REQUIRE(writer->write(frames.data(), 3000).ok());
            expected.insert(expected.end(), frames.begin(), frames.end());
        }
        CHECK(writer->frames_written() == 15000);
        CHECK_FALSE(std::filesystem::exists(path)); // nothing replaces the target before close
        REQUIRE(writer->close().ok());
        CHECK_FALSE(writer->write(expected.data(), 1).ok());
    }
    auto back = audio::read_wav(path);
    REQUIRE(back.ok());
    CHECK(back->channels == 2);
    CHECK(back->sample_rate == 48000);
    CHECK(back->samples == expected);
    CHECK(std::filesystem::file_size(path) == 44 + expected.size() * 2);

    const auto unfinished = dir / "unfinished.wav";
    {
        auto writer = audio::WavWriter::open(unfinished);
        REQUIRE(writer.ok());
        REQUIRE(writer->write(expected.data(), 100).ok());
    }
    CHECK_FALSE(std::filesystem::exists(unfinished));
    int leftovers = 0;
    for (auto& entry : std::filesystem::directory_iterator(dir.path()))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++leftovers;
    CHECK(leftovers == 0);
}

TEST_CASE("wav: writing refuses shapes it cannot store and folders that do not exist") {
    test::ScratchDir dir;
    SoundData sound;
    sound.channels = 3;
    sound.samples = {1, 2, 3};
    auto three = audio::write_wav(dir / "three.wav", sound);
    REQUIRE_FALSE(three.ok());
    CHECK(three.error().str().find("3 channels") != std::string::npos);

    sound.channels = 2;
    auto odd = audio::write_wav(dir / "odd.wav", sound);
    REQUIRE_FALSE(odd.ok());
    CHECK(odd.error().str().find("whole number") != std::string::npos);

    auto no_folder = audio::WavWriter::open(dir / "missing" / "x.wav");
    REQUIRE_FALSE(no_folder.ok());
    CHECK(no_folder.error().str().find("x.wav") != std::string::npos);
}
