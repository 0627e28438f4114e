#pragma once
// Shared by the hardening tests (tests/{level,anim,editor}/test_fuzz_regressions.cpp): the fuzz regression
// files, scoped write faults, damaged copies of a file, and whether permission tests can mean anything here.
#include "core/files.h"
#include "core/result.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace ks::hardening {

// The kept corpus fuzz/corpus/<target>.tar.xz (minimised by scripts/fuzz.sh with KS_FUZZ_SAVE_CORPUS=1),
// unpacked once per test process into a scratch folder that lives as long as the process; an empty path
// when the target has none.
inline std::filesystem::path kept_corpus(const std::string& target) {
    static std::vector<std::pair<std::string, std::unique_ptr<ks::test::ScratchDir>>> unpacked;
    for (const auto& [name, dir] : unpacked)
        if (name == target) return dir->path();
    const auto archive = ks::test::source_dir() / "fuzz" / "corpus" / (target + ".tar.xz");
    if (!std::filesystem::exists(archive)) return {};
    auto dir = std::make_unique<ks::test::ScratchDir>();
    const auto result =
        ks::test::run_command("tar -xJf '" + archive.string() + "' -C '" + dir->path().string() + "'");
    REQUIRE_MESSAGE(result.exit_code == 0, result.output);
    unpacked.emplace_back(target, std::move(dir));
    return unpacked.back().second->path();
}

// Every file in tests/data/fuzz/<target>/ (seeds and crash/timeout/oom inputs found by scripts/fuzz.sh) and
// in the target's kept corpus, sorted so failures are reported in a stable order.
inline std::vector<std::filesystem::path> fuzz_inputs(const std::string& target) {
    std::vector<std::filesystem::path> out;
    for (const auto& dir : {ks::test::data_dir() / "fuzz" / target, kept_corpus(target)}) {
        if (dir.empty()) continue;
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
            if (entry.is_regular_file()) out.push_back(entry.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Makes every atomic write fail at one stage until the guard dies.
struct FaultGuard {
    explicit FaultGuard(files::Fault fault) { files::inject_fault(fault); }
    ~FaultGuard() { files::inject_fault(files::Fault::None); }
    FaultGuard(const FaultGuard&) = delete;
    FaultGuard& operator=(const FaultGuard&) = delete;
};

inline const char* fault_name(files::Fault fault) {
    switch (fault) {
    case files::Fault::None:
        return "none";
    case files::Fault::OpenTemp:
        return "read-only folder (OpenTemp)";
    case files::Fault::ShortWrite:
        return "disk full (ShortWrite)";
    case files::Fault::BeforeRename:
        return "killed before rename (BeforeRename)";
    }
    return "?";
}
inline constexpr files::Fault kSaveFaults[] = {files::Fault::OpenTemp, files::Fault::ShortWrite,
                                               files::Fault::BeforeRename};

// Temporary files an interrupted atomic write left in `dir` (".name.tmp-XXXXXX").
inline int leftover_temp_files(const std::filesystem::path& dir) {
    int n = 0;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++n;
    return n;
}

// Root reads and writes regardless of permission bits, so chmod-based tests prove nothing there; those
// cases are covered by fault injection (writes) and by a folder in place of the file (reads) instead.
inline bool permissions_enforced() {
    return ::geteuid() != 0;
}

// Damaged versions of a good file's text: what a crash, a bad copy or a full disk leaves behind.
struct Damaged {
    std::string what;
    std::string text;
};
inline std::vector<Damaged> damaged_copies(const std::string& good) {
    std::vector<Damaged> out;
    out.push_back({"empty", ""});
    out.push_back({"whitespace only", " \n\t\n"});
    for (double fraction : {0.01, 0.25, 0.5, 0.9, 0.999})
        out.push_back({"truncated at " + std::to_string(fraction),
                       good.substr(0, size_t(double(good.size()) * fraction))});
    std::string zeroed = good;
    std::fill(zeroed.begin() + long(zeroed.size() / 2), zeroed.begin() + long(zeroed.size() / 2 + 64), '\0');
    out.push_back({"64 NUL bytes in the middle (unflushed block)", zeroed});
    std::string flipped = good;
    for (size_t i = 7; i < flipped.size(); i += 97) flipped[i] = char(flipped[i] ^ 0x55);
    out.push_back({"bytes flipped every 97", flipped});
    out.push_back({"binary garbage", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\xff\xfe", 18)});
    out.push_back({"two copies glued together", good + good});
    return out;
}

// A rejected file's error says what is wrong and names the file it is about.
inline void check_clear_error(const Error& error, const std::string& file) {
    CHECK_FALSE(error.message.empty());
    CHECK_MESSAGE(error.str().find(file) != std::string::npos, error.str());
}

} // namespace ks::hardening
