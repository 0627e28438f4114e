// The dojo's blend table (default, cells, wildcard fallback, the effective grid against the compiled clips)
// and clip events (add, move, rename, sound, remove; kept sorted; refusals leave the file unchanged).
#include "dojo_test_util.h"
#include "model/dojo_clips.h"

#include <algorithm>
#include <cmath>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::index_of;
using ks::dojo_test::shipped_clips;
using ks::dojo_test::text;

namespace {

// Every cell of the grid is the time anim::compile gives the game for that pair.
void grid_matches_compiled(const anim::AnimationFile& file) {
    auto rig = anim::build_rig(file);
    REQUIRE(rig.ok());
    auto clips = anim::compile(file, *rig);
    REQUIRE(clips.ok());
    const BlendGrid grid = blend_grid(file);
    REQUIRE(grid.clips.size() == file.clips.size());
    for (std::size_t f = 0; f < grid.clips.size(); ++f)
        for (std::size_t t = 0; t < grid.clips.size(); ++t) {
            INFO(grid.clips[f] << " -> " << grid.clips[t]);
            CHECK(static_cast<float>(grid.at(f, t).seconds) ==
                  clips->blend_time(static_cast<int>(f), static_cast<int>(t)));
        }
}

template <class Edit>
void refused_blend(anim::AnimationFile& file, Edit&& edit, const std::string& expected) {
    const std::string before = text(file);
    auto result = edit();
    REQUIRE_FALSE(result.ok());
    INFO(result.error().str());
    CHECK(result.error().str().find(expected) != std::string::npos);
    CHECK(text(file) == before);
}

} // namespace

TEST_CASE("dojo blends: the grid shows each pair's time and where it comes from, as the game compiles it") {
    anim::AnimationFile file = shipped_clips();
    file.default_blend = 0.12;
    file.blends = {
        {"*", "reset", 0}, {"idle", "alert", 0.08}, {"shooting", "*", 0.3}, {"shooting", "reset", 0.5}};
    const BlendGrid grid = blend_grid(file);
    const std::size_t idle = index_of(file, "idle"), alert = index_of(file, "alert"),
                      reset = index_of(file, "reset"), shooting = index_of(file, "shooting");
    CHECK(grid.default_seconds == 0.12);
    CHECK(grid.at(idle, alert).seconds == 0.08);
    CHECK(grid.at(idle, alert).source == BlendCell::Source::Explicit);
    CHECK(grid.at(alert, idle).seconds == 0.12);
    CHECK(grid.at(alert, idle).source == BlendCell::Source::Default);
    CHECK(grid.at(alert, reset).source == BlendCell::Source::Wildcard);
    CHECK(grid.at(shooting, idle).seconds == 0.3);
    // Both wildcards reach shooting -> reset, but the pair naming both clips wins.
    CHECK(grid.at(shooting, reset).seconds == 0.5);
    CHECK(grid.at(shooting, reset).source == BlendCell::Source::Explicit);
    grid_matches_compiled(file);
}

TEST_CASE("dojo blends: set, update and clear cells and the default; a cleared cell falls back") {
    anim::AnimationFile file = shipped_clips();
    const std::size_t alert = index_of(file, "alert"), idle = index_of(file, "idle");
    REQUIRE(set_default_blend(file, 0.2));
    CHECK(blend_grid(file).at(alert, idle).seconds == 0.2);
    const std::size_t pairs = file.blends.size();
    REQUIRE(set_blend(file, "alert", "idle", 0.3));
    CHECK(file.blends.size() == pairs + 1);
    REQUIRE(set_blend(file, "alert", "idle", 0.4)); // updates the same pair
    CHECK(file.blends.size() == pairs + 1);
    CHECK(blend_grid(file).at(alert, idle).seconds == 0.4);
    REQUIRE(set_blend(file, "*", "idle", 0.7));
    grid_matches_compiled(file);

    REQUIRE(clear_blend(file, "alert", "idle"));
    CHECK(blend_grid(file).at(alert, idle).seconds == 0.7); // the wildcard now
    CHECK(blend_grid(file).at(alert, idle).source == BlendCell::Source::Wildcard);
    refused_blend(
        file, [&] { return clear_blend(file, "alert", "idle"); }, "comes from a pair with *");
    REQUIRE(clear_blend(file, "*", "idle"));
    CHECK(blend_grid(file).at(alert, idle).source == BlendCell::Source::Default);
    refused_blend(
        file, [&] { return clear_blend(file, "alert", "idle"); }, "uses the default blend (0.2 s)");

    // Duplicate pairs (a hand-edited file) collapse to one when the cell is set.
    file.blends.push_back({"alert", "idle", 1});
    file.blends.push_back({"alert", "idle", 2});
    REQUIRE(set_blend(file, "alert", "idle", 0.5));
    CHECK(std::count_if(file.blends.begin(), file.blends.end(),
                        [](const anim::BlendPair& p) { return p.from == "alert" && p.to == "idle"; }) == 1);
    CHECK(dojo_file_issues(file).empty());
    grid_matches_compiled(file);

    refused_blend(
        file, [&] { return set_blend(file, "alert", "idle", -0.1); }, "blend time -0.1 s is out of range");
    refused_blend(
        file, [&] { return set_blend(file, "alert", "idle", std::nan("")); }, "out of range");
    refused_blend(
        file, [&] { return set_blend(file, "alert", "idle", 10.5); }, "seconds in [0, 10 s]");
    refused_blend(
        file, [&] { return set_blend(file, "alrt", "idle", 0.1); }, "did you mean 'alert'?");
    refused_blend(
        file, [&] { return set_default_blend(file, INFINITY); }, "out of range");
    CHECK(set_blend(file, "alert", "idle", 0).ok()); // a cut is allowed
    CHECK(set_blend(file, "alert", "idle", kMaxBlendSeconds).ok());
}

TEST_CASE("dojo events: added, moved, renamed, re-sounded and removed; always sorted; clamped moves") {
    anim::AnimationFile file = shipped_clips();
    const std::size_t pose = index_of(file, "shoot_pose");
    const double length = file.clips[pose].duration();
    REQUIRE(length == 0.3);
    auto b = add_event(file, pose, 0.2, "b");
    REQUIRE(b.ok());
    CHECK(*b == 0);
    auto a = add_event(file, pose, 0.1, "a");
    REQUIRE(a.ok());
    CHECK(*a == 0);
    auto c = add_event(file, pose, 0.2, "c", "robot_shot"); // after the event at the same time
    REQUIRE(c.ok());
    CHECK(*c == 2);
    auto names = [&] {
        std::string s;
        for (const anim::ClipEvent& e : file.clips[pose].events) s += e.name;
        return s;
    };
    CHECK(names() == "abc");
    CHECK(file.clips[pose].events[2].sound == "robot_shot");
    CHECK(dojo_file_issues(file).empty());

    auto moved = move_event(file, pose, 0, 5.0); // past the end: stops at it
    REQUIRE(moved.ok());
    CHECK(*moved == 2);
    CHECK(file.clips[pose].events[2].time == length);
    CHECK(names() == "bca");
    moved = move_event(file, pose, 2, -1.0);
    REQUIRE(moved.ok());
    CHECK(*moved == 0);
    CHECK(file.clips[pose].events[0].time == 0);
    REQUIRE(rename_event(file, pose, 0, "flash"));
    REQUIRE(set_event_sound(file, pose, 0, "robot_shot"));
    REQUIRE(set_event_sound(file, pose, 2, ""));
    CHECK(file.clips[pose].events[0].name == "flash");
    CHECK(file.clips[pose].events[0].sound == "robot_shot");
    CHECK(file.clips[pose].events[2].sound.empty());
    REQUIRE(remove_event(file, pose, 1));
    CHECK(names() == "flashc");
    CHECK(dojo_file_issues(file).empty());

    refused_blend(
        file, [&] { return add_event(file, pose, 0.31, "late"); }, "event time 0.31 s is outside clip");
    refused_blend(
        file, [&] { return add_event(file, pose, -0.1, "early"); }, "a time in [0, 0.3 s]");
    refused_blend(
        file, [&] { return add_event(file, pose, 0.1, ""); }, "an event needs a name");
    refused_blend(
        file, [&] { return add_event(file, pose, 0.1, "x", "Robot Shot"); }, "other than a-z, 0-9 and _");
    refused_blend(
        file, [&] { return rename_event(file, pose, 0, ""); }, "an event needs a name");
    refused_blend(
        file, [&] { return set_event_sound(file, pose, 0, "shot.wav"); }, "without its .wav");
    refused_blend(
        file, [&] { return remove_event(file, pose, 2); }, "has no event 3");
    refused_blend(
        file, [&] { return move_event(file, pose, 0, std::nan("")); }, "not a number");
    refused_blend(
        file, [&] { return add_event(file, 99, 0.1, "x"); }, "clip 99 does not exist");
}

TEST_CASE("dojo events: a hand-written file's unsorted events come out sorted after an edit") {
    anim::AnimationFile file = dojo_test::nod_file();
    file.clips[0].events = {{0.8, "z", ""}, {0.1, "y", ""}, {0.5, "x", ""}};
    auto added = add_event(file, 0, 0.3, "w");
    REQUIRE(added.ok());
    CHECK(*added == 1);
    std::string order;
    for (const anim::ClipEvent& e : file.clips[0].events) order += e.name;
    CHECK(order == "ywxz");
}

TEST_CASE("the blend grid's column headers: whole names that fit, start.end cuts, row numbers for clashes") {
    const std::vector<std::string> names = {
        "idle", "walk", "shoot_pose", "shoot_pose_reverse", "alert", "patrol_left_arm", "patrol_right_arm"};
    const std::vector<std::string> at8 = short_clip_labels(names, 8);
    CHECK(at8 == std::vector<std::string>{"idle", "walk", "shoo.ose", "shoo.rse", "alert", "#6", "#7"});
    for (const std::string& label : at8) CHECK(label.size() <= 8);
    // Wide enough for every name: all whole.
    CHECK(short_clip_labels(names, 40) == names);
    // Narrower than 3 is taken as 3; equal cuts of different names never stay equal.
    const std::vector<std::string> at1 = short_clip_labels({"alpha", "aroma", "beta"}, 1);
    CHECK(at1 == std::vector<std::string>{"#1", "#2", "b.a"});
    CHECK(short_clip_labels({}, 8).empty());
}
