// level/level_catalog.h: the level files of a folder with their names, broken ones with their errors.
#include "core/files.h"
#include "level/level_catalog.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::level;
namespace fs = std::filesystem;

namespace {
std::string tiny_level(const std::string& name) {
    return R"({"format": "killswitch-level", "version": 2, "name": ")" + name +
           R"(", "entities": [{"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [10, 10]}}]})";
}
void write(const fs::path& path, const std::string& text) {
    REQUIRE(files::write_atomic(path, text).ok());
}
} // namespace

TEST_CASE("level catalog: names from the files, errors for broken ones, sorted, skips and limits") {
    test::ScratchDir dir;
    write(dir / "b_second.json", tiny_level("Second level"));
    write(dir / "a_first.json", tiny_level("First level"));
    write(dir / "c_unnamed.json", tiny_level(""));
    write(dir / "d_broken.json", "{\"format\": \"killswitch-level\", \"version\": 2, \"entities\": [}");
    write(dir / "e_skipped.json", tiny_level("Skipped"));
    write(dir / "notes.txt", "not a level");
    fs::create_directories(dir / "sub.json"); // a folder named like a level is not one
    fs::create_directories(dir / "nested");
    write(dir / "nested" / "deep.json", tiny_level("Deep"));

    const LevelFolder listed = list_level_files(dir.path(), {"e_skipped.json"});
    CHECK(listed.exists);
    CHECK(listed.left_out == 0);
    REQUIRE(listed.levels.size() == 4);
    CHECK(listed.levels[0].name == "First level");
    CHECK(listed.levels[0].ok());
    CHECK(listed.levels[0].file == dir / "a_first.json");
    CHECK(listed.levels[1].name == "Second level");
    CHECK(listed.levels[2].name == "c_unnamed"); // no name in the file: its file name
    const LevelFileEntry& broken = listed.levels[3];
    CHECK_FALSE(broken.ok());
    CHECK(broken.name == "d_broken");
    CHECK(broken.error.find((dir / "d_broken.json").string() + ":1:") != std::string::npos);
    CHECK(broken.error.find("JSON syntax error") != std::string::npos);

    const LevelFolder limited = list_level_files(dir.path(), {}, 2);
    CHECK(limited.levels.size() == 2);
    CHECK(limited.left_out == 3);
}

TEST_CASE("level catalog: a missing or empty folder is an empty list, the shipped folder lists its levels") {
    test::ScratchDir dir;
    CHECK_FALSE(list_level_files(dir / "missing").exists);
    CHECK(list_level_files(dir / "missing").levels.empty());
    CHECK(list_level_files({}).levels.empty());
    CHECK(list_level_files(dir.path()).exists);
    CHECK(list_level_files(dir.path()).levels.empty());

    const LevelFolder shipped =
        list_level_files(test::source_dir() / "levels", {"dojo.json", "campaign.json"});
    bool main_found = false;
    for (const LevelFileEntry& entry : shipped.levels) {
        CHECK_MESSAGE(entry.ok(), entry.error);
        CHECK(entry.file.filename() != "dojo.json");
        main_found |= entry.file.filename() == "main.json" && entry.name == "Main level";
    }
    CHECK(main_found);
}
