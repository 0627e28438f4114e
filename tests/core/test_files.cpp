#include "core/files.h"
#include "hardening/fault_support.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <filesystem>
#include <unistd.h>
#include <vector>

using namespace ks;
namespace fs = std::filesystem;

namespace {
int leftover_temp_files(const fs::path& dir) {
    int n = 0;
    for (auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++n;
    return n;
}
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

    for (files::Fault fault :
         {files::Fault::OpenTemp, files::Fault::ShortWrite, files::Fault::BeforeRename}) {
        CAPTURE(static_cast<int>(fault));
        const hardening::FaultGuard guard(fault);
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

TEST_CASE("files::list: the regular files with a name ending, sorted; links followed; never throws") {
    test::ScratchDir dir;
    for (const char* name : {"b.json", "a.json", ".json", "notes.txt", "a.json.txt", "wall_basecolor.png"})
        REQUIRE(files::write_atomic(dir / name, "{}").ok());
    fs::create_directory(dir / "folder.json");             // a folder, not a file
    fs::create_symlink(dir / "a.json", dir / "link.json"); // a link to a file counts
    fs::create_symlink(dir / "gone", dir / "dangling.json");

    auto json = files::list(dir.path(), ".json");
    REQUIRE(json.ok());
    CHECK(*json == std::vector<fs::path>{dir / "a.json", dir / "b.json", dir / "link.json"});
    auto textures = files::list(dir.path(), "_basecolor.png");
    REQUIRE(textures.ok());
    CHECK(*textures == std::vector<fs::path>{dir / "wall_basecolor.png"});
    auto none = files::list(dir.path(), ".wav");
    REQUIRE(none.ok());
    CHECK(none->empty());

    for (const fs::path& not_a_folder : {dir / "missing", dir / "a.json", fs::path()}) {
        CAPTURE(not_a_folder);
        Result<std::vector<fs::path>> listed = Error("not called");
        CHECK_NOTHROW(listed = files::list(not_a_folder, ".json"));
        REQUIRE_FALSE(listed.ok());
        CHECK(listed.error().message.starts_with("cannot list the folder: "));
        CHECK(listed.error().where.file == not_a_folder.string());
        CHECK(listed.value_or(std::vector<fs::path>{}).empty());
    }
}

TEST_CASE("files::list skips entries it cannot examine instead of throwing") {
    if (::geteuid() == 0) {
        MESSAGE("running as root: folder permissions do not apply");
        return;
    }
    test::ScratchDir dir;
    REQUIRE(fs::create_directory(dir / "sealed"));
    REQUIRE(files::write_atomic(dir / "sealed" / "a.wav", "RIFF").ok());
    fs::create_symlink("a.wav", dir / "sealed" / "link.wav");
    // Readable but not searchable: the names and their types can be read, but what a link points to cannot
    // be examined (std::filesystem's throwing overloads throw there).
    fs::permissions(dir / "sealed", fs::perms::owner_read);
    Result<std::vector<fs::path>> listed = Error("not called");
    CHECK_NOTHROW(listed = files::list(dir / "sealed", ".wav"));
    fs::permissions(dir / "sealed", fs::perms::owner_all);
    REQUIRE(listed.ok());
    CHECK(*listed == std::vector<fs::path>{dir / "sealed" / "a.wav"});
}
