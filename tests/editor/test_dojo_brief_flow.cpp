// Issue 31's brief as the action count in docs/animation.md ("The brief's action count") does it, each
// counted step as the edit the panel makes for it: a new clip, key 1's easing, Duplicate key for the end key,
// key 1 posed at its exact time (the timeline scrub lands on its diamond), key 1 duplicated twice with the
// forearm turned at each copy, Loop: next (idle), two blend cells, an event with a sound. The result is the
// brief's clip: 2 s, four keys with the chosen easing, the arm raised through the wave and home at the end,
// blended from and back to idle, valid and compiled.
#include "dojo_test_util.h"
#include "model/dojo_clips.h"
#include "model/dojo_frames.h"
#include "model/dojo_keys.h"
#include "model/dojo_pose_keys.h"

#include <span>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::shipped_clips;

namespace {
const anim::TargetDef* brief_target(const anim::PhaseDef& phase, const std::string& node) {
    for (const anim::TargetDef& t : phase.targets)
        if (t.node == node) return &t;
    return nullptr;
}
} // namespace

TEST_CASE("the brief's counted steps make a 2 s wave with eases, blended from and back to idle") {
    anim::AnimationFile file = shipped_clips();
    // New clip..., "wave", Enter: one empty 0.5 s key.
    auto made = new_clip(file, "wave");
    REQUIRE(made);
    const std::size_t wave = *made;
    // Key 1's easing combo (the key table writes the phase's ease).
    const auto ease = anim::parse_ease_name("Quadratic.InOut");
    REQUIRE(ease);
    file.clips[wave].phases[0].ease = *ease;
    // Duplicate key: the empty end key (the rest rule takes the arms home at its end).
    REQUIRE(duplicate_phase(file, wave, 0));
    // The timeline scrubbed onto key 1's diamond: exactly 0.5 s, so auto-key writes key 1.
    const TimeUnits seconds = clip_time_units(file.clips[wave]);
    const double key1 = scrub_time(file.clips[wave], seconds, 0.497, 0.01);
    CHECK(key1 == 0.5);
    const NodeRotation raised[] = {{"arm_r", DVec3(0, 0, 150)}, {"forearm_r", DVec3(0, 0, 40)}};
    REQUIRE(key_rotations_at(file, wave, key1, raised));
    CHECK(file.clips[wave].phases.size() == 2); // keyed, not split
    // Key 1 duplicated (a pause holding the pose), the forearm turned at the copy; then again the other way.
    for (const double turn : {70.0, 10.0}) {
        const std::size_t shown = file.clips[wave].phases.size() == 2 ? 0 : 1;
        auto copy = duplicate_phase(file, wave, shown);
        REQUIRE(copy);
        double at = 0;
        for (std::size_t p = 0; p <= *copy; ++p) at += file.clips[wave].phases[p].duration;
        const double scrubbed = scrub_time(file.clips[wave], seconds, at + 0.004, 0.01);
        CHECK(scrubbed == at);
        const NodeRotation wave_forearm{"forearm_r", DVec3(0, 0, turn)};
        REQUIRE(key_rotations_at(file, wave, scrubbed, std::span(&wave_forearm, 1)));
    }
    // Loop: next, the first other clip (idle); the two blend cells; an event with a sound at the last wave.
    REQUIRE(set_loop_mode(file, wave, anim::LoopMode::Next, file.clips[0].name));
    REQUIRE(set_blend(file, "idle", "wave", 0.3));
    REQUIRE(set_blend(file, "wave", "idle", 0.3));
    REQUIRE(add_event(file, wave, 1.5, "sound_cue", "robot_motor"));

    const anim::ClipDef& clip = file.clips[wave];
    CHECK(clip.duration() == 2.0);
    REQUIRE(clip.phases.size() == 4);
    for (const anim::PhaseDef& phase : clip.phases) CHECK(phase.ease == *ease);
    CHECK(clip.next == "idle");
    CHECK(clip.phases[3].targets.empty()); // home at 2 s
    const double forearm[3] = {40, 70, 10};
    for (std::size_t p = 0; p < 3; ++p) {
        const anim::TargetDef* arm = brief_target(clip.phases[p], "arm_r");
        const anim::TargetDef* fore = brief_target(clip.phases[p], "forearm_r");
        REQUIRE(arm);
        REQUIRE(fore);
        CHECK(arm->rot->z == 150.0); // raised through the wave
        CHECK(fore->rot->z == forearm[p]);
    }
    CHECK(dojo_file_issues(file).empty());
    auto rig = anim::build_rig(file);
    REQUIRE(rig);
    CHECK(anim::compile(file, *rig).ok());
}
