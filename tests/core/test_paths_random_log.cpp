#include "core/log.h"
#include "core/math.h"
#include "core/paths.h"
#include "core/random.h"

#include <cstdlib>
#include <doctest/doctest.h>
#include <filesystem>
#include <optional>
#include <string>

using namespace ks;
namespace fs = std::filesystem;

TEST_CASE("data root holds assets/ and levels/") {
    const fs::path& root = paths::data_root();
    CHECK(fs::is_directory(root / "assets"));
    CHECK(fs::is_directory(root / "levels"));
    CHECK(paths::level("main.json") == root / "levels" / "main.json");
    CHECK(paths::asset("fonts") == root / "assets" / "fonts");
    CHECK(fs::exists(paths::executable_dir()));
}

namespace {
// Sets an environment variable (or unsets it: nullptr) for one scope, then puts the old value back.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        value ? ::setenv(name, value, 1) : ::unsetenv(name);
    }
    ~ScopedEnv() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

  private:
    const char* name_;
    std::optional<std::string> old_;
};
} // namespace

TEST_CASE("the player's config and data folders follow the XDG rule: absolute variable, else HOME") {
    const ScopedEnv home("HOME", "/home/ks-test");
    {
        const ScopedEnv config("XDG_CONFIG_HOME", "/tmp/ks-xdg-config");
        const ScopedEnv data("XDG_DATA_HOME", "/tmp/ks-xdg-data");
        CHECK(paths::user_config_dir() == fs::path("/tmp/ks-xdg-config/killswitch"));
        CHECK(paths::user_data_dir() == fs::path("/tmp/ks-xdg-data/killswitch"));
    }
    for (const char* ignored : {"relative/config", "", static_cast<const char*>(nullptr)}) {
        CAPTURE(ignored ? ignored : "(unset)");
        const ScopedEnv config("XDG_CONFIG_HOME", ignored);
        const ScopedEnv data("XDG_DATA_HOME", ignored);
        CHECK(paths::user_config_dir() == fs::path("/home/ks-test/.config/killswitch"));
        CHECK(paths::user_data_dir() == fs::path("/home/ks-test/.local/share/killswitch"));
    }
    const ScopedEnv no_home("HOME", nullptr);
    const ScopedEnv relative("XDG_CONFIG_HOME", "relative/config");
    CHECK(paths::user_config_dir().empty());
    const ScopedEnv absolute("XDG_CONFIG_HOME", "/tmp/ks-xdg-config");
    CHECK(paths::user_config_dir() == fs::path("/tmp/ks-xdg-config/killswitch"));
}

TEST_CASE("Rng is deterministic and in range") {
    Rng a(42), b(42), c(43);
    bool differs = false;
    for (int i = 0; i < 1000; ++i) {
        float x = a.uniform();
        CHECK(x == b.uniform());
        CHECK(x >= 0.0f);
        CHECK(x < 1.0f);
        if (x != c.uniform()) differs = true;
        CHECK(a.below(7) < 7u);
        b.below(7);
        c.below(7);
    }
    CHECK(differs);
    // The PCG32 reference sequence for seed 42, stream 54 (from the PCG paper's demo program).
    Rng ref(42, 54);
    CHECK(ref.next_u32() == 0xa15c02b7u);
    CHECK(ref.next_u32() == 0x7b47f409u);
    CHECK(ref.next_u32() == 0xba1d3330u);
}

TEST_CASE("log capture counts levels") {
    log::Capture capture;
    log::warn("missing file ", "x.png", " used ", 1, " placeholder");
    log::error("bad");
    CHECK(capture.count(log::Level::Warn) == 1);
    CHECK(capture.count(log::Level::Error) == 1);
    CHECK(capture.text().find("missing file x.png used 1 placeholder") != std::string::npos);
}

TEST_CASE("yaw/pitch/roll quaternion conventions") {
    Quat yaw90 = quat_from_ypr(radians(90.0f), 0, 0);
    Vec3 forward = yaw90 * Vec3(0, 0, -1); // -z turned left by 90 degrees about +y is -x
    CHECK(forward.x == doctest::Approx(-1.0f).epsilon(1e-6));
    CHECK(forward.z == doctest::Approx(0.0f).epsilon(1e-6));
    CHECK(is_finite(Vec3(1, 2, 3)));
    CHECK_FALSE(is_finite(Vec3(1, NAN, 3)));
}
