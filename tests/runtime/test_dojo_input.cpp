// The dojo panel driven by real X input (xdotool under Xvfb), the way an animator works: New clip typed
// into its dialog, a blend cell Ctrl+clicked and typed, Save; an event added at the playhead, a curve key
// dragged, Save, then the file changed outside the editor and reloaded. Each case edits a scratch copy of
// robot.json (--dojo-file) and checks what was saved; the shipped file is never written. The editor reports
// where its buttons and cells are in --status-file; the test waits on that state, never on time. The last
// case poses the robot's forearm by dragging its gizmo ring in the preview, keyed with K and by auto-key.
#include "anim/clip_io.h"
#include "core/files.h"
#include "model/dojo_clips.h"
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using namespace ks;
using nlohmann::json;
using Session = test::EditorSession;

namespace {
std::filesystem::path shipped_clips() {
    return test::source_dir() / "assets" / "animations" / "robot.json";
}

const anim::BlendPair* find_pair(const anim::AnimationFile& file, const std::string& from,
                                 const std::string& to) {
    for (const auto& pair : file.blends)
        if (pair.from == from && pair.to == to) return &pair;
    return nullptr;
}

bool has_dojo_spot(const json& j, const char* spot) {
    return j.contains("dojo") && j["dojo"]["spots"].contains(spot);
}
} // namespace

TEST_CASE("dojo input: New clip typed into its dialog, a blend cell from idle typed, Save writes both") {
    const auto shipped_before = files::read_text(shipped_clips());
    REQUIRE(shipped_before);
    test::DojoWindow window;
    Session& s = window.session();
    const auto clips = window.clips();
    json st = s.wait("the dojo with its New clip button",
                     [](const json& j) { return has_dojo_spot(j, "new_clip"); });
    CHECK(st["dojo"]["file"] == clips.string());
    const size_t clip_count = st["dojo"]["clips"];

    // New clip: the dialog's name field has the keyboard; the typed name replaces the suggestion.
    s.click(st["dojo"]["spots"]["new_clip"]);
    s.wait("the New clip dialog",
           [](const json& j) { return has_dojo_spot(j, "clip_name") && j["input"]["text_input"]; });
    s.type("wave");
    s.key("Return");
    st = s.wait("the clip created", [&](const json& j) { return j["dojo"]["clips"] == clip_count + 1; });
    CHECK(st["dojo"]["clip"] == "wave"); // the new clip is shown
    CHECK(st["dojo"]["undo"] == 1);
    CHECK(st["dojo"]["dirty"] == true);
    CHECK(st["undo"] == 0); // the level's history is untouched

    // Blends page: Ctrl+click the idle -> wave cell and type a time.
    s.click(st["dojo"]["spots"]["page_blends"]);
    st = s.wait("the blend grid",
                [](const json& j) { return j["dojo"]["blend_cells"].contains("idle>wave"); });
    const json cell = st["dojo"]["blend_cells"]["idle>wave"];
    s.focus();
    s.move_to(cell);
    s.xdo("keydown ctrl");
    s.wait("Ctrl seen", [](const json& j) { return j["input"]["ctrl"] == true; });
    s.xdo("click 1");
    s.frames(2);
    s.xdo("keyup ctrl");
    st = s.wait("the cell taking typed text", [](const json& j) { return j["input"]["text_input"] == true; });
    CHECK(st["dojo"]["transition"] == true); // selecting the cell plays idle -> wave in the tester
    s.key("ctrl+a");
    s.type("0.35");
    s.key("Return");
    st = s.wait("the blend set", [](const json& j) { return j["dojo"]["undo"] == 2; });
    CHECK(st["dojo"]["undo_name"] == "blend idle -> wave");

    // Save, and read the file back.
    s.click(st["dojo"]["spots"]["save"]);
    st = s.wait("saved", [](const json& j) { return j["dojo"]["dirty"] == false; });
    auto saved = anim::load_animation_file(clips);
    REQUIRE(saved);
    const anim::ClipDef* wave = saved->find_clip("wave");
    REQUIRE(wave);
    CHECK(wave->loop == anim::LoopMode::Once);
    CHECK(wave->phases.size() == 1);
    CHECK(wave->phases[0].duration == editor::kNewClipSeconds);
    const anim::BlendPair* pair = find_pair(*saved, "idle", "wave");
    REQUIRE(pair);
    CHECK(pair->time == 0.35);
    CHECK(saved->clips.size() == clip_count + 1);

    // Quitting with unsaved clip edits asks first: Cancel stays, Discard quits without writing.
    s.key("ctrl+z");
    st = s.wait("the blend undone", [](const json& j) { return j["dojo"]["dirty"] == true; });
    for (const char* answer : {"quit_cancel", "quit_discard"}) {
        s.click(st["menu"]["file"]);
        st = s.wait("the File menu", [](const json& j) { return j["menu"]["quit"][0].get<float>() > 0.0f; });
        s.click(st["menu"]["quit"]);
        st = s.wait("the unsaved clip edits question",
                    [&](const json& j) { return has_dojo_spot(j, answer); });
        s.click(st["dojo"]["spots"][answer]);
        if (std::string(answer) == "quit_cancel") {
            st = s.wait("the question answered", [&](const json& j) { return !has_dojo_spot(j, answer); });
            CHECK(st["dojo"]["dirty"] == true); // still running, the edits kept
        }
    }
    CHECK(window.process().wait_exit(60) == 0);
    auto after = anim::load_animation_file(clips);
    REQUIRE(after);
    CHECK(find_pair(*after, "idle", "wave")); // the undone blend was not written
    CHECK(*files::read_text(shipped_clips()) == *shipped_before);
}

TEST_CASE("dojo input: an event added at the playhead, a curve key dragged (one undo step), Save; a change "
          "made outside is noticed and reloaded") {
    test::DojoWindow window("clip=shoot_pose,page=events,node=arm_r,channel=rot.z,time=0.1");
    Session& s = window.session();
    const auto clips = window.clips();
    json st = s.wait("the Events page", [](const json& j) { return has_dojo_spot(j, "add_event"); });
    CHECK(st["dojo"]["clip"] == "shoot_pose");
    CHECK(st["dojo"]["events"] == 0);

    // Add event at the playhead (0.1 s): the name field has the keyboard.
    s.click(st["dojo"]["spots"]["add_event"]);
    s.wait("the Add event popup", [](const json& j) { return j["input"]["text_input"] == true; });
    s.type("footstep");
    s.key("Return");
    st = s.wait("the event added", [](const json& j) { return j["dojo"]["events"] == 1; });
    CHECK(st["dojo"]["undo"] == 1);
    // Its flag on the lane under the timeline, dragged later: one undo step for the whole drag.
    st = s.wait("the event's flag", [](const json& j) { return j["dojo"]["event_flags"].size() == 1; });
    const float flag_x = st["dojo"]["event_flags"][0][0];
    s.drag(st["dojo"]["event_flags"][0], 80.0f, 0.0f);
    st = s.wait("the event moved", [&](const json& j) {
        return j["dojo"]["undo"] == 2 && j["dojo"]["event_flags"].size() == 1 &&
               j["dojo"]["event_flags"][0][0].get<float>() > flag_x + 40.0f;
    });
    CHECK(st["dojo"]["undo_name"] == "move event footstep");
    s.key("ctrl+z"); // back to 0.1 s
    st = s.wait("the move undone", [&](const json& j) { return j["dojo"]["undo"] == 1; });
    CHECK(st["dojo"]["event_flags"][0][0].get<float>() == doctest::Approx(flag_x).epsilon(0.001));

    // Curves page: the shoot pose's one key on arm_r's z rotation (60 degrees, absolute), dragged up.
    s.click(st["dojo"]["spots"]["page_curves"]);
    st = s.wait("the curve's key handles", [](const json& j) { return !j["dojo"]["curve_keys"].empty(); });
    REQUIRE(st["dojo"]["curve_keys"].size() == 1);
    s.drag(st["dojo"]["curve_keys"][0], 0.0f, -40.0f);
    st = s.wait("the key dragged", [](const json& j) { return j["dojo"]["undo"] == 2; });
    st = s.frames(3);
    CHECK(st["dojo"]["undo"] == 2); // the whole drag is one step
    CHECK(st["dojo"]["undo_name"].get<std::string>().find("drag key 1 of") == 0);

    // Ctrl+C copies the shown key, Ctrl+Shift+V pastes it mirrored (one undo step); undone before saving.
    s.key("ctrl+c");
    s.key("ctrl+shift+v");
    st = s.wait("the key pasted mirrored", [](const json& j) { return j["dojo"]["undo"] == 3; });
    CHECK(st["dojo"]["undo_name"] == "paste mirrored");
    s.key("ctrl+z");
    st = s.wait("the paste undone", [](const json& j) { return j["dojo"]["undo"] == 2; });

    s.click(st["dojo"]["spots"]["save"]);
    st = s.wait("saved", [](const json& j) { return j["dojo"]["dirty"] == false; });
    auto saved = anim::load_animation_file(clips);
    REQUIRE(saved);
    const anim::ClipDef* pose = saved->find_clip("shoot_pose");
    REQUIRE(pose);
    REQUIRE(pose->events.size() == 1);
    CHECK(pose->events[0].name == "footstep");
    CHECK(pose->events[0].time == 0.1);
    const auto arm = std::find_if(pose->phases[0].targets.begin(), pose->phases[0].targets.end(),
                                  [](const anim::TargetDef& t) { return t.node == "arm_r"; });
    REQUIRE(arm != pose->phases[0].targets.end());
    REQUIRE(arm->rot);
    CHECK(arm->rot->z > 62.0);  // dragged up from 60
    CHECK(arm->rot->y == 22.5); // the other axes untouched
    // A vertical drag moves the value only: the key's time is exactly where it was.
    const auto shipped = anim::load_animation_file(shipped_clips());
    REQUIRE(shipped);
    CHECK(pose->phases[0].duration == shipped->find_clip("shoot_pose")->phases[0].duration);

    // Outside the editor: a clip added to the file. The dojo notices, and Reload reads it.
    {
        auto file = anim::load_animation_file(clips);
        REQUIRE(file);
        REQUIRE(editor::new_clip(*file, "outside"));
        REQUIRE(anim::save_animation_file(clips, *file));
    }
    const size_t before = st["dojo"]["clips"];
    st = s.wait("the outside change noticed",
                [](const json& j) { return j["dojo"]["changed_on_disk"] == true; });
    REQUIRE(has_dojo_spot(st, "reload_notice"));
    s.click(st["dojo"]["spots"]["reload_notice"]);
    st = s.wait("reloaded", [&](const json& j) { return j["dojo"]["clips"] == before + 1; });
    CHECK(st["dojo"]["changed_on_disk"] == false);
    CHECK(st["dojo"]["undo"] == 0); // a reload starts a fresh history
}

TEST_CASE("dojo input: a joint clicked in the preview, its gizmo ring dragged, K keys it; auto-key makes a "
          "drag one undo step") {
    test::DojoWindow window("clip=shoot_pose,time=0.3");
    Session& s = window.session();
    const auto clips = window.clips();
    json st = s.wait("the rig's joints over the preview", [](const json& j) {
        return j.contains("dojo") && j["dojo"]["pose"]["joints"].contains("forearm_r");
    });
    s.click(st["dojo"]["pose"]["joints"]["forearm_r"]);
    st = s.wait("forearm_r selected, its rings drawn", [](const json& j) {
        return j["dojo"]["pose"]["node"] == "forearm_r" &&
               j["dojo"]["pose"]["rings"][2][0].get<float>() > 0.0f;
    });
    // Along ring z's tangent at its outermost point: a turn about the forearm's own z.
    const json ring = st["dojo"]["pose"]["rings"][2];
    const json joint = st["dojo"]["pose"]["joints"]["forearm_r"];
    const float rx = ring[0].get<float>() - joint[0].get<float>(),
                ry = ring[1].get<float>() - joint[1].get<float>();
    const float len = std::sqrt(rx * rx + ry * ry);
    REQUIRE(len > 10.0f);
    s.drag(ring, -ry / len * 40.0f, rx / len * 40.0f);
    st = s.wait("the forearm turned, not keyed",
                [](const json& j) { return j["dojo"]["pose"]["edits"] == 1; });
    CHECK(st["dojo"]["undo"] == 0);
    s.key("k");
    st = s.wait("keyed", [](const json& j) { return j["dojo"]["undo"] == 1; });
    CHECK(st["dojo"]["undo_name"] == "Key forearm_r at 0.30 s");
    CHECK(st["dojo"]["phases"] == 1); // on the clip's key: no key added

    s.click(st["dojo"]["spots"]["auto_key"]);
    st = s.wait("auto-key on", [](const json& j) { return j["dojo"]["pose"]["auto_key"] == true; });
    s.drag(st["dojo"]["pose"]["rings"][2], ry / len * 40.0f, -rx / len * 40.0f, 8);
    st = s.wait("the drag keyed", [](const json& j) { return j["dojo"]["undo"] == 2; });
    st = s.frames(3);
    CHECK(st["dojo"]["undo"] == 2);                       // the whole drag is one step
    CHECK(st["dojo"]["undo_name"] == "Rotate forearm_r"); // undoing it: tests/editor/test_dojo_pose.cpp
}
