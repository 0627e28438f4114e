// The editor's navigation-mesh preview: built in the background from a copy of the level, the newest
// revision wins, and a level the mesh cannot be built for shows the build's message instead of a mesh.
#include "level/level.h"
#include "level/level_io.h"
#include "model/nav_preview.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <chrono>
#include <thread>

using namespace ks;
using namespace ks::editor;

namespace {

level::Level room() {
    level::Level lv;
    auto& floor = lv.add(level::EntityType::Floor, Vec3(0.0f), "floor");
    floor.as<level::FloorProps>().size = Vec2(30.0f, 30.0f);
    return lv;
}

// Polls like the editor's frame loop until the preview shows `revision`'s build.
void poll_until_shown(NavPreview& preview, const level::Level& level, std::uint64_t revision) {
    for (int i = 0; i < 2000; ++i) {
        preview.update(level, revision);
        if (!preview.building() && preview.stats().builds > 0) {
            preview.update(level, revision); // starts nothing when this revision is the shown one
            if (!preview.building()) return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    FAIL("the preview never finished building");
}

} // namespace

TEST_CASE("the preview builds the robots' mesh in the background and shows its triangles") {
    NavPreview preview;
    const level::Level lv = room();
    CHECK(preview.triangles().empty());
    preview.update(lv, 1);
    CHECK(preview.building());
    poll_until_shown(preview, lv, 1);
    CHECK(preview.error().empty());
    CHECK(preview.triangles().size() >= 2);
    CHECK(preview.stats().builds == 1);
    CHECK(preview.stats().last_build_ms > 0.0);
    preview.update(lv, 1); // same revision: nothing to do
    CHECK_FALSE(preview.building());
}

TEST_CASE("an edit during a build is built next; the newest revision is the one shown") {
    NavPreview preview;
    level::Level lv = room();
    preview.update(lv, 1);
    auto& wall = lv.add(level::EntityType::Wall, Vec3(0.0f), "wall"); // splits the room
    wall.as<level::WallProps>().size = Vec3(30.0f, 16.0f, 1.0f);
    preview.update(lv, 2);
    preview.finish(); // revision 1's build
    CHECK(preview.stats().builds == 1);
    const std::size_t before = preview.triangles().size();
    poll_until_shown(preview, lv, 2);
    CHECK(preview.stats().builds == 2);
    CHECK(preview.triangles().size() != before);
}

TEST_CASE("a level without a floor shows the build's message, and the main level shows its doors") {
    NavPreview preview;
    level::Level empty;
    preview.update(empty, 7);
    preview.finish();
    CHECK(preview.triangles().empty());
    CHECK_FALSE(preview.error().empty());

    auto main_level = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE(main_level);
    preview.update(*main_level, 8);
    preview.finish();
    CHECK(preview.error().empty());
    CHECK(preview.stats().door_triangles > 0);
}
