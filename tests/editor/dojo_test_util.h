#pragma once
// Shared by the dojo model tests: the shipped robot clips (read-only) and small clip files built in code.
#include "anim/clip_io.h"
#include "model/dojo_clips.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <string>

namespace ks::dojo_test {

inline anim::AnimationFile shipped_clips() {
    auto loaded = anim::load_animation_file(ks::test::source_dir() / "assets" / "animations" / "robot.json");
    REQUIRE_MESSAGE(loaded.ok(), (loaded.ok() ? std::string() : loaded.error().str()));
    return *loaded;
}

inline std::size_t index_of(const anim::AnimationFile& file, const std::string& name) {
    auto found = editor::find_clip_index(file, name);
    REQUIRE_MESSAGE(found.ok(), name);
    return *found;
}

inline std::string text(const anim::AnimationFile& file) {
    return anim::save_animation_string(file);
}

// robot > chest (at 0, 1, 0) > head (at 0, 0.5, 0); chest and head go home under the rest rule. One clip,
// "nod" (once, 1 s): key 1 at 0.4 s, Linear, chest rot (0, 0, 30); key 2 at 1 s, Quadratic.In, chest rot
// (0, 0, 10) and head add_rot (0, 90, 0); an event "tap" at 0.9 s.
inline anim::AnimationFile nod_file() {
    anim::AnimationFile f;
    f.rig = {{"robot", "", DVec3(0), DVec3(0)},
             {"chest", "robot", DVec3(0, 1, 0), DVec3(0)},
             {"head", "chest", DVec3(0, 0.5, 0), DVec3(0)}};
    f.rest_nodes = {"chest", "head"};
    anim::ClipDef nod;
    nod.name = "nod";
    anim::PhaseDef lean{0.4, anim::Ease::linear(), {}};
    anim::TargetDef chest;
    chest.node = "chest";
    chest.rot = DVec3(0, 0, 30);
    lean.targets.push_back(chest);
    anim::PhaseDef look{0.6, anim::Ease::named(anim::EaseFamily::Quadratic, anim::EaseMode::In), {}};
    chest.rot = DVec3(0, 0, 10);
    look.targets.push_back(chest);
    anim::TargetDef head;
    head.node = "head";
    head.add_rot = DVec3(0, 90, 0);
    look.targets.push_back(head);
    nod.phases = {lean, look};
    nod.events = {{0.9, "tap", ""}};
    f.clips = {nod};
    REQUIRE(anim::validate(f).empty());
    return f;
}

} // namespace ks::dojo_test
