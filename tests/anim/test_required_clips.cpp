// The robot's required clips: one list (anim/required_clips.h), present in the shipped file, and a missing
// one reported by check_required_clips naming every missing clip.
#include "anim/dojo.h"
#include "anim/required_clips.h"
#include "anim_test_support.h"

#include <doctest/doctest.h>

#include <set>
#include <string>

using namespace ks;
using namespace ks::anim;
using ks::anim::test::robot_library;

TEST_CASE("required robot clips: unique names with a reason each, all in the shipped file, the Dojo's among "
          "them") {
    std::set<std::string> names;
    for (const RequiredClip& r : required_robot_clips()) {
        INFO(r.name);
        CHECK(names.insert(r.name).second);
        CHECK(std::string(r.reason).find(std::string("'") + r.name + "'") != std::string::npos);
        CHECK(robot_library().file.find_clip(r.name) != nullptr);
        CHECK(find_required_clip(r.name) == &r);
    }
    CHECK(names.size() == 7);
    CHECK(find_required_clip("wave") == nullptr);
    CHECK(std::string(find_required_clip("death")->reason) == "the game plays 'death' when a robot dies");
    for (const std::string& dojo_clip : reference_dojo_clips()) CHECK(names.count(dojo_clip) == 1);
    CHECK(names.count("reset") == 1); // the Dojo's key 0
    CHECK(check_required_clips(robot_library().file).empty());
}

TEST_CASE("check_required_clips lists every missing required clip in one issue; validate() stays generic") {
    AnimationFile file = robot_library().file;
    auto drop = [&](const std::string& name) {
        std::erase_if(file.clips, [&](const ClipDef& c) { return c.name == name; });
        std::erase_if(file.blends, [&](const BlendPair& p) { return p.from == name || p.to == name; });
    };
    drop("death");
    auto issues = check_required_clips(file);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].path.str() == "clips");
    CHECK(issues[0].message == "the robot's required clip 'death' is missing");
    CHECK(issues[0].hint.find("idle, alert, shoot_pose, shooting, shoot_pose_reverse, death, reset") !=
          std::string::npos);

    drop("reset");
    issues = check_required_clips(file);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message == "the robot's required clips 'death', 'reset' are missing");
    // The loader's own checks know nothing of the robot: any animation file may lack these names.
    CHECK(validate(file).empty());
}
