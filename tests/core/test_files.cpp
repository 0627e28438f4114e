#include "core/files.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <filesystem>
#include <unistd.h>

using namespace ks;
namespace fs = std::filesystem;

namespace {
int leftover_temp_files(const fs::path& dir) {
    int n = 0;
    for (auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++n;
    return n;
}
struct FaultGuard {
    explicit FaultGuard(files::Fault f) { files::inject_fault(f); }
    ~FaultGuard() { files::inject_fault(files::Fault::None); }
};
} // namespace

TEST_CASE("atomic write creates and replaces files") {
    test::ScratchDir dir;
    fs::path target = dir / "level.json";
    REQUIRE(files::write_atomic(target, "first").ok());
    CHECK(test::read_file(target) == "first");
    REQUIRE(files::write_atomic(target, "second, longer").ok());
    CHECK(test::read_file(target) == "second, longer");
    CHECK(leftover_temp_files(dir.path()) == 0);

    auto read = files::read_text(target);
    REQUIRE(read.ok());
    CHECK(*read == "second, longer");
}

TEST_CASE("atomic write keeps the previous file intact when a save fails at any stage") {
    test::ScratchDir dir;
    fs::path target = dir / "level.json";
    REQUIRE(files::write_atomic(target, "precious original").ok());

    for (files::Fault fault : {files::Fault::OpenTemp, files::Fault::ShortWrite, files::Fault::BeforeRename}) {
        CAPTURE(static_cast<int>(fault));
        FaultGuard guard(fault);
        auto result = files::write_atomic(target, "replacement that must not appear half-written");
        REQUIRE_FALSE(result.ok());
        CHECK(result.error().where.file == target.string());
        CHECK(result.error().hint.find("previous file") != std::string::npos);
        CHECK(test::read_file(target) == "precious original");
    }
    // Only the simulated crash leaves its temp file behind (as a real crash would); the others clean up.
    CHECK(leftover_temp_files(dir.path()) <= 1);
}

TEST_CASE("atomic write into a missing folder and reading missing files give clear errors") {
    test::ScratchDir dir;
    auto write = files::write_atomic(dir / "no-such-folder" / "x.json", "data");
    REQUIRE_FALSE(write.ok());
    CHECK(write.error().message.find("temporary file") != std::string::npos);

    auto read = files::read_text(dir / "missing.json");
    REQUIRE_FALSE(read.ok());
    CHECK(read.error().message == "file not found");
    CHECK(read.error().where.file.find("missing.json") != std::string::npos);

    auto folder = files::read_text(dir.path());
    REQUIRE_FALSE(folder.ok());
}

TEST_CASE("atomic write into a read-only folder fails cleanly") {
    if (::geteuid() == 0) {
        // root ignores folder permissions; the injected OpenTemp fault above covers this path.
        MESSAGE("running as root: read-only folder covered by fault injection");
        return;
    }
    test::ScratchDir dir;
    fs::path target = dir / "level.json";
    REQUIRE(files::write_atomic(target, "original").ok());
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    auto result = files::write_atomic(target, "new");
    fs::permissions(dir.path(), fs::perms::owner_all);
    CHECK_FALSE(result.ok());
    CHECK(test::read_file(target) == "original");
}
