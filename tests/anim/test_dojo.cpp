#include "anim/dojo.h"
#include "anim/rotation.h"
#include "anim_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

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

namespace {
// The root node's rotation against the rig's rest (radians).
float root_tilt(const DojoController& dojo, const ks::anim::Rig& rig) {
    ks::anim::Pose rest;
    rest.set_rest(rig);
    const int root = rig.find("robot");
    return angle_between(dojo.pose().rotation[static_cast<std::size_t>(root)],
                         rest.rotation[static_cast<std::size_t>(root)]);
}
} // namespace

// The reference's test robot snaps its root back before every animation: the death clip's spin and tip-over
// are relative to the root, so without that the robot stayed tipped over for keys 1-4 and a second 5
// tipped it further.
TEST_CASE("Dojo: each key starts with the root at rest; death after death tips over the same way") {
    const AnimationLibrary& lib = robot_library();
    auto dojo = DojoController::create(lib.clips, lib.rig, reference_dojo_clips());
    REQUIRE(dojo.ok());
    const int root = lib.rig.find("robot");
    REQUIRE(root >= 0);
    REQUIRE(dojo->press('5'));
    dojo->advance(3.0);
    const float tipped = root_tilt(*dojo, lib.rig);
    CHECK(tipped == doctest::Approx(0.95 * 3.14159265 / 2).epsilon(1e-4)); // the death clip's tip-over
    const ks::Quat first_death = dojo->pose().rotation[static_cast<std::size_t>(root)];
    for (char key : {'1', '2', '3', '4'}) {
        CAPTURE(key);
        REQUIRE(dojo->press(key));
        dojo->advance(2.0);
        CHECK(root_tilt(*dojo, lib.rig) < 1e-5f); // standing upright again
        REQUIRE(dojo->press('5'));
        dojo->advance(3.0);
        CHECK(angle_between(dojo->pose().rotation[static_cast<std::size_t>(root)], first_death) < 1e-5f);
    }
    // Death straight after death: the same fall, not a further tip.
    REQUIRE(dojo->press('5'));
    dojo->advance(3.0);
    CHECK(angle_between(dojo->pose().rotation[static_cast<std::size_t>(root)], first_death) < 1e-5f);
}

TEST_CASE("Dojo: key 3 plays the shooting clip once and holds the shoot pose; the arms do not snap home") {
    const AnimationLibrary& lib = robot_library();
    auto dojo = DojoController::create(lib.clips, lib.rig, reference_dojo_clips());
    REQUIRE(dojo.ok());
    const auto arm = static_cast<std::size_t>(lib.rig.find("arm_r"));
    const auto chest = static_cast<std::size_t>(lib.rig.find("chest"));
    REQUIRE(dojo->press('2'));
    dojo->advance(1.0);
    const ks::Quat aimed_arm = dojo->pose().rotation[arm];
    REQUIRE(dojo->press('3'));
    // Only the root is anchored: the raised arm starts the recoil where it was.
    CHECK(angle_between(dojo->pose().rotation[arm], aimed_arm) < 1e-6f);
    dojo->advance(0.2); // the recoil's peak: the chest leans 30 degrees
    CHECK(dojo->pose().euler[chest].z == doctest::Approx(ks::radians(30.0f)).epsilon(0.05));
    dojo->advance(0.4);
    CHECK(dojo->player().finished());
    const ks::anim::Pose held = dojo->pose();
    CHECK(std::abs(held.euler[chest].z) < 1e-5f);
    CHECK(angle_between(held.rotation[arm], aimed_arm) < 1e-5f);
    // Held, not looped: no second recoil later on.
    for (int i = 0; i < 40; ++i) {
        dojo->advance(0.05);
        CHECK(std::abs(dojo->pose().euler[chest].z) < 1e-5f);
    }
    CHECK(dojo->legend().back() == "playing: shooting  2.60 s");
}

namespace {
// The shipped file plus `extra` copies of the alert clip named extra_1, extra_2, ... (each turning the
// right arm a different way), compiled for the file's rig.
struct ExtendedClips {
    AnimationFile file;
    ks::anim::Rig rig;
    ClipSet clips;
};
ExtendedClips extended_clips(int extra) {
    ExtendedClips out{robot_library().file, robot_library().rig, {}};
    for (int i = 1; i <= extra; ++i) {
        ClipDef clip;
        clip.name = "extra_" + std::to_string(i);
        PhaseDef phase;
        phase.duration = 0.25;
        TargetDef arm;
        arm.node = "arm_r";
        arm.rot = ks::DVec3(20.0 * i, 0, 0);
        phase.targets.push_back(arm);
        clip.phases.push_back(phase);
        out.file.clips.push_back(clip);
    }
    auto compiled = compile(out.file, out.rig);
    REQUIRE_MESSAGE(compiled, (compiled ? std::string() : compiled.error().str()));
    out.clips = std::move(*compiled);
    return out;
}
} // namespace

TEST_CASE("Dojo: the file's other clips get keys 6-9 in file order, the rest are listed and playable") {
    const ExtendedClips set = extended_clips(6);
    const auto keys = dojo_key_clips(set.clips);
    CHECK(keys == std::vector<std::string>{"alert", "shoot_pose", "shooting", "shoot_pose_reverse", "death",
                                           "idle", "extra_1", "extra_2", "extra_3"});
    auto dojo = DojoController::create(set.clips, set.rig, keys);
    REQUIRE(dojo.ok());
    const std::vector<std::string> expected = {"1  alert",    "2  shoot_pose",
                                               "3  shooting", "4  shoot_pose_reverse",
                                               "5  death",    "6  idle",
                                               "7  extra_1",  "8  extra_2",
                                               "9  extra_3",  "   extra_4",
                                               "   extra_5",  "   extra_6",
                                               "0  reset",    "playing: (rest pose)"};
    CHECK(dojo->legend() == expected);
    REQUIRE(dojo->entries().size() == set.clips.clips.size()); // every clip once
    CHECK(dojo->playing_entry() == -1);

    const auto arm = static_cast<std::size_t>(set.rig.find("arm_r"));
    REQUIRE(dojo->press('9'));
    dojo->advance(1.0);
    CHECK(dojo->pose().euler[arm].x == doctest::Approx(ks::radians(60.0f)));
    CHECK(dojo->playing_entry() == 8);
    // A clip without a key: started from the list.
    REQUIRE(dojo->play_entry(11));
    CHECK(dojo->entries()[11].clip == "extra_6");
    dojo->advance(1.0);
    CHECK(dojo->pose().euler[arm].x == doctest::Approx(ks::radians(120.0f)));
    CHECK(dojo->playing_entry() == 11);
    CHECK(dojo->legend().back() == "playing: extra_6  1.00 s");
    CHECK_FALSE(dojo->play_entry(dojo->entries().size()));
    CHECK_FALSE(dojo->press('\0')); // "no key" is not a key
    REQUIRE(dojo->press('0'));
    CHECK(dojo->playing_entry() == 12);
    CHECK(std::abs(dojo->pose().euler[arm].x) < 1e-6f);

    // The shipped file: 1-5 the reference, 6 idle, nothing past it.
    const auto shipped = dojo_key_clips(robot_library().clips);
    CHECK(shipped ==
          std::vector<std::string>{"alert", "shoot_pose", "shooting", "shoot_pose_reverse", "death", "idle"});
}

TEST_CASE("Dojo: a file without one of the reference clips is refused, naming it") {
    ExtendedClips set{robot_library().file, robot_library().rig, {}};
    std::erase_if(set.file.clips, [](const ClipDef& c) { return c.name == "shoot_pose_reverse"; });
    auto compiled = compile(set.file, set.rig);
    REQUIRE(compiled);
    auto dojo = DojoController::create(*compiled, set.rig, dojo_key_clips(*compiled));
    REQUIRE_FALSE(dojo.ok());
    CHECK(dojo.error().str().find("'shoot_pose_reverse'") != std::string::npos);
}

TEST_CASE("Dojo: anchoring the root leaves the other channels, the blend table and the events alone") {
    const AnimationLibrary& lib = robot_library();
    const ClipSet anchored = anchor_root_to_rest(lib.clips, lib.rig);
    REQUIRE(anchored.clips.size() == lib.clips.clips.size());
    const int root = lib.rig.find("robot");
    for (std::size_t c = 0; c < anchored.clips.size(); ++c) {
        const Clip &a = anchored.clips[c], &b = lib.clips.clips[c];
        CAPTURE(a.name);
        CHECK(a.events == b.events);
        CHECK(a.duration == b.duration);
        for (std::size_t d = 0; d < anchored.clips.size(); ++d)
            CHECK(anchored.blend_time(static_cast<int>(c), static_cast<int>(d)) ==
                  lib.clips.blend_time(static_cast<int>(c), static_cast<int>(d)));
        // Every root channel (rotation and position) is there, with absolute keys only.
        int root_channels = 0;
        for (const Channel& ch : a.channels) {
            if (ch.node != root) continue;
            ++root_channels;
            for (std::uint32_t k = 0; k < ch.key_count; ++k)
                CHECK(a.keys[ch.first_key + k].mode == KeyMode::Absolute);
        }
        CHECK(root_channels == 2);
        // The other channels are untouched.
        for (const Channel& ch : b.channels) {
            if (ch.node == root) continue;
            const auto same = std::find_if(a.channels.begin(), a.channels.end(), [&](const Channel& o) {
                return o.node == ch.node && o.is_position == ch.is_position;
            });
            REQUIRE(same != a.channels.end());
            REQUIRE(same->key_count == ch.key_count);
            for (std::uint32_t k = 0; k < ch.key_count; ++k) {
                CHECK(a.keys[same->first_key + k].mode == b.keys[ch.first_key + k].mode);
                CHECK(a.keys[same->first_key + k].value == b.keys[ch.first_key + k].value);
            }
        }
    }
}
