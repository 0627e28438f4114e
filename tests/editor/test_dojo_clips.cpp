// The dojo's clip management (new, from a pose, duplicate, rename, delete, loop mode): each edit one undo
// step, each refusal a clear message with the file unchanged, the required clips protected with the reason.
#include "anim/player.h"
#include "anim/required_clips.h"
#include "dojo_test_util.h"
#include "model/dojo_clips.h"

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::index_of;
using ks::dojo_test::shipped_clips;
using ks::dojo_test::text;

namespace {

// The pose `clip` reaches `seconds` after starting from rest, on the file's own rig.
anim::Pose pose_at(const anim::AnimationFile& file, const std::string& clip, double seconds) {
    auto rig = anim::build_rig(file);
    REQUIRE(rig.ok());
    auto clips = anim::compile(file, *rig);
    REQUIRE(clips.ok());
    anim::Player player(*clips, *rig);
    player.play(clips->find(clip), 0.0f);
    player.advance(seconds);
    return player.pose();
}

float largest_angle(const anim::Pose& a, const anim::Pose& b) {
    float worst = 0;
    for (std::size_t i = 0; i < a.euler.size(); ++i)
        worst = std::max(
            {worst, glm::length(a.euler[i] - b.euler[i]), glm::length(a.position[i] - b.position[i])});
    return worst;
}

// Runs an edit that must fail: the error's text contains `expected`, and the file and history are unchanged.
template <class Edit>
void refused_clip(anim::AnimationFile& file, DojoHistory& history, Edit&& edit, const std::string& expected) {
    const std::string before = text(file);
    const std::size_t steps = history.undo_count();
    auto result = apply_dojo_edit(file, history, "refused", [&] { return edit(); });
    REQUIRE_FALSE(result.ok());
    INFO(result.error().str());
    CHECK(result.error().str().find(expected) != std::string::npos);
    CHECK(text(file) == before);
    CHECK(history.undo_count() == steps);
}

} // namespace

TEST_CASE("dojo clips: a new empty clip is one 0.5 s key with no targets, one undo step; bad names refused") {
    anim::AnimationFile file = shipped_clips();
    const std::string original = text(file);
    DojoHistory history;
    auto added = apply_dojo_edit(file, history, "new clip wave", [&] { return new_clip(file, "wave"); });
    REQUIRE(added.ok());
    CHECK(*added == file.clips.size() - 1);
    const anim::ClipDef& wave = file.clips.back();
    CHECK(wave.name == "wave");
    CHECK(wave.loop == anim::LoopMode::Once);
    REQUIRE(wave.phases.size() == 1);
    CHECK(wave.phases[0].duration == kNewClipSeconds);
    CHECK(wave.phases[0].targets.empty());
    CHECK(dojo_file_issues(file).empty());
    CHECK(history.undo_count() == 1);
    CHECK(history.undo_name() == "new clip wave");

    refused_clip(
        file, history, [&] { return new_clip(file, "wave"); }, "a clip named 'wave' already exists");
    refused_clip(
        file, history, [&] { return new_clip(file, "wave"); }, "e.g. 'wave_copy'");
    refused_clip(
        file, history, [&] { return new_clip(file, ""); }, "a clip needs a name");
    refused_clip(
        file, history, [&] { return new_clip(file, "big wave"); }, "other than letters, digits, _ and -");
    refused_clip(
        file, history, [&] { return new_clip(file, "*"); }, "other than letters");

    REQUIRE(history.undo(file));
    CHECK(text(file) == original);
    REQUIRE(history.redo(file));
    CHECK(file.clips.back().name == "wave");
}

TEST_CASE("dojo clips: a new clip from a pose reaches that pose; pose values are degrees and rest offsets") {
    anim::AnimationFile file = shipped_clips();
    const std::size_t death = index_of(file, "death");
    const double end = file.clips[death].duration();
    // The end of death (its root spin is relative: the pose captures where it got to).
    auto pose = clip_pose_values(file, death, end);
    REQUIRE(pose.ok());
    CHECK(pose->size() == file.rig.size());
    auto added = new_clip(file, "dead", *pose);
    REQUIRE(added.ok());
    CHECK(file.clips[*added].phases[0].targets.size() == file.rig.size());
    CHECK(anim::validate(file).empty());
    const float difference =
        largest_angle(pose_at(file, "dead", kNewClipSeconds), pose_at(file, "death", end));
    CHECK(difference < 1e-4f);
    CHECK(largest_angle(pose_at(file, "dead", 0.0), pose_at(file, "death", end)) > 0.5f); // it moves there

    // From a Player's pose on a rig: Euler radians to degrees, positions to offsets from rest.
    auto rig = anim::Rig::create({{"robot", -1, Vec3(0), Vec3(0)}, {"arm", 0, Vec3(0, 2, 0), Vec3(0)}});
    REQUIRE(rig.ok());
    anim::Pose p;
    p.set_rest(*rig);
    p.euler[1] = Vec3(0, 0, static_cast<float>(std::numbers::pi / 2));
    p.position[1] = Vec3(0.5f, 2.0f, 0);
    const auto values = pose_values(*rig, p);
    REQUIRE(values.size() == 2);
    CHECK(values[1].node == "arm");
    CHECK(values[1].rot.z == doctest::Approx(90).epsilon(1e-6));
    CHECK(values[1].pos == DVec3(0.5, 0, 0));

    // A pose the file cannot hold is refused whole.
    DojoHistory history;
    std::vector<NodePoseValue> bad = {{"tail", DVec3(0), DVec3(0)}};
    refused_clip(
        file, history, [&] { return new_clip(file, "wag", bad); }, "unknown node 'tail'");
    bad = {{"chest", DVec3(0), DVec3(0)}, {"chest", DVec3(1), DVec3(0)}};
    refused_clip(
        file, history, [&] { return new_clip(file, "wag", bad); }, "lists node 'chest' twice");
    bad = {{"chest", DVec3(0, 1e9, 0), DVec3(0)}};
    refused_clip(
        file, history, [&] { return new_clip(file, "wag", bad); }, "out of range");
    CHECK_FALSE(clip_pose_values(file, death, -1.0).ok());
    CHECK_FALSE(clip_pose_values(file, 99, 0.0).ok());
}

TEST_CASE("dojo clips: duplicate names copies, rename follows blends and next, delete removes its blends") {
    anim::AnimationFile file = shipped_clips();
    DojoHistory history;
    const std::size_t idle = index_of(file, "idle");
    auto copy = duplicate_clip(file, idle);
    REQUIRE(copy.ok());
    CHECK(*copy == idle + 1);
    CHECK(file.clips[*copy].name == "idle_copy");
    CHECK(file.clips[*copy].phases.size() == file.clips[idle].phases.size());
    auto second = duplicate_clip(file, idle);
    REQUIRE(second.ok());
    CHECK(file.clips[*second].name == "idle_copy_2");
    CHECK(copy_clip_name(file, "idle") == "idle_copy_3");

    // idle_copy_2 plays idle_copy next, and a blend pair names idle_copy at both ends.
    REQUIRE(set_loop_mode(file, index_of(file, "idle_copy_2"), anim::LoopMode::Next, "idle_copy"));
    REQUIRE(set_blend(file, "idle_copy", "idle_copy", 0.3));
    REQUIRE(set_blend(file, "alert", "idle_copy", 0.2));
    auto renamed = apply_dojo_edit(file, history, "rename",
                                   [&] { return rename_clip(file, index_of(file, "idle_copy"), "stroll"); });
    REQUIRE(renamed.ok());
    CHECK(file.clips[index_of(file, "idle_copy_2")].next == "stroll");
    CHECK(blend_grid(file).at(index_of(file, "stroll"), index_of(file, "stroll")).seconds == 0.3);
    CHECK(blend_grid(file).at(index_of(file, "alert"), index_of(file, "stroll")).source ==
          BlendCell::Source::Explicit);
    CHECK(dojo_file_issues(file).empty());

    // Deleting a clip another plays next is refused, naming who; once that is undone, it goes with its pairs.
    const std::size_t stroll = index_of(file, "stroll");
    refused_clip(
        file, history, [&] { return delete_clip(file, stroll); }, "'idle_copy_2' plays it next");
    refused_clip(
        file, history, [&] { return rename_clip(file, stroll, "idle"); }, "already exists");
    REQUIRE(set_loop_mode(file, index_of(file, "idle_copy_2"), anim::LoopMode::Once));
    CHECK(file.clips[index_of(file, "idle_copy_2")].next.empty());
    const std::size_t pairs = file.blends.size();
    REQUIRE(apply_dojo_edit(file, history, "delete", [&] { return delete_clip(file, stroll); }));
    CHECK(file.find_clip("stroll") == nullptr);
    CHECK(file.blends.size() == pairs - 2);
    CHECK(dojo_file_issues(file).empty());
    REQUIRE(history.undo(file));
    CHECK(file.find_clip("stroll") != nullptr);
    CHECK(file.blends.size() == pairs);
    CHECK_FALSE(duplicate_clip(file, 99).ok());
}

TEST_CASE("dojo clips: required clips cannot be deleted or renamed, and the refusal says why") {
    anim::AnimationFile file = shipped_clips();
    DojoHistory history;
    for (const anim::RequiredClip& required : anim::required_robot_clips()) {
        const std::size_t c = index_of(file, required.name);
        INFO(required.name);
        CHECK(clip_protection(file, c) == required.reason);
        refused_clip(
            file, history, [&] { return delete_clip(file, c); },
            std::string("cannot delete '") + required.name + "': " + required.reason);
        refused_clip(
            file, history, [&] { return rename_clip(file, c, "renamed"); },
            std::string("cannot rename '") + required.name + "': " + required.reason);
    }
    refused_clip(
        file, history, [&] { return delete_clip(file, index_of(file, "death")); },
        "the game plays 'death' when a robot dies");
    REQUIRE(new_clip(file, "wave"));
    CHECK(clip_protection(file, index_of(file, "wave")).empty());
    // The last clip of a file that is not the robot's cannot go either.
    anim::AnimationFile single = dojo_test::nod_file();
    refused_clip(
        single, history, [&] { return delete_clip(single, 0); }, "the file's only clip");
    // Renaming to its own name is no change and no error.
    CHECK(rename_clip(single, 0, "nod").ok());
}

TEST_CASE("dojo clips: loop modes once, loop, ping_pong and next; zero length and unknown next refused") {
    anim::AnimationFile file = shipped_clips();
    DojoHistory history;
    const std::size_t pose = index_of(file, "shoot_pose"), reset = index_of(file, "reset");
    REQUIRE(file.clips[reset].duration() == 0);
    for (anim::LoopMode mode : {anim::LoopMode::PingPong, anim::LoopMode::Loop, anim::LoopMode::Once}) {
        REQUIRE(set_loop_mode(file, pose, mode));
        CHECK(file.clips[pose].loop == mode);
    }
    REQUIRE(set_loop_mode(file, pose, anim::LoopMode::Next, "shooting"));
    CHECK(file.clips[pose].next == "shooting");
    CHECK(dojo_file_issues(file).empty());

    refused_clip(
        file, history, [&] { return set_loop_mode(file, reset, anim::LoopMode::PingPong); },
        "clip 'reset' has zero length, so it cannot ping-pong");
    refused_clip(
        file, history, [&] { return set_loop_mode(file, reset, anim::LoopMode::Loop); }, "cannot loop");
    refused_clip(
        file, history, [&] { return set_loop_mode(file, pose, anim::LoopMode::Next); },
        "needs the clip to play next");
    refused_clip(
        file, history, [&] { return set_loop_mode(file, pose, anim::LoopMode::Next, "shootin"); },
        "did you mean 'shooting'?");
    refused_clip(
        file, history, [&] { return set_loop_mode(file, pose, anim::LoopMode::Once, "death"); },
        "only loop mode 'next'");
    refused_clip(
        file, history, [&] { return set_loop_mode(file, reset, anim::LoopMode::Next, "reset"); },
        "returns to itself");

    for (anim::LoopMode mode :
         {anim::LoopMode::Once, anim::LoopMode::Loop, anim::LoopMode::PingPong, anim::LoopMode::Next}) {
        auto back = loop_mode_from_name(loop_mode_name(mode));
        REQUIRE(back.ok());
        CHECK(*back == mode);
    }
    auto typo = loop_mode_from_name("pingpong");
    REQUIRE_FALSE(typo.ok());
    CHECK(typo.error().str().find("did you mean 'ping_pong'?") != std::string::npos);
}
