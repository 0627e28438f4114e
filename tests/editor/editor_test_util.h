#pragma once
// Shared helpers for the editor model tests.
#include "level/entity_shapes.h"
#include "level/level_io.h"
#include "model/autosave.h"
#include "model/edit_entities.h"
#include "model/editor.h"
#include "model/script.h"
#include "test_support.h"
#include "view/view_camera.h"

#include <doctest/doctest.h>

#include <string>

namespace ks::editor_test {

// Brush entity `id`'s brush in the world (level::world_brush), required to exist.
inline brush::Brush world_brush_of(const editor::Editor& ed, int id) {
    auto world = level::world_brush(*ed.level().find(id));
    REQUIRE(world.ok());
    return *world;
}

// How many brush entities the level holds.
inline int brush_count(const editor::Editor& ed) {
    int n = 0;
    for (const level::Entity& e : ed.level().entities) n += e.type() == level::EntityType::Brush;
    return n;
}

inline std::string text_of(const editor::Editor& editor) {
    return level::save_level_string(editor.level());
}

inline level::Level load_shipped(const char* name) {
    auto loaded = level::load_level_file(ks::test::source_dir() / "levels" / name);
    REQUIRE_MESSAGE(loaded.ok(), (loaded.ok() ? std::string() : loaded.error().str()));
    return *loaded;
}

// A small valid level: two rooms joined by a door, a floor, a robot, a pickup and the control panel, whose
// use completes the level's one objective.
inline const char* kTwoRoomScript = R"(# two rooms along z, joined by a door in the wall at z = 0
level_name Two rooms
grid 0.5 15
place floor at 0,0,0 name Ground
set size 20,40
place wall at -10,0,0 yaw 90 name West
set size 40,16,0.5
place wall at 10,0,0 yaw 90 name East
set size 40,16,0.5
place wall at 0,0,20 name South
set size 20,16,0.5
place wall at 0,0,-20 name North
set size 20,16,0.5
place wall at -6.25,0,0 name Door west side
set size 7.5,16,0.5
place wall at 6.25,0,0 name Door east side
set size 7.5,16,0.5
place wall at 0,5,0 name Lintel
set size 5,11,0.5
place door at 0,0,0 name Door
place robot at 3,0,-10 yaw 90
place pickup at -5,0,10
set kind ammo
place pickup at 5,0,10
set kind shield
place control_panel at 0,0,-15 name Panel
player_start 0,0,15
objective add shutdown Shut down the simulation at the control panel
link 13 add on_use shutdown complete
)";

// Ids of kTwoRoomScript's door, robot and control panel.
constexpr int kDoor = 9, kRobot = 10, kPanel = 13;

// The editor after kTwoRoomScript (the test stops if the script fails).
inline editor::Editor two_rooms() {
    editor::Editor ed;
    auto r = editor::run_script_text(kTwoRoomScript, "two_rooms.kss", {}, ed);
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    return ed;
}

// Four walls 1..4 along x, a robot 5 (the groups and layers tests).
inline editor::Editor four_walls() {
    editor::Editor ed;
    for (int i = 0; i < 4; ++i)
        REQUIRE(editor::place(ed, level::EntityType::Wall, Vec3(4.0f * i, 0, 0)).ok());
    REQUIRE(editor::place(ed, level::EntityType::Robot, Vec3(0, 0, 8)).ok());
    return ed;
}

// The viewport size the view and picking tests use.
inline const Vec2 kViewport(960.0f, 540.0f);

// The top view over `centre` in a kViewport-sized view, 60 units across (the picking and drag tests').
inline editor::ViewCamera top_view(Vec3 centre = Vec3(0.0f)) {
    editor::ViewCamera v;
    v.set_viewport(kViewport);
    v.set_view(editor::ViewMode::Top, centre, 60.0f);
    return v;
}

// A visibility filter that shows every entity.
inline bool all_shown(const level::Entity&) {
    return true;
}

// A clock the test moves by hand, for the autosaver's idle timing.
struct FakeClock {
    double now = 1000.0;
    editor::Clock clock() {
        return [this] { return now; };
    }
};

} // namespace ks::editor_test
