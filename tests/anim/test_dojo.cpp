#include "anim/dojo.h"
#include "anim/rotation.h"
#include "anim_test_support.h"

#include <doctest/doctest.h>

using namespace ks::anim;
using ks::anim::test::robot_library;

TEST_CASE("Dojo keys 1-5 play the reference clips, 0 resets, and the legend shows what plays") {
    const AnimationLibrary& lib = robot_library();
    auto dojo = DojoController::create(lib.clips, lib.rig, reference_dojo_clips());
    REQUIRE(dojo.ok());
    CHECK(dojo->legend().back() == "playing: (rest pose)");
    const char* expected[] = {"alert", "shoot_pose", "shooting", "shoot_pose_reverse", "death"};
    for (int i = 0; i < 5; ++i) {
        CHECK(dojo->press(static_cast<char>('1' + i)));
        CHECK(dojo->player().current_clip() == lib.clips.find(expected[i]));
        const ks::anim::Pose before = dojo->pose();
        dojo->advance(0.03);
        CHECK(dojo->legend()[static_cast<std::size_t>(i)] ==
              std::string(1, static_cast<char>('1' + i)) + "  " + expected[i]);
        CHECK(dojo->legend().back() == std::string("playing: ") + expected[i] + "  0.03 s  (blending)");
        (void)before;
    }
    CHECK_FALSE(dojo->press('7'));
    CHECK_FALSE(dojo->press('x'));
    CHECK(dojo->player().current_clip() == lib.clips.find("death"));
    dojo->advance(3.0);
    CHECK(dojo->legend().back() == "playing: death  3.03 s");
    CHECK(dojo->press('0'));
    ks::anim::Pose rest;
    rest.set_rest(lib.rig);
    for (int n = 0; n < rest.size(); ++n)
        CHECK(angle_between(dojo->pose().rotation[n], rest.rotation[n]) < 1e-6f);
}

TEST_CASE("Dojo bindings naming missing clips are refused with the list of known ones") {
    const AnimationLibrary& lib = robot_library();
    auto dojo = DojoController::create(lib.clips, lib.rig, {"alert", "dance"}, "sleep");
    REQUIRE_FALSE(dojo.ok());
    CHECK(dojo.error().str().find("'dance', 'sleep'") != std::string::npos);
    CHECK(dojo.error().str().find("known clips: idle, alert") != std::string::npos);
    CHECK_FALSE(DojoController::create(lib.clips, lib.rig, std::vector<std::string>(10, "alert")).ok());
}
