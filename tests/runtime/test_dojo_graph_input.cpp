// The dojo's graph editor and IK posing driven by real X input (xdotool under Xvfb): a box dragged around two
// of idle's arm keys selects them, Alt+drag scales their times about their centre (one undo step, the other
// keys where they were), Save writes it; a hand dragged with IK on turns its arm and forearm, K keys both.
// Each case edits a scratch copy of robot.json (--dojo-file); the editor reports where its keys, joints and
// buttons are in --status-file, and the test waits on that state, never on time.
#include "anim/clip_io.h"
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
float coord(const json& point, int i) {
    return point[static_cast<std::size_t>(i)].get<float>();
}

const anim::TargetDef* graph_input_target(const anim::PhaseDef& phase, const std::string& node) {
    for (const anim::TargetDef& t : phase.targets)
        if (t.node == node) return &t;
    return nullptr;
}
} // namespace

TEST_CASE("dojo graph input: a box selects two keys, Alt+drag scales their times about their centre in one "
          "undo step, Save writes it") {
    // idle's arm_r z rotation: keys at 0.4 s (10), 0.8 s (0), 1.2 s (-10) and 1.6 s (0).
    test::DojoWindow window("clip=idle,page=curves,node=arm_r,channel=rot.z");
    Session& s = window.session();
    const auto clips = window.clips();
    json st = s.wait("idle's four arm keys on the graph",
                     [](const json& j) { return j.contains("dojo") && j["dojo"]["curve_keys"].size() == 4; });
    const json keys = st["dojo"]["curve_keys"];
    CHECK(st["dojo"]["curve_selected"] == 0);

    // A box dragged from empty space above-left of key 2 to below-right of key 3.
    const float left = coord(keys[1], 0) - 14.0f, right = coord(keys[2], 0) + 14.0f;
    const float top = std::min(coord(keys[1], 1), coord(keys[2], 1)) - 14.0f,
                bottom = std::max(coord(keys[1], 1), coord(keys[2], 1)) + 14.0f;
    REQUIRE(left > coord(keys[0], 0) + 14.0f); // the box starts clear of key 1
    s.drag(json{std::round(left), std::round(top)}, std::round(right - left), std::round(bottom - top), 6);
    st = s.wait("keys 2 and 3 selected by the box",
                [](const json& j) { return j["dojo"]["curve_selected"] == 2; });
    CHECK(st["dojo"]["undo"] == 0); // selecting edits nothing

    // Alt+drag 100 pixels to the right, from between the two keys: their times double about 1 s.
    const json between{std::round((coord(keys[1], 0) + coord(keys[2], 0)) * 0.5f),
                       std::round((coord(keys[1], 1) + coord(keys[2], 1)) * 0.5f) + 20.0f};
    s.focus();
    s.xdo("keydown alt");
    s.wait("Alt seen", [](const json& j) { return j["input"]["alt"] == true; });
    s.drag(between, 100.0f, 0.0f, 5);
    s.xdo("keyup alt");
    st = s.wait("the keys scaled", [](const json& j) { return j["dojo"]["undo"] == 1; });
    st = s.frames(3);
    CHECK(st["dojo"]["undo"] == 1); // the whole drag is one step
    CHECK(st["dojo"]["undo_name"] == "scale 2 keys");
    CHECK(st["dojo"]["curve_selected"] == 2);
    const json moved = st["dojo"]["curve_keys"];
    REQUIRE(moved.size() == 4);
    CHECK(coord(moved[0], 0) == doctest::Approx(coord(keys[0], 0)).epsilon(0.002)); // unselected: unmoved
    CHECK(coord(moved[3], 0) == doctest::Approx(coord(keys[3], 0)).epsilon(0.002));
    CHECK(coord(moved[1], 0) < coord(keys[1], 0) - 20.0f);
    CHECK(coord(moved[2], 0) > coord(keys[2], 0) + 20.0f);

    s.click(st["dojo"]["spots"]["save"]);
    st = s.wait("saved", [](const json& j) { return j["dojo"]["dirty"] == false; });
    auto saved = anim::load_animation_file(clips);
    REQUIRE(saved);
    const anim::ClipDef* idle = saved->find_clip("idle");
    REQUIRE(idle);
    REQUIRE(idle->phases.size() == 4);
    // 0.8 -> 0.6 s and 1.2 -> 1.4 s; keys 1 and 4 stay at 0.4 and 1.6 s; the values are untouched.
    CHECK(idle->phases[0].duration == 0.4);
    CHECK(idle->phases[1].duration == doctest::Approx(0.2));
    CHECK(idle->phases[2].duration == doctest::Approx(0.8));
    CHECK(idle->phases[0].duration + idle->phases[1].duration + idle->phases[2].duration +
              idle->phases[3].duration ==
          doctest::Approx(1.6).epsilon(1e-9));
    const double arm_z[4] = {10, 0, -10, 0};
    for (std::size_t p = 0; p < 4; ++p) {
        const anim::TargetDef* arm = graph_input_target(idle->phases[p], "arm_r");
        REQUIRE(arm);
        CHECK(arm->rot->z == arm_z[p]);
    }
    CHECK_FALSE(idle->frame_rate); // seconds: no frame rate stored
}

TEST_CASE("dojo graph input: the hand dragged with IK on turns the arm and forearm; K keys both") {
    test::DojoWindow window("clip=shoot_pose,time=0.3");
    Session& s = window.session();
    const auto clips = window.clips();
    json st = s.wait("the rig's joints over the preview", [](const json& j) {
        return j.contains("dojo") && j["dojo"]["pose"]["joints"].contains("hand_r") &&
               j["dojo"]["spots"].contains("ik");
    });
    s.click(st["dojo"]["pose"]["joints"]["hand_r"]);
    st = s.wait("hand_r selected", [](const json& j) { return j["dojo"]["pose"]["node"] == "hand_r"; });
    s.click(st["dojo"]["spots"]["ik"]);
    st = s.wait("IK on", [](const json& j) { return j["dojo"]["pose"]["ik"] == true; });
    const json hand = st["dojo"]["pose"]["joints"]["hand_r"];
    const json elbow = st["dojo"]["pose"]["joints"]["forearm_r"];
    // Towards the elbow (always within reach): the arm bends more.
    const float ex = coord(elbow, 0) - coord(hand, 0), ey = coord(elbow, 1) - coord(hand, 1);
    const float reach = std::hypot(ex, ey);
    REQUIRE(reach > 20.0f);
    const float dx = std::round(ex / reach * 18.0f), dy = std::round(ey / reach * 18.0f);
    s.drag(json{std::round(coord(hand, 0)), std::round(coord(hand, 1))}, dx, dy, 6);
    st = s.wait("the arm and forearm turned, not keyed",
                [](const json& j) { return j["dojo"]["pose"]["edits"] == 2; });
    CHECK(st["dojo"]["undo"] == 0);
    st = s.frames(2);
    const json now = st["dojo"]["pose"]["joints"]["hand_r"];
    const float mx = coord(now, 0) - coord(hand, 0), my = coord(now, 1) - coord(hand, 1);
    INFO("the hand moved by (" << mx << ", " << my << ") for a drag of (" << dx << ", " << dy << ")");
    CHECK(std::hypot(mx, my) > 9.0f);                             // it follows the mouse
    CHECK(mx * dx + my * dy > 0.7f * 18.0f * std::hypot(mx, my)); // in the drag's direction
    s.key("k");
    st = s.wait("keyed", [](const json& j) { return j["dojo"]["undo"] == 1; });
    CHECK(st["dojo"]["undo_name"] == "Key 2 nodes at 0.30 s");
    CHECK(st["dojo"]["pose"]["edits"] == 0);

    s.click(st["dojo"]["spots"]["save"]);
    st = s.wait("saved", [](const json& j) { return j["dojo"]["dirty"] == false; });
    auto saved = anim::load_animation_file(clips);
    auto shipped = anim::load_animation_file(test::source_dir() / "assets" / "animations" / "robot.json");
    REQUIRE(saved);
    REQUIRE(shipped);
    const anim::PhaseDef& after = saved->find_clip("shoot_pose")->phases[0];
    const anim::PhaseDef& before = shipped->find_clip("shoot_pose")->phases[0];
    for (const char* node : {"arm_r", "forearm_r"}) {
        const anim::TargetDef* a = graph_input_target(after, node);
        const anim::TargetDef* b = graph_input_target(before, node);
        REQUIRE(a);
        REQUIRE(b);
        CAPTURE(node);
        CHECK(glm::length(*a->rot - *b->rot) > 1.0); // turned by more than a degree
    }
    const anim::TargetDef* hand_key = graph_input_target(after, "hand_r");
    const anim::TargetDef* hand_before = graph_input_target(before, "hand_r");
    REQUIRE(hand_key);
    REQUIRE(hand_before);
    CHECK(*hand_key->rot == *hand_before->rot); // the hand itself is not turned
}
