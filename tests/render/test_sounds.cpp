// The committed sound effects (assets/sounds/, written by ks_assetgen): every name of the audio plan is there
// as 48 kHz mono 16-bit PCM, loud enough and never clipped, one-shots start at once and end in silence,
// loops are seamless, and the sounds are told apart (by spectrum, envelope, length, and the relations the
// design asks for: the robot's shot lower than the rifle's, the cylinder's blast bigger than the robot's...).
// That the files are what a fresh run of the generator writes is test_assetgen's byte-for-byte test. Sounds
// a designer replaced (assets/sounds/designer_sounds.txt) need only be readable.
#include "audio/wav.h"
#include "planned_sounds.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
constexpr double kRate = 48000.0;
constexpr double kPiDouble = 3.14159265358979323846;

fs::path sound_file(const std::string& name) {
    return ks::test::source_dir() / "assets" / "sounds" / (name + ".wav");
}

// The fmt chunk's format tag, channels, rate and bits, walking the RIFF chunks (0s when there is none).
struct WavFormat {
    unsigned tag = 0, channels = 0, rate = 0, bits = 0;
};
WavFormat wav_format(const std::string& bytes) {
    const auto u16 = [&](std::size_t at) {
        return static_cast<unsigned>(static_cast<unsigned char>(bytes[at])) |
               static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 1])) << 8;
    };
    const auto u32 = [&](std::size_t at) { return u16(at) | u16(at + 2) << 16; };
    WavFormat f;
    if (bytes.size() < 12 || bytes.compare(0, 4, "RIFF") != 0 || bytes.compare(8, 4, "WAVE") != 0) return f;
    for (std::size_t at = 12; at + 8 <= bytes.size(); at += 8 + u32(at + 4) + (u32(at + 4) & 1)) {
        if (bytes.compare(at, 4, "fmt ") == 0 && at + 24 <= bytes.size())
            return {u16(at + 8), u16(at + 10), u32(at + 12), u16(at + 22)};
    }
    return f;
}

struct Sound {
    std::string name;
    std::vector<double> x; // -1..1
    double seconds() const { return static_cast<double>(x.size()) / kRate; }
};

Sound load(const std::string& name) {
    auto data = ks::audio::read_wav(sound_file(name));
    REQUIRE_MESSAGE(data, name << ": " << (data ? "" : data.error().str()));
    Sound s{name, {}};
    for (std::int16_t v : data->samples) s.x.push_back(v / 32767.0);
    return s;
}

double peak(const std::vector<double>& x, std::size_t from = 0, std::size_t to = SIZE_MAX) {
    double p = 0.0;
    for (std::size_t i = from; i < std::min(to, x.size()); ++i) p = std::max(p, std::abs(x[i]));
    return p;
}

double rms(const std::vector<double>& x, std::size_t from = 0, std::size_t to = SIZE_MAX) {
    to = std::min(to, x.size());
    if (to <= from) return 0.0;
    double sum = 0.0;
    for (std::size_t i = from; i < to; ++i) sum += x[i] * x[i];
    return std::sqrt(sum / static_cast<double>(to - from));
}

double db(double v) {
    return 20.0 * std::log10(std::max(v, 1e-10));
}

void fft(std::vector<std::complex<double>>& a) {
    const std::size_t n = a.size();
    for (std::size_t i = 1, j = 0; i < n; ++i) {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(a[i], a[j]);
    }
    for (std::size_t len = 2; len <= n; len <<= 1) {
        const auto step = std::polar(1.0, -2.0 * kPiDouble / static_cast<double>(len));
        for (std::size_t i = 0; i < n; i += len) {
            std::complex<double> w(1.0);
            for (std::size_t k = 0; k < len / 2; ++k, w *= step) {
                const auto u = a[i + k], v = a[i + k + len / 2] * w;
                a[i + k] = u + v;
                a[i + k + len / 2] = u - v;
            }
        }
    }
}

// Power spectrum summed over 2048-sample Hann frames of samples [from, to) (bins 0..1024).
std::vector<double> power_spectrum(const std::vector<double>& x, std::size_t from = 0,
                                   std::size_t to = SIZE_MAX) {
    constexpr std::size_t kFrame = 2048;
    to = std::min(to, x.size());
    std::vector<double> power(kFrame / 2 + 1, 0.0);
    for (std::size_t start = from; start < to; start += kFrame / 2) {
        std::vector<std::complex<double>> a(kFrame);
        for (std::size_t i = 0; i < kFrame; ++i)
            a[i] =
                (start + i < to ? x[start + i] : 0.0) * (0.5 - 0.5 * std::cos(2.0 * kPiDouble * i / kFrame));
        fft(a);
        for (std::size_t k = 0; k < power.size(); ++k) power[k] += std::norm(a[k]);
    }
    return power;
}

double bin_hz(std::size_t k) {
    return static_cast<double>(k) * kRate / 2048.0;
}

// Magnitude-weighted mean frequency.
double centroid(const std::vector<double>& x, std::size_t from = 0, std::size_t to = SIZE_MAX) {
    const auto power = power_spectrum(x, from, to);
    double weighted = 0.0, total = 0.0;
    for (std::size_t k = 1; k < power.size(); ++k) {
        weighted += std::sqrt(power[k]) * bin_hz(k);
        total += std::sqrt(power[k]);
    }
    return total > 0.0 ? weighted / total : 0.0;
}

// The frequency of the strongest bin in samples [from, to): the pitch of a clear note.
double dominant_hz(const std::vector<double>& x, std::size_t from, std::size_t to) {
    const auto power = power_spectrum(x, from, to);
    return bin_hz(static_cast<std::size_t>(std::max_element(power.begin() + 1, power.end()) - power.begin()));
}

// Share of the power below `hz` in samples [from, to).
double low_share(const std::vector<double>& x, double hz, std::size_t from = 0, std::size_t to = SIZE_MAX) {
    const auto power = power_spectrum(x, from, to);
    double low = 0.0, total = 0.0;
    for (std::size_t k = 1; k < power.size(); ++k) {
        total += power[k];
        if (bin_hz(k) < hz) low += power[k];
    }
    return total > 0.0 ? low / total : 0.0;
}

// The spectrum's shape: dB per third-octave band from 50 Hz to 16 kHz, relative to the loudest band,
// floored at -60 dB.
std::vector<double> band_profile(const std::vector<double>& x) {
    const auto power = power_spectrum(x);
    std::vector<double> bands;
    for (double lo = 50.0; lo < 16000.0; lo *= std::pow(2.0, 1.0 / 3.0)) {
        double sum = 1e-20;
        for (std::size_t k = 1; k < power.size(); ++k)
            if (bin_hz(k) >= lo && bin_hz(k) < lo * std::pow(2.0, 1.0 / 3.0)) sum += power[k];
        bands.push_back(10.0 * std::log10(sum));
    }
    const double top = *std::max_element(bands.begin(), bands.end());
    for (double& b : bands) b = std::max(b - top, -60.0);
    return bands;
}

// RMS over 16 equal slices, relative to the loudest slice.
std::vector<double> envelope(const std::vector<double>& x) {
    std::vector<double> e;
    for (std::size_t s = 0; s < 16; ++s) e.push_back(rms(x, s * x.size() / 16, (s + 1) * x.size() / 16));
    const double top = *std::max_element(e.begin(), e.end());
    for (double& v : e) v /= top;
    return e;
}

double mean_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i] - b[i]);
    return sum / static_cast<double>(a.size());
}

// The step from the last sample to the first, over the largest step between neighbours within 10 ms either
// side of the seam (a loop's seam must be an ordinary step, no click).
double seam_ratio(const std::vector<double>& x) {
    const std::size_t n = x.size(), around = 480;
    const auto step = [&](std::size_t i) { return std::abs(x[(i + 1) % n] - x[i]); };
    double largest = 0.0;
    for (std::size_t k = 1; k <= around; ++k) largest = std::max({largest, step(n - 1 - k), step(k - 1)});
    return step(n - 1) / std::max(largest, 1e-9);
}

bool generated(const std::string& name) {
    static const std::set<std::string> designer = ks::test::designer_sounds();
    return designer.count(name) == 0;
}

// The generator's sounds (not the designer's), loaded once.
const std::map<std::string, Sound>& all_sounds() {
    static const std::map<std::string, Sound> sounds = [] {
        std::map<std::string, Sound> m;
        for (const auto* names : {&ks::test::planned_one_shots(), &ks::test::planned_loops()})
            for (const std::string& n : *names)
                if (generated(n) && fs::exists(sound_file(n))) m[n] = load(n);
        return m;
    }();
    return sounds;
}

const Sound& sound(const std::string& name) {
    const auto it = all_sounds().find(name);
    REQUIRE_MESSAGE(it != all_sounds().end(), "assets/sounds/" << name << ".wav is missing");
    return it->second;
}

} // namespace

TEST_CASE("every sound of the audio plan is committed as 48 kHz mono 16-bit PCM, within the size budget") {
    std::uintmax_t bytes = 0;
    for (const auto* names : {&ks::test::planned_one_shots(), &ks::test::planned_loops()})
        for (const std::string& name : *names) {
            CAPTURE(name);
            REQUIRE_MESSAGE(fs::exists(sound_file(name)), "missing; run ks_assetgen --out assets");
            bytes += fs::file_size(sound_file(name));
            if (!generated(name)) {
                const auto designer = ks::audio::read_wav(sound_file(name));
                CHECK_MESSAGE(designer, (designer ? "" : designer.error().str()));
                continue;
            }
            const WavFormat f = wav_format(ks::test::read_file(sound_file(name)));
            CHECK(f.tag == 1);
            CHECK(f.channels == 1);
            CHECK(f.rate == 48000);
            CHECK(f.bits == 16);
        }
    CHECK(ks::test::planned_one_shots().size() == 28);
    CHECK(ks::test::planned_loops().size() == 7);
    CHECK(bytes < 6u * 1024u * 1024u);
}

TEST_CASE("sounds are audible, peak at or below 0 dBFS and never clip") {
    for (const auto& [name, s] : all_sounds()) {
        CAPTURE(name);
        CHECK(s.seconds() > 0.04);
        CHECK(db(rms(s.x)) > -30.0);
        CHECK(db(peak(s.x)) <= 0.0);
        // Clipping shows as runs of samples pinned at full scale.
        int run = 0, longest = 0;
        for (double v : s.x) {
            run = std::abs(v) >= 32766.0 / 32767.0 ? run + 1 : 0;
            longest = std::max(longest, run);
        }
        CHECK(longest < 2);
    }
}

TEST_CASE("one-shots are normalised, start at once and end in silence") {
    for (const std::string& name : ks::test::planned_one_shots()) {
        if (!generated(name)) continue;
        CAPTURE(name);
        const Sound& s = sound(name);
        CHECK(db(peak(s.x)) == doctest::Approx(-1.0).epsilon(0.05));
        const double p = peak(s.x);
        std::size_t onset = 0;
        while (onset < s.x.size() && std::abs(s.x[onset]) < 0.01 * p) ++onset;
        CHECK(onset < 48 * 5); // within 5 ms
        CHECK(std::abs(s.x.front()) < 0.01);
        // No click at the end: the last sample is (nearly) zero and the last 5 ms are quiet.
        CHECK(std::abs(s.x.back()) < 4.0 / 32767.0);
        CHECK(db(peak(s.x, s.x.size() - 240)) < -40.0);
    }
}

TEST_CASE("loops are seamless, of their planned lengths and levels") {
    for (const std::string& name : ks::test::planned_loops()) {
        if (!generated(name)) continue;
        CAPTURE(name);
        const Sound& s = sound(name);
        const bool ambience = name.rfind("ambient_", 0) == 0;
        CHECK(s.seconds() >= (ambience ? 8.0 : 2.0));
        CHECK(s.seconds() <= (ambience ? 12.0 : 4.0));
        CHECK(seam_ratio(s.x) < 1.5);
        CHECK(db(peak(s.x)) <= -0.9);
        CHECK(db(rms(s.x)) <= -9.0);
    }
    if (generated("ambient_facility") && generated("ambient_dojo")) {
        CHECK(db(rms(sound("ambient_facility").x)) == doctest::Approx(-12.0).epsilon(0.05));
        CHECK(db(rms(sound("ambient_dojo").x)) < db(rms(sound("ambient_facility").x)) - 2.0);
    }

    // The seam check catches a click: 100.25 cycles of a sine end at its crest and jump back to zero.
    std::vector<double> broken(96000);
    for (std::size_t i = 0; i < broken.size(); ++i)
        broken[i] = 0.5 * std::sin(2.0 * kPiDouble * 100.25 * static_cast<double>(i) / 96000.0);
    CHECK(seam_ratio(broken) > 5.0);
    // While a whole number of cycles is seamless.
    for (std::size_t i = 0; i < broken.size(); ++i)
        broken[i] = 0.5 * std::sin(2.0 * kPiDouble * 100.0 * static_cast<double>(i) / 96000.0);
    CHECK(seam_ratio(broken) < 1.5);
}

TEST_CASE("every sound differs from every other in spectrum, envelope or length") {
    std::vector<const Sound*> list;
    std::map<std::string, std::vector<double>> bands, envelopes;
    for (const auto& [name, s] : all_sounds()) {
        list.push_back(&s);
        bands[name] = band_profile(s.x);
        envelopes[name] = envelope(s.x);
    }
    REQUIRE(list.size() == 35 - ks::test::designer_sounds().size());
    for (std::size_t i = 0; i < list.size(); ++i)
        for (std::size_t j = i + 1; j < list.size(); ++j) {
            const Sound &a = *list[i], &b = *list[j];
            const double spectrum_db = mean_abs_difference(bands[a.name], bands[b.name]);
            const double shape = mean_abs_difference(envelopes[a.name], envelopes[b.name]);
            const double length = std::abs(std::log2(a.seconds() / b.seconds()));
            INFO(a.name << " vs " << b.name << ": spectrum " << spectrum_db << " dB, envelope " << shape
                        << ", length " << length << " octaves");
            CHECK((spectrum_db > 4.0 || shape > 0.1 || length > 0.5));
        }
}

TEST_CASE("the sounds keep the relations of their design") {
    // A relation is only the generator's promise while all its sounds are the generator's.
    const auto ours = [](std::initializer_list<const char*> names) {
        return std::all_of(names.begin(), names.end(), [](const char* n) { return generated(n); });
    };
    if (ours({"rifle_shot", "robot_shot"})) // the robot's blaster is lower and buzzier
        CHECK(centroid(sound("robot_shot").x) < 0.8 * centroid(sound("rifle_shot").x));

    if (ours({"cylinder_explosion", "robot_explosion"})) {
        // The cylinder is the bigger blast: longer, and after the first crack (0.25 to 1.5 s) louder and
        // deeper.
        const auto& cylinder = sound("cylinder_explosion").x;
        const auto& robot_blast = sound("robot_explosion").x;
        CHECK(cylinder.size() > robot_blast.size());
        CHECK(rms(cylinder, 12000, 72000) > 1.5 * rms(robot_blast, 12000, 72000));
        CHECK(low_share(cylinder, 150.0, 12000, 72000) > low_share(robot_blast, 150.0, 12000, 72000));
    }
    if (ours({"land", "jump"})) // landing is heavier
        CHECK(low_share(sound("land").x, 150.0) > low_share(sound("jump").x, 150.0));
    if (ours({"footstep_stairs", "footstep_floor"})) // the metal tread rings on
        CHECK(sound("footstep_stairs").seconds() > 1.5 * sound("footstep_floor").seconds());
    if (ours({"ui_hover", "ui_click"})) CHECK(sound("ui_hover").seconds() < sound("ui_click").seconds());

    if (ours({"pickup_health", "pickup_ammo", "pickup_shield"})) {
        // Health the warmest, ammo the most metallic (brightest).
        const double health = centroid(sound("pickup_health").x), ammo = centroid(sound("pickup_ammo").x),
                     shield = centroid(sound("pickup_shield").x);
        CHECK(health < shield);
        CHECK(shield < ammo);
    }
    if (ours({"robot_alert"})) { // it rises: the second chirp is higher than the first
        const auto& alert = sound("robot_alert").x;
        CHECK(centroid(alert, 0, 5000) < centroid(alert, 8000, 15000));
    }
    if (ours({"door_locked", "door_open"})) { // the refusal is short and low: a buzz, not a slide
        CHECK(sound("door_locked").seconds() < 0.6 * sound("door_open").seconds());
        CHECK(centroid(sound("door_locked").x) < 2500.0);
    }
    if (ours({"objective_complete", "win_sting"})) { // good news that rises, smaller than the win
        const auto& done = sound("objective_complete").x;
        CHECK(dominant_hz(done, 0, 5000) * 1.3 < dominant_hz(done, 7000, 14000));
        CHECK(sound("objective_complete").seconds() < 0.6 * sound("win_sting").seconds());
    }
    if (ours({"message_shown", "objective_complete", "ui_click"})) { // a chirp: brief, between UI and news
        CHECK(sound("message_shown").seconds() < sound("objective_complete").seconds());
        CHECK(sound("message_shown").seconds() > sound("ui_click").seconds());
    }
    if (ours({"player_death"})) { // it falls
        const auto& death = sound("player_death").x;
        CHECK(centroid(death, 4800, 24000) > 1.5 * centroid(death, 48000, 72000));
    }
}

TEST_CASE("ks_assetgen reports and draws the sounds it made") {
    const fs::path generator = ks::test::bin_dir() / "ks_assetgen";
    REQUIRE_MESSAGE(fs::exists(generator), "build the ks_assetgen target first: " << generator);
    ks::test::ScratchDir scratch;
    const auto run = ks::test::run_command(
        "'" + generator.string() + "' --out '" + (scratch / "out").string() +
        "' --only ui_click --sound-report --sound-views '" + (scratch / "views").string() + "'");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK(run.output.find("centroid Hz") != std::string::npos);
    CHECK(run.output.find("ui_click") != std::string::npos);
    CHECK(fs::exists(scratch / "out" / "sounds" / "ui_click.wav"));
    const std::string png = ks::test::read_file(scratch / "views" / "ui_click.png");
    CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
}

TEST_CASE("ks_assetgen leaves the sounds a designer replaced alone") {
    const fs::path generator = ks::test::bin_dir() / "ks_assetgen";
    REQUIRE_MESSAGE(fs::exists(generator), "build the ks_assetgen target first: " << generator);
    ks::test::ScratchDir scratch;
    fs::create_directories(scratch / "out" / "sounds");
    const fs::path list = scratch / "out" / "sounds" / "designer_sounds.txt";
    const fs::path replaced = scratch / "out" / "sounds" / "ui_click.wav";
    ks::test::run_command("printf '# mine\\n  ui_click  # recorded\\n' > '" + list.string() + "'");
    ks::test::run_command("printf 'designer' > '" + replaced.string() + "'");
    const std::string exe = "'" + generator.string() + "' --out '" + (scratch / "out").string() + "'";

    const auto kept = ks::test::run_command(exe + " --only ui_click");
    INFO(kept.output);
    CHECK(kept.exit_code == 0);
    CHECK(ks::test::read_file(replaced) == "designer");
    CHECK(kept.output.find("kept the designer's sounds/ui_click.wav") != std::string::npos);
    // Sounds not on the list are still written.
    CHECK(ks::test::run_command(exe + " --only ui_hover").exit_code == 0);
    CHECK(fs::exists(scratch / "out" / "sounds" / "ui_hover.wav"));

    // A misspelt name is refused with the file, the line and the likely name.
    ks::test::run_command("printf 'ui_clik\\n' > '" + list.string() + "'");
    const auto typo = ks::test::run_command(exe + " --only ui_click");
    CHECK(typo.exit_code == 1);
    CHECK(typo.output.find("designer_sounds.txt:1") != std::string::npos);
    CHECK(typo.output.find("did you mean 'ui_click'") != std::string::npos);
}
